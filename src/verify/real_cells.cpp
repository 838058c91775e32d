#include "verify/real_cells.hpp"

#include <algorithm>
#include <set>

namespace uabt::verify::detail {

namespace {

using Point = std::pair<Fraction, Fraction>;
using Polygon = std::vector<Point>;

Fraction side(const Line& l, const Point& p) {
  return l.at(p.first, p.second);
}

// Splits a convex polygon by a line into its parts on the negative and the positive side.
void split(const Polygon& poly, const Line& line, std::vector<Polygon>& out) {
  std::vector<int> s;
  bool negative = false, positive = false;
  for (const auto& p : poly) {
    s.push_back(side(line, p).sign());
    negative = negative || s.back() < 0;
    positive = positive || s.back() > 0;
  }
  if (!negative || !positive) {
    out.push_back(poly);
    return;
  }
  Polygon below, above;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const std::size_t j = (i + 1) % poly.size();
    if (s[i] <= 0) below.push_back(poly[i]);
    if (s[i] >= 0) above.push_back(poly[i]);
    if (s[i] * s[j] < 0) {
      const Fraction si = side(line, poly[i]), sj = side(line, poly[j]);
      const Fraction t = si / (si - sj);
      const Point cut{poly[i].first + t * (poly[j].first - poly[i].first),
                      poly[i].second + t * (poly[j].second - poly[i].second)};
      below.push_back(cut);
      above.push_back(cut);
    }
  }
  out.push_back(below);
  out.push_back(above);
}

Fraction area(const Polygon& poly) {
  Fraction twice;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % poly.size()];
    twice += p.first * q.second - q.first * p.second;
  }
  return (twice.sign() < 0 ? -twice : twice) / Fraction(2);
}

std::vector<std::pair<double, double>> shape_of(const Polygon& poly) {
  std::vector<std::pair<double, double>> out;
  for (const auto& [x, y] : poly) out.emplace_back(x.to_double(), y.to_double());
  return out;
}

// Where a line meets the horizontal y = y0 (x), or the vertical x = x0 (y).
Fraction x_on(const Line& l, const Fraction& y) {
  return -(l.b * y + l.c) / l.a;
}
Fraction y_on(const Line& l, const Fraction& x) {
  return -(l.a * x + l.c) / l.b;
}

}  // namespace

void RealComponent::build() {
  cells.clear();
  if (axes.size() == 1) {
    const RealAxis& ax = axes[0];
    const bool degenerate = ax.breaks.size() == 1;  // a range of one point is a constant
    for (std::size_t c = 0; c < ax.cells(); ++c) {
      RealCell cell;
      cell.weight = degenerate ? Fraction(1) : ax.length(c);
      cell.point = {ax.middle(c)};
      cell.axis_cell = {c};
      cell.shape = {{ax.from(c).to_double(), 0.0}, {ax.to(c).to_double(), 0.0}};
      cells.push_back(std::move(cell));
    }
    return;
  }
  const RealAxis& ax = axes[0];
  const RealAxis& ay = axes[1];
  auto add = [&](std::size_t cx, std::size_t cy, Fraction weight, const Point& p,
                 const Polygon& shape) {
    RealCell cell;
    cell.weight = weight;
    cell.point = {p.first, p.second};
    cell.axis_cell = {cx, cy};
    for (const Line& l : lines) cell.signs.push_back(side(l, p).sign());
    cell.shape = shape_of(shape);
    cells.push_back(std::move(cell));
  };
  // Points along a segment where lines cross it, strictly inside, sorted by the parameter.
  auto cuts_along = [&](const Point& p, const Point& q, const Line* on) {
    std::set<Fraction> ts;
    for (const Line& l : lines) {
      if (on != nullptr && l == *on) continue;
      const Fraction sp = side(l, p), sq = side(l, q);
      if (sp.sign() * sq.sign() < 0) ts.insert(sp / (sp - sq));
    }
    return ts;
  };
  auto lerp = [](const Point& p, const Point& q, const Fraction& t) {
    return Point{p.first + t * (q.first - p.first), p.second + t * (q.second - p.second)};
  };
  // An open segment from p to q split at the lines that cross it: open pieces and the points.
  std::set<Point> points_done;
  auto segment = [&](std::size_t cx, std::size_t cy, const Point& p, const Point& q,
                     const Line* on) {
    std::vector<Fraction> ts{Fraction(0)};
    for (const auto& t : cuts_along(p, q, on)) ts.push_back(t);
    ts.push_back(Fraction(1));
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const Point a = lerp(p, q, ts[k]), b = lerp(p, q, ts[k + 1]);
      add(cx, cy, Fraction(0), lerp(a, b, Fraction::of(1, 2)), {a, b});
      if (k + 2 < ts.size() && points_done.insert(b).second) add(cx, cy, Fraction(0), b, {b});
    }
  };
  for (std::size_t cy = 0; cy < ay.cells(); ++cy) {
    for (std::size_t cx = 0; cx < ax.cells(); ++cx) {
      const bool px = RealAxis::is_point(cx), py = RealAxis::is_point(cy);
      const Fraction x0 = ax.from(cx), x1 = ax.to(cx), y0 = ay.from(cy), y1 = ay.to(cy);
      if (px && py) {
        add(cx, cy, Fraction(0), {x0, y0}, {{x0, y0}});
      } else if (py) {  // horizontal open segment
        segment(cx, cy, {x0, y0}, {x1, y0}, nullptr);
      } else if (px) {  // vertical open segment
        segment(cx, cy, {x0, y0}, {x0, y1}, nullptr);
      } else {
        std::vector<Polygon> parts{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
        for (const Line& l : lines) {
          std::vector<Polygon> next;
          for (const auto& poly : parts) split(poly, l, next);
          parts = std::move(next);
        }
        for (const auto& poly : parts) {
          Fraction sx, sy;
          for (const auto& [x, y] : poly) {
            sx += x;
            sy += y;
          }
          const Fraction n(static_cast<long long>(poly.size()));
          add(cx, cy, area(poly), {sx / n, sy / n}, poly);
        }
        // The lines inside the open box: where each meets the box's edges, then split.
        for (const Line& l : lines) {
          std::set<Point> ends;
          for (const Fraction& y : {y0, y1}) {
            const Fraction x = x_on(l, y);
            if (x >= x0 && x <= x1) ends.insert({x, y});
          }
          for (const Fraction& x : {x0, x1}) {
            const Fraction y = y_on(l, x);
            if (y >= y0 && y <= y1) ends.insert({x, y});
          }
          if (ends.size() < 2) continue;  // misses the box, or touches a corner
          segment(cx, cy, *ends.begin(), *ends.rbegin(), &l);
        }
      }
    }
  }
}

}  // namespace uabt::verify::detail
