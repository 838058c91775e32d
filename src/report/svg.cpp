#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <tuple>

#include "base/text.hpp"
#include "fretish/expr.hpp"
#include "report/common.hpp"
#include "report/coverage_view.hpp"
#include "report/reports.hpp"
#include "smt/evaluate.hpp"

namespace uabt::report {

namespace {

using detail::kGapColour;
using detail::kOverlapColour;

constexpr double kWidth = 720;
constexpr double kMargin = 10;
constexpr double kLegendRow = 20;

std::string num(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", value);
  std::string out = buffer;
  // "12.00" → "12", "12.50" → "12.5": fewer bytes, same picture.
  while (out.back() == '0') out.pop_back();
  if (out.back() == '.') out.pop_back();
  if (out == "-0") out = "0";
  return out;
}

// Dark text on light fills, white on dark ones (WCAG relative luminance).
const char* text_colour_on(const std::string& hex) {
  if (hex.size() != 7) return "#000";
  auto channel = [&](int at) {
    const double c = std::stoi(hex.substr(at, 2), nullptr, 16) / 255.0;
    return c <= 0.03928 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const double luminance = 0.2126 * channel(1) + 0.7152 * channel(3) + 0.0722 * channel(5);
  return luminance > 0.2 ? "#000" : "#fff";
}

// Element ids must be unique in a page that inlines several pictures.
std::string id_prefix(const std::string& adaptable, const char* kind) {
  return std::string("uabt-") + kind + "-" + detail::hex64(detail::fnv1a(adaptable)).substr(0, 10);
}

std::string patterns(const std::string& prefix) {
  return "<defs>"
         "<pattern id=\"" +
         prefix +
         "-gap\" patternUnits=\"userSpaceOnUse\" width=\"8\" "
         "height=\"8\" patternTransform=\"rotate(45)\"><rect width=\"8\" height=\"8\" "
         "fill=\"#fde0e0\"/><rect width=\"4\" height=\"8\" fill=\"" +
         std::string(kGapColour) +
         "\"/></pattern>"
         "<pattern id=\"" +
         prefix +
         "-overlap\" patternUnits=\"userSpaceOnUse\" width=\"6\" "
         "height=\"6\" patternTransform=\"rotate(-45)\"><rect width=\"6\" height=\"6\" "
         "fill=\"#ffffff\"/><rect width=\"2\" height=\"6\" fill=\"" +
         std::string(kOverlapColour) +
         "\"/></pattern>"
         "</defs>";
}

std::string svg_open(double width, double height, const std::string& title) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" +
         num(height) + "\" viewBox=\"0 0 " + num(width) + " " + num(height) +
         "\" role=\"img\" font-family=\"system-ui, -apple-system, 'Segoe UI', sans-serif\" "
         "font-size=\"13\"><title>" +
         detail::html_escape(title) + "</title>";
}

std::string text_at(double x, double y, const std::string& content, const char* extra = "") {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\"" + extra + ">" +
         detail::html_escape(content) + "</text>";
}

struct LegendRow {
  std::string fill;  // colour or url(#…)
  std::string text;
};

std::string legend(const std::vector<LegendRow>& rows, double top) {
  std::string out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double y = top + kLegendRow * static_cast<double>(i);
    out += "<rect x=\"" + num(kMargin) + "\" y=\"" + num(y) +
           "\" width=\"14\" height=\"14\" fill=\"" + rows[i].fill +
           "\" stroke=\"#333\" stroke-width=\"0.5\"/>";
    out += text_at(kMargin + 22, y + 11.5, rows[i].text);
  }
  return out;
}

}  // namespace

std::string coverage_svg(const verify::Coverage& coverage) {
  const std::string prefix = id_prefix(coverage.adaptable, "bar");
  const double bar_x = kMargin, bar_y = 28, bar_w = kWidth - 2 * kMargin, bar_h = 36;
  std::string body;
  std::vector<LegendRow> rows;
  double legend_top = bar_y + bar_h + 16;
  // Counted nodes say states; measured ones the share of the space (exact beside it).
  auto amount = [&](std::uint64_t states, const std::optional<detail::ShownShare>& share) {
    if (coverage.counted)
      return count_text(states, "state") + " (" + detail::percent(states, coverage.states) + ")";
    return share ? detail::share_text(*share) + " of the space" : std::string("?");
  };
  const bool boundary_gap =
      coverage.gap_share.text == "0" && !coverage.gap_regions.empty() && coverage.measured;
  const bool boundary_overlap =
      coverage.overlap_share.text == "0" && !coverage.overlap_regions.empty() && coverage.measured;

  if (detail::has_shares(coverage)) {
    struct Segment {
      double share;
      bool force;  // drawn even at share 0 (a boundary the gate reported)
      std::string fill, ink, tooltip, label;
    };
    std::vector<Segment> segments;
    for (std::size_t i = 0; i < coverage.alternatives.size(); ++i) {
      const auto& alternative = coverage.alternatives[i];
      const auto share = detail::alternative_share(coverage, i);
      const std::string colour = detail::alternative_colour(i);
      const std::string said = amount(alternative.states, share);
      segments.push_back({share ? share->value : 0, false, colour, text_colour_on(colour),
                          alternative.name + " (" + alternative.requirement + "): " + said,
                          share ? detail::share_text(*share) : ""});
      std::string text =
          alternative.name + " — " + alternative.requirement + ": selected in " + said;
      if (!alternative.reachable || (share && share->exact == "0")) text += ", never selected";
      if (coverage.counted && alternative.enabled_states > alternative.states)
        text += "; its guard holds in " + std::to_string(alternative.enabled_states) + " (" +
                detail::percent(alternative.enabled_states, coverage.states) + ")";
      else if (!coverage.counted && alternative.enabled_share.value > (share ? share->value : 0))
        text += "; its guard holds in " + detail::share_text({alternative.enabled_share.value,
                                                              alternative.enabled_share.text});
      rows.push_back({colour, text});
    }
    const auto gap = detail::gap_share(coverage);
    const std::string gap_said =
        boundary_gap ? std::string("only on a boundary (measure 0), see the decision table")
                     : amount(coverage.gap_states, gap);
    segments.push_back({gap ? gap->value : 0, boundary_gap, "url(#" + prefix + "-gap)", "",
                        "gap: no guard holds in " + gap_said, ""});
    // Widths: every part that is there gets at least a few pixels, the others give way.
    constexpr double kMinVisible = 4;
    double fixed = 0, rest = 0;
    for (const auto& sg : segments) {
      if (sg.share * bar_w < kMinVisible && (sg.share > 0 || sg.force))
        fixed += kMinVisible;
      else
        rest += sg.share;
    }
    double x = bar_x;
    for (const auto& sg : segments) {
      if (sg.share <= 0 && !sg.force) continue;
      const bool tiny = sg.share * bar_w < kMinVisible;
      const double w = tiny ? kMinVisible : (rest > 0 ? sg.share / rest * (bar_w - fixed) : 0);
      body += "<rect x=\"" + num(x) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(w) +
              "\" height=\"" + num(bar_h) + "\" fill=\"" + sg.fill +
              "\" stroke=\"#fff\" stroke-width=\"1\"><title>" + detail::html_escape(sg.tooltip) +
              "</title></rect>";
      if (w >= 48 && !sg.ink.empty())
        body += text_at(x + w / 2, bar_y + bar_h / 2 + 4.5,
                        coverage.counted
                            ? detail::percent(static_cast<std::uint64_t>(std::llround(
                                                  sg.share * static_cast<double>(coverage.states))),
                                              coverage.states)
                            : sg.label.substr(0, sg.label.find(' ')),
                        (" text-anchor=\"middle\" fill=\"" + sg.ink + "\"").c_str());
      x += w;
    }
    body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(bar_w) +
            "\" height=\"" + num(bar_h) + "\" fill=\"none\" stroke=\"#333\" stroke-width=\"1\"/>";

    // The overlap lies inside the alternatives' segments (the first guard wins there), so it
    // gets its own gauge under the bar rather than a place in it.
    const auto overlap = detail::overlap_share(coverage);
    const double gauge_y = bar_y + bar_h + 8, gauge_h = 10;
    body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(gauge_y) + "\" width=\"" + num(bar_w) +
            "\" height=\"" + num(gauge_h) +
            "\" fill=\"#f2f2f2\" stroke=\"#999\" "
            "stroke-width=\"0.5\"/>";
    const double overlap_value = overlap ? overlap->value : 0;
    if (overlap_value > 0 || boundary_overlap)
      body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(gauge_y) + "\" width=\"" +
              num(std::max(bar_w * overlap_value, kMinVisible)) + "\" height=\"" + num(gauge_h) +
              "\" fill=\"url(#" + prefix + "-overlap)\" stroke=\"" + kOverlapColour +
              "\" stroke-width=\"0.5\"><title>overlap: " +
              detail::html_escape(boundary_overlap ? std::string("on a boundary (measure 0)")
                                                   : amount(coverage.overlap_states, overlap)) +
              " where two or more guards hold</title></rect>";
    legend_top = gauge_y + gauge_h + 14;
    rows.push_back(
        {"url(#" + prefix + "-gap)", "gap — no guard holds, the node fails: " + gap_said});
    rows.push_back({"url(#" + prefix + "-overlap)",
                    "overlap — two or more guards hold (gauge under the bar): " +
                        (boundary_overlap ? std::string("on a boundary (measure 0), see the table")
                                          : amount(coverage.overlap_states, overlap))});
  } else {
    const std::string why = coverage.counted || coverage.measured ? "the domain admits no state"
                            : coverage.bounded
                                ? "shares " + detail::not_measured_text(coverage)
                                : "not counted: " + (coverage.not_counted_reason.empty()
                                                         ? std::string("no reason given")
                                                         : coverage.not_counted_reason);
    body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(bar_w) +
            "\" height=\"" + num(bar_h) +
            "\" fill=\"#eeeeee\" stroke=\"#999\" stroke-width=\"1\" "
            "stroke-dasharray=\"4 3\"/>";
    body += text_at(bar_x + bar_w / 2, bar_y + bar_h / 2 + 4.5, why,
                    " text-anchor=\"middle\" fill=\"#333\"");
    for (std::size_t i = 0; i < coverage.alternatives.size(); ++i) {
      const auto& alternative = coverage.alternatives[i];
      std::string text = alternative.name + " — " + alternative.requirement +
                         (alternative.reachable ? ": selected in some state" : ": never selected");
      if (coverage.bounded)
        text += ", " + detail::bounds_text(alternative.share_lower, alternative.share_upper);
      rows.push_back({detail::alternative_colour(i), text});
    }
    if (coverage.bounded) {
      rows.push_back(
          {"url(#" + prefix + "-gap)",
           "gap — " + detail::bounds_text(coverage.gap_share_lower, coverage.gap_share_upper)});
      rows.push_back({"url(#" + prefix + "-overlap)",
                      "overlap — " + detail::bounds_text(coverage.overlap_share_lower,
                                                         coverage.overlap_share_upper)});
    }
  }

  const double height = legend_top + kLegendRow * static_cast<double>(rows.size()) + 4;
  std::string out = svg_open(kWidth, height, "Terrain coverage of " + coverage.adaptable);
  out += patterns(prefix);
  std::string heading = coverage.adaptable + ": ";
  heading += coverage.counted ? count_text(coverage.states, "state") + " in the domain"
             : coverage.measured
                 ? "the domain measured exactly (measure " + coverage.measure.text + ")"
                 : std::string("state space not measured");
  out += text_at(kMargin, 18, heading, " font-weight=\"600\"");
  out += body;
  out += legend(rows, legend_top);
  out += "</svg>";
  return out;
}

namespace {

// ---- the map: the selected alternative over the exact cells ---------------------------------

constexpr double kMinVisible = 3;  // pixels: a gap or overlap is never thinner than this

struct Frame {
  double left, top, width, height;
  const verify::MapAxis* x;
  const verify::MapAxis* y;  // null: a strip
  double px(double v) const { return left + (v - x->lower) / (x->upper - x->lower) * width; }
  double py(double v) const {
    if (y == nullptr) return top + height - v * height;
    return top + height - (v - y->lower) / (y->upper - y->lower) * height;
  }
};

// Whether a shape is an axis-parallel rectangle (x0,y0) (x1,y0) (x1,y1) (x0,y1), as cells over
// discrete or independent variables are; a cell a sloped line cuts is a polygon, even one with
// four corners and two sides on the box.
bool is_box(const std::vector<std::pair<double, double>>& p) {
  return p.size() == 4 && p[0].second == p[1].second && p[1].first == p[2].first &&
         p[2].second == p[3].second && p[3].first == p[0].first;
}

// An extent [lo, hi] in pixels too thin to see, widened to the minimum around its centre.
void widen(double& lo, double& hi) {
  if (hi - lo >= kMinVisible) return;
  const double c = (lo + hi) / 2;
  lo = c - kMinVisible / 2;
  hi = c + kMinVisible / 2;
}

std::string fill_of(int outcome, const std::string& prefix) {
  return outcome < 0 ? "url(#" + prefix + "-gap)"
                     : detail::alternative_colour(static_cast<std::size_t>(outcome));
}

std::string outcome_names(const verify::MapShape& shape, const verify::Coverage& coverage) {
  std::string names;
  for (int o : shape.outcomes) {
    names += names.empty() ? "" : " or ";
    names += o < 0 ? std::string("gap (no guard holds)")
             : static_cast<std::size_t>(o) < coverage.alternatives.size()
                 ? coverage.alternatives[static_cast<std::size_t>(o)].name
                 : "alternative " + std::to_string(o + 1);
  }
  return names;
}

struct MapLegend {
  bool gap = false, overlap = false, mixed = false, uncertain = false, boundary = false;
};

void draw_panel(const verify::CoverageMap& map, const verify::MapPanel& panel, const Frame& f,
                const verify::Coverage& coverage, const std::string& prefix, MapLegend& seen,
                std::string& body) {
  body += "<rect x=\"" + num(f.left) + "\" y=\"" + num(f.top) + "\" width=\"" + num(f.width) +
          "\" height=\"" + num(f.height) + "\" fill=\"#f4f4f4\"/>";
  std::string areas, lines, labels;
  std::vector<std::tuple<double, double, double>> placed;  // labels: x, baseline, width
  for (const auto& shape : panel.shapes) {
    const bool gap =
        std::find(shape.outcomes.begin(), shape.outcomes.end(), -1) != shape.outcomes.end();
    std::string tooltip = shape.where + ": " + outcome_names(shape, coverage);
    if (shape.outcomes.size() > 1) tooltip += " (depends on the variables off the map)";
    if (shape.overlap) tooltip += "; two or more guards hold";
    if (shape.uncertain) tooltip += "; not measured exactly here";
    if (gap && shape.gap_share.text != "0")
      tooltip += "; gap share " + detail::share_text({shape.gap_share.value, shape.gap_share.text});
    const std::string title = "<title>" + detail::html_escape(tooltip) + "</title>";
    if (shape.points.size() >= 3) {
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (const auto& [x, y] : shape.points) {
        x0 = std::min(x0, f.px(x));
        x1 = std::max(x1, f.px(x));
        y0 = std::min(y0, f.py(y));
        y1 = std::max(y1, f.py(y));
      }
      const bool rect = is_box(shape.points);
      const bool tiny = (gap || shape.overlap) && (x1 - x0 < kMinVisible || y1 - y0 < kMinVisible);
      std::string tag, geometry;  // the shape as drawn, for the overlap's hatching over it
      if (rect || tiny) {
        // Too thin to see: widened to the minimum around its centre, its share written beside.
        widen(x0, x1);
        widen(y0, y1);
        const double band = (y1 - y0) / static_cast<double>(shape.outcomes.size());
        std::string g = "<g>" + title;
        for (std::size_t k = 0; k < shape.outcomes.size(); ++k)
          g += "<rect x=\"" + num(x0) + "\" y=\"" + num(y0 + band * static_cast<double>(k)) +
               "\" width=\"" + num(x1 - x0) + "\" height=\"" + num(band) + "\" fill=\"" +
               fill_of(shape.outcomes[k], prefix) + "\"/>";
        g += "</g>";
        (tiny ? lines : areas) += g;
        tag = "rect";
        geometry = "x=\"" + num(x0) + "\" y=\"" + num(y0) + "\" width=\"" + num(x1 - x0) +
                   "\" height=\"" + num(y1 - y0) + "\"";
        if (tiny && gap) {
          // Beside the shape: right of a thin column, above a thin row; never on another label.
          const std::string text =
              "gap " + detail::share_text({shape.gap_share.value, shape.gap_share.text});
          const bool column = x1 - x0 <= y1 - y0;
          const double lx = column ? x1 + 3 : x0 + 2, ly = column ? (y0 + y1) / 2 + 4 : y0 - 2;
          const double lw = 6.0 * static_cast<double>(text.size());
          bool clear = true;
          for (const auto& [ax, ay, aw] : placed)
            clear = clear && (ly < ay - 11 || ly > ay + 11 || lx + lw < ax || lx > ax + aw);
          if (clear) {
            placed.emplace_back(lx, ly, lw);
            labels += text_at(lx, ly, text,
                              " font-size=\"11\" fill=\"#d62728\" stroke=\"#fff\" "
                              "stroke-width=\"3\" paint-order=\"stroke\"");
          }
        }
      } else {
        std::string pts;
        for (const auto& [x, y] : shape.points)
          pts += (pts.empty() ? "" : " ") + num(f.px(x)) + "," + num(f.py(y));
        areas += "<polygon points=\"" + pts + "\" fill=\"" +
                 fill_of(shape.outcomes.front(), prefix) + "\" stroke=\"" +
                 fill_of(shape.outcomes.front(), prefix) + "\" stroke-width=\"0.3\">" + title +
                 "</polygon>";
        if (shape.outcomes.size() > 1)
          areas += "<polygon points=\"" + pts + "\" fill=\"url(#" + prefix + "-mixed)\"/>";
        tag = "polygon";
        geometry = "points=\"" + pts + "\"";
      }
      if (shape.outcomes.size() > 1) seen.mixed = true;
      if (shape.overlap) {
        // The whole cell hatched over its alternative's colour and outlined, as its legend says.
        seen.overlap = true;
        lines += "<" + tag + " class=\"overlap\" " + geometry + " fill=\"url(#" + prefix +
                 "-overlap-mark)\" stroke=\"" + kOverlapColour +
                 "\" stroke-width=\"1.5\" stroke-dasharray=\"4 2\">" + title + "</" + tag + ">";
      }
      if (gap) seen.gap = true;
      if (shape.uncertain) seen.uncertain = true;
      continue;
    }
    // A boundary: drawn only where the gate has something to say (a gap or an overlap).
    if (!gap && !shape.overlap) continue;
    seen.boundary = true;
    const char* colour = gap ? kGapColour : kOverlapColour;
    if (shape.points.size() == 2) {
      lines += "<line x1=\"" + num(f.px(shape.points[0].first)) + "\" y1=\"" +
               num(f.py(shape.points[0].second)) + "\" x2=\"" + num(f.px(shape.points[1].first)) +
               "\" y2=\"" + num(f.py(shape.points[1].second)) + "\" stroke=\"" + colour +
               "\" stroke-width=\"3\" stroke-linecap=\"round\">" + title + "</line>";
    } else {
      lines += "<circle cx=\"" + num(f.px(shape.points[0].first)) + "\" cy=\"" +
               num(f.py(shape.points[0].second)) + "\" r=\"3.5\" fill=\"" + colour + "\">" + title +
               "</circle>";
    }
  }
  body += "<g shape-rendering=\"crispEdges\">" + areas + "</g>" + lines + labels;
  body += "<rect x=\"" + num(f.left) + "\" y=\"" + num(f.top) + "\" width=\"" + num(f.width) +
          "\" height=\"" + num(f.height) + "\" fill=\"none\" stroke=\"#333\" stroke-width=\"1\"/>";
  // Ticks at every boundary; labels where they do not collide.
  double last = -1e300;
  for (const auto& [at, label] : map.x.ticks) {
    const double x = f.px(at);
    body += "<line x1=\"" + num(x) + "\" y1=\"" + num(f.top + f.height) + "\" x2=\"" + num(x) +
            "\" y2=\"" + num(f.top + f.height + 4) + "\" stroke=\"#333\"/>";
    if (x - last < 6.5 * static_cast<double>(label.size()) + 6) continue;
    body += text_at(x, f.top + f.height + 15, label, " text-anchor=\"middle\" font-size=\"10\"");
    last = x;
  }
  if (f.y != nullptr) {
    last = 1e300;
    for (const auto& [at, label] : f.y->ticks) {
      const double y = f.py(at);
      body += "<line x1=\"" + num(f.left - 4) + "\" y1=\"" + num(y) + "\" x2=\"" + num(f.left) +
              "\" y2=\"" + num(y) + "\" stroke=\"#333\"/>";
      if (last - y < 12) continue;
      body += text_at(f.left - 6, y + 3.5, label, " text-anchor=\"end\" font-size=\"10\"");
      last = y;
    }
  }
  if (!panel.label.empty())
    body += text_at(f.left + f.width / 2, f.top - 6, panel.label,
                    " text-anchor=\"middle\" font-weight=\"600\"");
}

// The cells runs visited in one panel, outlined over the map; a boundary cell (a segment or a
// point) is drawn thick. Too thin to see: widened to the minimum around its centre.
std::string visited_marks(const std::vector<verify::MapMark>& visited, std::size_t panel,
                          const Frame& f) {
  std::string out;
  for (const verify::MapMark& mark : visited) {
    if (mark.panel != panel || mark.points.empty()) continue;
    std::string runs;
    for (const auto& run : mark.runs) runs += (runs.empty() ? "" : ", ") + run;
    const std::string title =
        "<title>" + detail::html_escape("visited by " + runs + ": " + mark.where) + "</title>";
    const char* style =
        "\" fill=\"#000\" fill-opacity=\"0.12\" stroke=\"#000\" stroke-width=\"2\">";
    const auto& p = mark.points;
    if (is_box(p)) {
      double x0 = std::min(f.px(p[0].first), f.px(p[2].first));
      double x1 = std::max(f.px(p[0].first), f.px(p[2].first));
      double y0 = std::min(f.py(p[0].second), f.py(p[2].second));
      double y1 = std::max(f.py(p[0].second), f.py(p[2].second));
      widen(x0, x1);
      widen(y0, y1);
      out += "<rect class=\"visited\" x=\"" + num(x0) + "\" y=\"" + num(y0) + "\" width=\"" +
             num(x1 - x0) + "\" height=\"" + num(y1 - y0) + style + title + "</rect>";
    } else if (p.size() >= 3) {
      std::string pts;
      for (const auto& [x, y] : p)
        pts += (pts.empty() ? "" : " ") + num(f.px(x)) + "," + num(f.py(y));
      out += "<polygon class=\"visited\" points=\"" + pts + style + title + "</polygon>";
    } else if (p.size() == 2) {
      out += "<line class=\"visited\" x1=\"" + num(f.px(p[0].first)) + "\" y1=\"" +
             num(f.py(p[0].second)) + "\" x2=\"" + num(f.px(p[1].first)) + "\" y2=\"" +
             num(f.py(p[1].second)) +
             "\" stroke=\"#000\" stroke-width=\"4\" stroke-linecap=\"round\">" + title + "</line>";
    } else {
      out += "<circle class=\"visited\" cx=\"" + num(f.px(p[0].first)) + "\" cy=\"" +
             num(f.py(p[0].second)) +
             "\" r=\"4\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\">" + title + "</circle>";
    }
  }
  return out;
}

}  // namespace

std::string coverage_map_svg(const load::Mission&, const verify::Coverage& coverage,
                             const std::vector<verify::MapMark>& visited) {
  if (!coverage.map || coverage.map->panels.empty()) return {};
  const verify::CoverageMap& map = *coverage.map;
  const std::string prefix = id_prefix(coverage.adaptable, "map");
  const std::size_t n = map.panels.size();
  const std::size_t columns = std::min<std::size_t>(n, 3);
  const std::size_t rows_of_panels = (n + columns - 1) / columns;
  const double pw = columns == 1 ? 440 : columns == 2 ? 300 : 210;
  const double ph = map.y ? (columns == 1 ? 300 : pw * 0.8) : 44;
  const double left = 64, top = 52, gap_x = 150, gap_y = 70;
  std::string body;
  MapLegend seen;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = left + static_cast<double>(k % columns) * (pw + gap_x);
    const double y = top + static_cast<double>(k / columns) * (ph + gap_y);
    Frame f{x, y, pw, ph, &map.x, map.y ? &*map.y : nullptr};
    draw_panel(map, map.panels[k], f, coverage, prefix, seen, body);
    body += visited_marks(visited, k, f);
    body += text_at(x + pw / 2, y + ph + 30, map.x.variable,
                    " text-anchor=\"middle\" font-size=\"12\" font-weight=\"600\"");
    if (map.y && k % columns == 0)
      body += "<text x=\"14\" y=\"" + num(y + ph / 2) + "\" transform=\"rotate(-90 14 " +
              num(y + ph / 2) + ")\" text-anchor=\"middle\" font-size=\"12\" font-weight=\"600\">" +
              detail::html_escape(map.y->variable) + "</text>";
  }
  std::vector<LegendRow> rows;
  for (std::size_t i = 0; i < coverage.alternatives.size(); ++i)
    rows.push_back({detail::alternative_colour(i),
                    coverage.alternatives[i].name + " — " + coverage.alternatives[i].requirement});
  if (seen.gap)
    rows.push_back({"url(#" + prefix + "-gap)", "gap — no guard holds, the node fails"});
  if (seen.overlap)
    rows.push_back({"url(#" + prefix + "-overlap-mark)",
                    "hatched, dashed outline: two or more guards hold (the first in priority "
                    "order is selected)"});
  if (seen.boundary)
    rows.push_back({kGapColour,
                    "thick line or point: a boundary (measure 0) in the gap (red) or "
                    "where guards overlap (grey)"});
  if (seen.mixed)
    rows.push_back({"url(#" + prefix + "-mixed)",
                    "striped: the alternative depends on variables off the map"});
  if (seen.uncertain)
    rows.push_back({"#f4f4f4",
                    "not measured exactly: an atom that is not linear, or relates more than "
                    "two variables (a guard's or an assumption's), cuts the cell; it is painted "
                    "whole"});
  if (!visited.empty()) {
    const bool boundary = std::any_of(visited.begin(), visited.end(),
                                      [](const verify::MapMark& m) { return m.points.size() < 3; });
    rows.push_back(
        {"#e0e0e0", std::string("outlined: a cell the runs visited (its tooltip names "
                                "them)") +
                        (boundary ? "; thick black: a boundary cell they visited" : "")});
  }
  const double legend_top = top + static_cast<double>(rows_of_panels) * (ph + gap_y) - 14;
  const double width = std::max(kWidth, left + static_cast<double>(columns) * (pw + gap_x));
  const double height = legend_top + kLegendRow * static_cast<double>(rows.size()) + 4;
  std::string title = "Selected alternative of " + coverage.adaptable + " over " + map.x.variable +
                      (map.y ? " and " + map.y->variable : "");
  if (!map.panel_variable.empty()) title += ", one panel per value of " + map.panel_variable;
  std::string out = svg_open(width, height, title);
  out += patterns(prefix);
  out += "<defs><pattern id=\"" + prefix +
         "-mixed\" patternUnits=\"userSpaceOnUse\" width=\"6\" height=\"6\" "
         "patternTransform=\"rotate(45)\"><rect width=\"2\" height=\"6\" fill=\"#fff\" "
         "fill-opacity=\"0.7\"/></pattern>";
  // The overlap's hatching, over an alternative's colour: dark stripes on nothing.
  if (seen.overlap)
    out += "<pattern id=\"" + prefix +
           "-overlap-mark\" patternUnits=\"userSpaceOnUse\" width=\"6\" height=\"6\" "
           "patternTransform=\"rotate(-45)\"><rect width=\"1.5\" height=\"6\" fill=\"" +
           kOverlapColour + "\"/></pattern>";
  out += "</defs>";
  out += text_at(kMargin, 18, title, " font-weight=\"600\"");
  out += text_at(kMargin, 34,
                 "Cells follow the exact boundaries of the guards; thin gaps are widened to " +
                     num(kMinVisible) + " px and labelled with their exact share.",
                 " font-size=\"11\" fill=\"#555\"");
  out += body + legend(rows, legend_top) + "</svg>";
  return out;
}

}  // namespace uabt::report
