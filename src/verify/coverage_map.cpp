#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "verify/coverage_parts.hpp"

namespace uabt::verify::detail {

namespace {

// The map visits every state once per guard; beyond this it is left out.
constexpr std::uint64_t kMaxMapWork = std::uint64_t{1} << 22;
constexpr std::uint64_t kMaxPanels = 12;

using Place = MapPlace;

struct Aggregate {
  std::set<int> outcomes;
  bool overlap = false, uncertain = false;
  Fraction gap;
};

// One key of the map: panel digit, x key, y key.
using Key = std::tuple<std::uint64_t, std::uint64_t, std::uint64_t>;

// The position of a state along one axis: its value's digit, or its cell along a real axis.
std::uint64_t key_digit(const Space& space, std::uint64_t s, const Place& p) {
  const std::uint64_t digit = space.digit(s, p.dim);
  if (p.axis < 0) return digit;
  const auto& comp = space.components()[space.dimensions()[p.dim].component];
  return comp.cells[digit].axis_cell[static_cast<std::size_t>(p.axis)];
}

// Geometry of one axis position: [from, to] in the variable's own units.
struct Extent {
  double from, to;
  RegionConstraint where;
};
Extent extent(const Space& space, const fretish::Domain& domain, const Place& p, std::uint64_t k) {
  const Dimension& d = space.dimensions()[p.dim];
  if (p.axis >= 0) {
    const auto& axis = space.components()[d.component].axes[static_cast<std::size_t>(p.axis)];
    Extent e{axis.from(k).to_double(), axis.to(k).to_double(), {}};
    const Fraction& a = axis.from(k);
    const Fraction& b = axis.to(k);
    e.where.text = RealAxis::is_point(k)
                       ? axis.variable + " = " + a.decimal()
                       : axis.variable + " in (" + a.decimal() + ", " + b.decimal() + ")";
    return e;
  }
  if (d.sort == smt::Sort::integer) {
    const double v = static_cast<double>(d.number(k));
    return {v - 0.5, v + 0.5, describe_range(space, p.dim, k, k, domain)};
  }
  return {static_cast<double>(k), static_cast<double>(k + 1),
          describe_range(space, p.dim, k, k, domain)};
}

// Where one cell of a two-variable component lies: "r in (0, 30) & s = 20 & on a boundary line".
std::string joint_where(const RealComponent& comp, const RealCell& cell) {
  std::string where;
  for (std::size_t a = 0; a < 2; ++a) {
    const auto& axis = comp.axes[a];
    const std::uint64_t c = cell.axis_cell[a];
    where += (a ? " & " : "") + (RealAxis::is_point(c)
                                     ? axis.variable + " = " + axis.from(c).decimal()
                                     : axis.variable + " in (" + axis.from(c).decimal() + ", " +
                                           axis.to(c).decimal() + ")");
  }
  for (std::size_t l = 0; l < comp.lines.size(); ++l)
    if (cell.signs[l] == 0) where += " & on a boundary line";
  return where;
}

// A box [x0, x1] x [y0, y1] as a shape: a point, a segment or a rectangle.
std::vector<std::pair<double, double>> box_points(double x0, double x1, double y0, double y1) {
  if (x0 == x1 && y0 == y1) return {{x0, y0}};
  if (x0 == x1) return {{x0, y0}, {x0, y1}};
  if (y0 == y1) return {{x0, y0}, {x1, y0}};
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace

std::optional<MapLayout> map_layout(const Space& space, std::size_t alternatives,
                                    std::string& why) {
  const auto& dims = space.dimensions();
  if (space.size() == 0) {
    why = "the node's space has no state";
    return std::nullopt;
  }
  if (space.size() * std::max<std::size_t>(alternatives, 1) > kMaxMapWork) {
    why = "too many cells to draw (" + std::to_string(space.size()) + " cells, " +
          std::to_string(alternatives) + " alternatives; the map draws at most " +
          std::to_string(kMaxMapWork) + " cells times alternatives)";
    return std::nullopt;
  }
  // Axes: real variables first (a related pair together), then integers, then the rest.
  std::vector<Place> numeric, other;
  for (std::size_t d = 0; d < dims.size(); ++d) {
    if (dims[d].component >= 0) {
      const auto& comp = space.components()[static_cast<std::size_t>(dims[d].component)];
      if (comp.axes[0].breaks.size() < 2) continue;  // a constant
      for (std::size_t a = 0; a < comp.axes.size(); ++a)
        numeric.push_back({d, static_cast<int>(a)});
    }
  }
  std::stable_sort(numeric.begin(), numeric.end(), [&](const Place& a, const Place& b) {
    const auto sa = space.components()[dims[a.dim].component].axes.size();
    const auto sb = space.components()[dims[b.dim].component].axes.size();
    return sa > sb;
  });
  for (std::size_t d = 0; d < dims.size(); ++d)
    if (dims[d].component < 0 && dims[d].sort == smt::Sort::integer) numeric.push_back({d, -1});
  for (std::size_t d = 0; d < dims.size(); ++d)
    if (dims[d].component < 0 && dims[d].sort != smt::Sort::integer) other.push_back({d, -1});
  std::vector<Place> axes = numeric;
  for (const auto& p : other) axes.push_back(p);
  if (axes.empty()) {
    why = "its guards read no variable that varies";
    return std::nullopt;
  }
  MapLayout layout;
  layout.x = axes[0];
  if (axes.size() > 1) layout.y = axes[1];
  for (std::size_t k = layout.y ? 2 : 1; k < axes.size(); ++k)
    if (axes[k].axis < 0 && dims[axes[k].dim].sort != smt::Sort::integer &&
        dims[axes[k].dim].radix <= kMaxPanels) {
      layout.panel = axes[k].dim;
      break;
    }
  layout.joint = layout.y && layout.y->dim == layout.x.dim;
  return layout;
}

MapMark map_mark(const Space& space, const fretish::Domain& domain, const MapLayout& layout,
                 std::uint64_t state) {
  MapMark mark;
  const auto& dims = space.dimensions();
  if (layout.panel) mark.panel = space.digit(state, *layout.panel);
  if (layout.joint) {
    const auto& comp = space.components()[dims[layout.x.dim].component];
    const auto& cell = comp.cells[space.digit(state, layout.x.dim)];
    mark.points = cell.shape;
    mark.where = joint_where(comp, cell);
  } else {
    const Extent ex = extent(space, domain, layout.x, key_digit(space, state, layout.x));
    double y0 = 0, y1 = 1;
    mark.where = ex.where.text;
    if (layout.y) {
      const Extent ey = extent(space, domain, *layout.y, key_digit(space, state, *layout.y));
      y0 = ey.from;
      y1 = ey.to;
      if (!ey.where.text.empty()) mark.where += (mark.where.empty() ? "" : " & ") + ey.where.text;
    }
    mark.points = box_points(ex.from, ex.to, y0, y1);
  }
  if (layout.panel) {
    const std::string label =
        describe_range(space, *layout.panel, mark.panel, mark.panel, domain).text;
    if (!label.empty()) mark.where += (mark.where.empty() ? "" : " & ") + label;
  }
  return mark;
}

void fill_map(const Space& space, const fretish::Domain& domain, const NodeTruths& truths,
              std::size_t alternatives, Coverage& coverage) {
  const auto& dims = space.dimensions();
  std::string why;
  const std::optional<MapLayout> layout = map_layout(space, alternatives, why);
  if (!layout) return;
  const Place px = layout->x;
  const std::optional<Place> py = layout->y;
  const std::optional<std::size_t> panel = layout->panel;
  const bool joint = layout->joint;

  std::map<Key, Aggregate> cells;
  for (std::uint64_t s = 0; s < space.size(); ++s) {
    if (!truths.domain.maybe.test(s)) continue;
    Key key{panel ? space.digit(s, *panel) : 0,
            joint ? space.digit(s, px.dim) : key_digit(space, s, px), 0};
    if (py && !joint) std::get<2>(key) = key_digit(space, s, *py);
    Aggregate& a = cells[key];
    int outcome = -1;
    for (std::size_t k = 0; k < truths.enabled.size(); ++k) {
      const Truth& e = truths.enabled[k];
      if (e.sure.test(s) != e.maybe.test(s)) a.uncertain = true;
      if (outcome < 0 && e.maybe.test(s)) outcome = static_cast<int>(k);
    }
    if (truths.domain.sure.test(s) != truths.domain.maybe.test(s)) a.uncertain = true;
    a.outcomes.insert(outcome);
    if (truths.overlap.maybe.test(s)) a.overlap = true;
    if (outcome < 0) a.gap += space.weight(s);
  }
  const Fraction total = space.measure(truths.domain.sure);

  auto make_axis = [&](const Place& p) {
    MapAxis a;
    const Dimension& d = dims[p.dim];
    if (p.axis >= 0) {
      const auto& axis = space.components()[d.component].axes[static_cast<std::size_t>(p.axis)];
      a.variable = axis.variable;
      a.lower = axis.breaks.front().to_double();
      a.upper = axis.breaks.back().to_double();
      for (const auto& b : axis.breaks) a.ticks.emplace_back(b.to_double(), b.decimal());
      return a;
    }
    a.variable = d.name;
    if (d.sort == smt::Sort::integer) {
      a.lower = static_cast<double>(d.number(0)) - 0.5;
      a.upper = static_cast<double>(d.number(d.radix - 1)) + 0.5;
      return a;  // ticks: where the outcome changes (below)
    }
    a.categorical = true;
    a.lower = 0;
    a.upper = static_cast<double>(d.radix);
    for (std::uint64_t k = 0; k < d.radix; ++k)
      a.ticks.emplace_back(static_cast<double>(k) + 0.5, d.sort == smt::Sort::enumeration
                                                             ? d.declaration->enum_values[k]
                                                             : (k ? "true" : "false"));
    return a;
  };

  CoverageMap map;
  map.x = make_axis(px);
  if (py) map.y = make_axis(*py);
  if (joint) {
    map.x.variable = space.components()[dims[px.dim].component].axes[0].variable;
    map.y->variable = space.components()[dims[px.dim].component].axes[1].variable;
  }
  map.other_variables = dims.size() > (joint ? 1u : py ? 2u : 1u) + (panel ? 1u : 0u);
  if (panel) map.panel_variable = dims[*panel].name;
  const std::uint64_t panels = panel ? dims[*panel].radix : 1;
  map.panels.resize(panels);
  for (std::uint64_t k = 0; k < panels; ++k)
    if (panel) map.panels[k].label = describe_range(space, *panel, k, k, domain).text;

  // Runs of equal integer positions along y (else x) merge into one shape.
  const bool merge_y = py && !joint;
  std::set<std::uint64_t> x_starts, y_starts;
  auto same = [](const Aggregate& a, const Aggregate& b) {
    return a.outcomes == b.outcomes && a.overlap == b.overlap && a.uncertain == b.uncertain;
  };
  // Runs: rectangles of equal outcome, first along y (keys are ordered panel, x, y), then
  // neighbouring runs along x with the same y extent merge too.
  struct Run {
    std::uint64_t pk, xk, x_end, yk, y_end;
    Aggregate agg;
  };
  std::vector<Run> runs;
  for (auto it = cells.begin(); it != cells.end();) {
    auto [pk, xk, yk] = it->first;
    Run run{pk, xk, xk, yk, yk, it->second};
    auto next = std::next(it);
    while (merge_y && next != cells.end() && std::get<0>(next->first) == pk &&
           std::get<1>(next->first) == xk && std::get<2>(next->first) == run.y_end + 1 &&
           same(next->second, run.agg)) {
      run.agg.gap += next->second.gap;
      run.y_end = std::get<2>(next->first);
      ++next;
    }
    runs.push_back(std::move(run));
    it = next;
  }
  if (!joint) {
    std::stable_sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
      return std::tie(a.pk, a.yk, a.y_end, a.xk) < std::tie(b.pk, b.yk, b.y_end, b.xk);
    });
    std::vector<Run> merged;
    for (auto& r : runs) {
      if (!merged.empty()) {
        Run& last = merged.back();
        if (last.pk == r.pk && last.yk == r.yk && last.y_end == r.y_end && last.x_end + 1 == r.xk &&
            same(last.agg, r.agg)) {
          last.x_end = r.x_end;
          last.agg.gap += r.agg.gap;
          continue;
        }
      }
      merged.push_back(std::move(r));
    }
    runs = std::move(merged);
    std::stable_sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
      return std::tie(a.pk, a.xk, a.yk) < std::tie(b.pk, b.xk, b.yk);
    });
  }
  for (const Run& run : runs) {
    const std::uint64_t pk = run.pk, xk = run.xk, x_end = run.x_end, yk = run.yk, y_end = run.y_end;
    const Aggregate& agg = run.agg;
    MapShape shape;
    shape.outcomes.assign(agg.outcomes.begin(), agg.outcomes.end());
    shape.overlap = agg.overlap;
    shape.uncertain = agg.uncertain;
    shape.gap_share = exact_of(ratio(agg.gap, total));
    if (joint) {
      const auto& comp = space.components()[dims[px.dim].component];
      shape.points = comp.cells[xk].shape;
      shape.where = joint_where(comp, comp.cells[xk]);
    } else {
      const Extent ex0 = extent(space, domain, px, xk), ex1 = extent(space, domain, px, x_end);
      double y0 = 0, y1 = 1;
      std::string where = ex0.where.text;
      if (x_end != xk) where = describe_range(space, px.dim, xk, x_end, domain).text;
      if (py) {
        const Extent ey0 = extent(space, domain, *py, yk), ey1 = extent(space, domain, *py, y_end);
        y0 = ey0.from;
        y1 = ey1.to;
        const std::string yw =
            y_end != yk ? describe_range(space, py->dim, yk, y_end, domain).text : ey0.where.text;
        if (!yw.empty()) where += (where.empty() ? "" : " & ") + yw;
      }
      y_starts.insert(yk);
      x_starts.insert(xk);
      const double x0 = ex0.from, x1 = ex1.to;
      shape.points = box_points(x0, x1, y0, y1);
      shape.where = where;
    }
    if (panel && !map.panels[pk].label.empty())
      shape.where += (shape.where.empty() ? "" : " & ") + map.panels[pk].label;
    map.panels[pk].shapes.push_back(std::move(shape));
  }
  // Integer axes: a tick at each end and where a run starts.
  auto integer_ticks = [&](const Place& p, MapAxis& a, const std::set<std::uint64_t>& starts) {
    if (p.axis >= 0 || dims[p.dim].sort != smt::Sort::integer) return;
    std::set<std::uint64_t> at = starts;
    at.insert(0);
    at.insert(dims[p.dim].radix - 1);
    for (std::uint64_t k : at) {
      const auto v = dims[p.dim].number(k);
      a.ticks.emplace_back(static_cast<double>(v), std::to_string(v));
    }
  };
  integer_ticks(px, map.x, x_starts);
  if (py && !joint) integer_ticks(*py, *map.y, y_starts);
  coverage.map = std::move(map);
}

}  // namespace uabt::verify::detail
