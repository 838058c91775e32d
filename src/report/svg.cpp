#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>

#include "fretish/expr.hpp"
#include "report/common.hpp"
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

std::string states_text(std::uint64_t n) {
  return std::to_string(n) + (n == 1 ? " state" : " states");
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

// ---- the map over two variables ----------------------------------------------------------

// One column or row of the map: the value drawn there and its label.
struct AxisCell {
  Value value;
  std::string label;
};

struct Axis {
  const fretish::Variable* variable = nullptr;
  std::vector<AxisCell> cells;
  bool sampled = false;  // cells stand for intervals, evaluated at their centre
};

std::optional<double> parse_double(const std::string& text) {
  double out = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(out))
    return std::nullopt;
  return out;
}

std::string short_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

Value real_value(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return Value::of_real(x, buffer);
}

constexpr std::size_t kMaxCells = 32;

// The cells of a variable along an axis; nullopt when it cannot be drawn (unbounded number).
std::optional<Axis> make_axis(const fretish::Variable& variable) {
  Axis axis;
  axis.variable = &variable;
  switch (variable.type) {
    case fretish::VarType::boolean:
      axis.cells = {{Value::of_bool(false), "false"}, {Value::of_bool(true), "true"}};
      return axis;
    case fretish::VarType::enumeration:
      if (variable.enum_values.empty() || variable.enum_values.size() > kMaxCells)
        return std::nullopt;
      for (const auto& literal : variable.enum_values)
        axis.cells.push_back({Value::of_enum(literal), literal});
      return axis;
    case fretish::VarType::integer:
    case fretish::VarType::real: {
      const auto lo = parse_double(variable.lower), hi = parse_double(variable.upper);
      if (!lo || !hi || *hi < *lo) return std::nullopt;
      if (variable.type == fretish::VarType::integer) {
        const double first = std::ceil(*lo), last = std::floor(*hi);
        if (last < first || last - first > 1e15) return std::nullopt;
        const double count = last - first + 1;
        if (count <= static_cast<double>(kMaxCells)) {
          for (double v = first; v <= last; v += 1) {
            const auto i = static_cast<std::int64_t>(v);
            axis.cells.push_back({Value::of_int(i), std::to_string(i)});
          }
          return axis;
        }
        axis.sampled = true;
        for (std::size_t k = 0; k < kMaxCells; ++k) {
          const double from = first + count * static_cast<double>(k) / kMaxCells;
          const double to = first + count * static_cast<double>(k + 1) / kMaxCells;
          const auto centre = static_cast<std::int64_t>(std::floor((from + to) / 2));
          axis.cells.push_back({Value::of_int(centre), std::to_string(centre)});
        }
        return axis;
      }
      axis.sampled = true;
      const double span = *hi - *lo;
      for (std::size_t k = 0; k < kMaxCells; ++k) {
        const double centre = *lo + span * (static_cast<double>(k) + 0.5) / kMaxCells;
        axis.cells.push_back({real_value(centre), short_number(centre)});
      }
      return axis;
    }
  }
  return std::nullopt;
}

// Values tried for a variable that is not on an axis: all of a small discrete set, else its
// bounds and centre (what the map says it does).
std::vector<Value> sample_values(const fretish::Variable& variable) {
  std::vector<Value> out;
  switch (variable.type) {
    case fretish::VarType::boolean: return {Value::of_bool(false), Value::of_bool(true)};
    case fretish::VarType::enumeration:
      for (const auto& literal : variable.enum_values) out.push_back(Value::of_enum(literal));
      return out;
    case fretish::VarType::integer:
    case fretish::VarType::real: {
      const auto lo = parse_double(variable.lower), hi = parse_double(variable.upper);
      std::vector<double> points;
      if (lo) points.push_back(*lo);
      if (lo && hi) points.push_back((*lo + *hi) / 2);
      if (hi) points.push_back(*hi);
      if (points.empty()) points.push_back(0);
      for (double p : points) {
        if (variable.type == fretish::VarType::integer) {
          const Value v = Value::of_int(static_cast<std::int64_t>(std::floor(p)));
          if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
        } else {
          const Value v = real_value(p);
          if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
        }
      }
      return out;
    }
  }
  return out;
}

constexpr std::size_t kMaxOtherStates = 256;
constexpr int kGap = std::numeric_limits<int>::max();  // sorts after every alternative

// What one cell of the map shows: the outcomes (alternative index or kGap) of the domain's
// states that project onto it, and whether two guards hold in one of them.
struct CellResult {
  std::set<int> outcomes;
  bool overlap = false;
  bool unknown = false;  // a guard has no value (e.g. division by zero) in some state
};

}  // namespace

std::string coverage_svg(const verify::Coverage& coverage) {
  const std::string prefix = id_prefix(coverage.adaptable, "bar");
  const double bar_x = kMargin, bar_y = 28, bar_w = kWidth - 2 * kMargin, bar_h = 36;
  std::string body;
  std::vector<LegendRow> rows;
  double legend_top = bar_y + bar_h + 16;

  if (coverage.counted && coverage.states > 0) {
    // Cumulative edges, so that rounding never leaves a hair-line between segments.
    std::uint64_t before = 0;
    auto edge = [&](std::uint64_t n) {
      return bar_x + bar_w * static_cast<double>(n) / static_cast<double>(coverage.states);
    };
    auto segment = [&](std::uint64_t n, const std::string& fill, const std::string& ink,
                       const std::string& tooltip) {
      if (n == 0) return;
      const double x0 = edge(before), x1 = edge(before + n);
      body += "<rect x=\"" + num(x0) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(x1 - x0) +
              "\" height=\"" + num(bar_h) + "\" fill=\"" + fill +
              "\" stroke=\"#fff\" stroke-width=\"1\"><title>" + detail::html_escape(tooltip) +
              "</title></rect>";
      if (x1 - x0 >= 48 && !ink.empty())
        body += text_at((x0 + x1) / 2, bar_y + bar_h / 2 + 4.5, detail::percent(n, coverage.states),
                        (" text-anchor=\"middle\" fill=\"" + ink + "\"").c_str());
      before += n;
    };
    for (std::size_t i = 0; i < coverage.alternatives.size(); ++i) {
      const auto& alternative = coverage.alternatives[i];
      const std::string colour = detail::alternative_colour(i);
      const std::string share = states_text(alternative.states) + " (" +
                                detail::percent(alternative.states, coverage.states) + ")";
      segment(alternative.states, colour, text_colour_on(colour),
              alternative.name + " (" + alternative.requirement + "): " + share);
      std::string text =
          alternative.name + " — " + alternative.requirement + ": selected in " + share;
      if (!alternative.reachable || alternative.states == 0) text += ", never selected";
      // enabled_states counts the states where the guard holds, selected or not.
      if (alternative.enabled_states > alternative.states)
        text += "; its guard holds in " + std::to_string(alternative.enabled_states) + " (" +
                detail::percent(alternative.enabled_states, coverage.states) + ")";
      rows.push_back({colour, text});
    }
    segment(coverage.gap_states, "url(#" + prefix + "-gap)", "",
            "gap: no guard holds in " + states_text(coverage.gap_states) + " (" +
                detail::percent(coverage.gap_states, coverage.states) + ")");
    body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(bar_w) +
            "\" height=\"" + num(bar_h) + "\" fill=\"none\" stroke=\"#333\" stroke-width=\"1\"/>";

    // The overlap states are inside the alternatives' segments (the first guard wins there),
    // so they get their own gauge under the bar rather than a place in it.
    const double gauge_y = bar_y + bar_h + 8, gauge_h = 10;
    body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(gauge_y) + "\" width=\"" + num(bar_w) +
            "\" height=\"" + num(gauge_h) +
            "\" fill=\"#f2f2f2\" stroke=\"#999\" "
            "stroke-width=\"0.5\"/>";
    if (coverage.overlap_states > 0)
      body += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(gauge_y) + "\" width=\"" +
              num(edge(coverage.overlap_states) - bar_x) + "\" height=\"" + num(gauge_h) +
              "\" fill=\"url(#" + prefix + "-overlap)\" stroke=\"" + kOverlapColour +
              "\" stroke-width=\"0.5\"><title>overlap: " +
              detail::html_escape(states_text(coverage.overlap_states)) +
              " where two or more guards hold</title></rect>";
    legend_top = gauge_y + gauge_h + 14;
    rows.push_back({"url(#" + prefix + "-gap)",
                    "gap — no guard holds, the node fails: " + states_text(coverage.gap_states) +
                        " (" + detail::percent(coverage.gap_states, coverage.states) + ")"});
    rows.push_back({"url(#" + prefix + "-overlap)",
                    "overlap — two or more guards hold (gauge under the bar): " +
                        states_text(coverage.overlap_states) + " (" +
                        detail::percent(coverage.overlap_states, coverage.states) + ")"});
  } else {
    const std::string why = coverage.counted
                                ? "the domain admits no state"
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
      rows.push_back(
          {detail::alternative_colour(i),
           alternative.name + " — " + alternative.requirement +
               (alternative.reachable ? ": selected in some state" : ": never selected")});
    }
  }

  const double height = legend_top + kLegendRow * static_cast<double>(rows.size()) + 4;
  std::string out = svg_open(kWidth, height, "Terrain coverage of " + coverage.adaptable);
  out += patterns(prefix);
  std::string heading = coverage.adaptable + ": ";
  heading += coverage.counted ? states_text(coverage.states) + " in the domain"
                              : std::string("state space not counted");
  out += text_at(kMargin, 18, heading, " font-weight=\"600\"");
  out += body;
  out += legend(rows, legend_top);
  out += "</svg>";
  return out;
}

namespace {

// The map of one pair of axes: the outcome of every cell.
struct Map {
  const Axis* x = nullptr;
  const Axis* y = nullptr;
  std::vector<CellResult> cells;  // row-major from the bottom row: cells[iy * nx + ix]
  bool other_variables = false;   // some variable off the axes was tried at several values
  std::size_t mixed = 0;          // cells whose outcome depends on the other variables
};

struct MapContext {
  const fretish::Domain& domain;
  const std::vector<const fretish::SelectionRequirement*>& selections;
  const std::vector<int>& colour_of;      // selection index → alternative (colour) index
  const std::set<std::string>& relevant;  // variables a guard or an assumption reads
};

// States a map may evaluate over all pairs of axes: bounds the report's time whatever the
// domain, and counts work rather than time so that the chosen map is deterministic.
constexpr std::size_t kMapBudget = std::size_t{1} << 20;

std::optional<Map> compute_map(const MapContext& context, const Axis& x_axis, const Axis& y_axis,
                               std::size_t& budget) {
  const fretish::Domain& domain = context.domain;
  // Every other variable: all its sample values when a guard or an assumption reads it (it
  // can change the outcome), one value otherwise (the state must still be complete).
  std::vector<std::pair<std::size_t, std::vector<Value>>> others;  // state slot, values
  std::size_t other_states = 1;
  State state;
  std::size_t x_slot = 0, y_slot = 0;
  for (const auto& variable : domain.variables) {
    if (&variable == x_axis.variable) x_slot = state.size();
    if (&variable == y_axis.variable) y_slot = state.size();
    if (&variable != x_axis.variable && &variable != y_axis.variable) {
      std::vector<Value> values = sample_values(variable);
      if (values.empty()) return std::nullopt;
      if (!context.relevant.count(variable.name)) values.resize(1);
      other_states *= values.size();
      if (other_states > kMaxOtherStates) return std::nullopt;
      others.emplace_back(state.size(), std::move(values));
    }
    state.emplace_back(variable.name, Value());
  }

  const std::size_t work = x_axis.cells.size() * y_axis.cells.size() * other_states;
  if (work > budget) return std::nullopt;
  budget -= work;

  Map map;
  map.x = &x_axis;
  map.y = &y_axis;
  map.other_variables = other_states > 1;
  const std::size_t nx = x_axis.cells.size(), ny = y_axis.cells.size();
  map.cells.resize(nx * ny);
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t ix = 0; ix < nx; ++ix) {
      CellResult& cell = map.cells[iy * nx + ix];
      state[x_slot].second = x_axis.cells[ix].value;
      state[y_slot].second = y_axis.cells[iy].value;
      for (std::size_t combination = 0; combination < other_states; ++combination) {
        std::size_t rest = combination;
        for (const auto& [slot, values] : others) {
          state[slot].second = values[rest % values.size()];
          rest /= values.size();
        }
        if (!smt::satisfies_domain(domain, state)) continue;
        int outcome = kGap;
        int guards_holding = 0;
        for (std::size_t k = 0; k < context.selections.size(); ++k) {
          bool holds = true;
          if (context.selections[k]->guard) {
            const auto value = smt::try_evaluate(*context.selections[k]->guard, domain, state);
            if (!value) cell.unknown = true;
            holds = value.value_or(false);
            if (holds) ++guards_holding;
          }
          if (holds && outcome == kGap) outcome = context.colour_of[k];
        }
        cell.outcomes.insert(outcome);
        if (guards_holding >= 2) cell.overlap = true;
      }
      if (cell.outcomes.size() > 1) ++map.mixed;
    }
  }
  return map;
}

// Where a tick stands along an axis (0 = first edge, 1 = last edge) and what it says. A
// short discrete axis labels every cell; a sampled one its bounds and centre.
std::vector<std::pair<double, std::string>> ticks(const Axis& axis) {
  std::vector<std::pair<double, std::string>> out;
  const auto n = static_cast<double>(axis.cells.size());
  if (axis.sampled) {
    const auto lo = parse_double(axis.variable->lower), hi = parse_double(axis.variable->upper);
    if (lo && hi) {
      return {
          {0.0, short_number(*lo)}, {0.5, short_number((*lo + *hi) / 2)}, {1.0, short_number(*hi)}};
    }
  }
  if (axis.cells.size() <= 12) {
    for (std::size_t i = 0; i < axis.cells.size(); ++i)
      out.emplace_back((static_cast<double>(i) + 0.5) / n, axis.cells[i].label);
    return out;
  }
  for (std::size_t i : {std::size_t{0}, axis.cells.size() / 2, axis.cells.size() - 1})
    out.emplace_back((static_cast<double>(i) + 0.5) / n, axis.cells[i].label);
  return out;
}

}  // namespace

std::string coverage_map_svg(const load::Mission& mission, const verify::Coverage& coverage) {
  const auto selections = detail::selections_of(mission, coverage.adaptable);
  if (selections.empty()) return {};
  const fretish::Domain& domain = mission.domain;

  std::set<std::string> used;
  for (const auto* selection : selections)
    if (selection->guard)
      for (const auto& name : fretish::identifiers_of(*selection->guard)) used.insert(name);
  std::set<std::string> relevant = used;
  for (const auto& assumption : domain.assumptions)
    if (assumption.expr)
      for (const auto& name : fretish::identifiers_of(*assumption.expr)) relevant.insert(name);

  // Candidate axes: the drawable variables the guards read, in declaration order.
  constexpr std::size_t kMaxCandidates = 6;
  std::vector<Axis> axes;
  for (const auto& variable : domain.variables) {
    if (axes.size() == kMaxCandidates || !used.count(variable.name)) continue;
    if (auto axis = make_axis(variable)) axes.push_back(std::move(*axis));
  }
  if (axes.size() < 2) return {};

  // Colours follow the coverage's alternative order (the bar's), matched by requirement.
  std::vector<int> colour_of(selections.size());
  for (std::size_t k = 0; k < selections.size(); ++k) {
    colour_of[k] = static_cast<int>(k);
    for (std::size_t i = 0; i < coverage.alternatives.size(); ++i)
      if (coverage.alternatives[i].requirement == selections[k]->id)
        colour_of[k] = static_cast<int>(i);
  }

  // The pair of axes that leaves the fewest cells depending on the other variables (by share
  // of cells); ties go to declaration order.
  const MapContext context{domain, selections, colour_of, relevant};
  std::optional<Map> best;
  std::size_t budget = kMapBudget;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    for (std::size_t b = a + 1; b < axes.size(); ++b) {
      auto map = compute_map(context, axes[a], axes[b], budget);
      if (!map) continue;
      if (!best || map->mixed * best->cells.size() < best->mixed * map->cells.size())
        best = std::move(map);
    }
  }
  if (!best) return {};
  const Map& map = *best;
  const Axis& x_axis = *map.x;
  const Axis& y_axis = *map.y;
  const std::size_t nx = x_axis.cells.size(), ny = y_axis.cells.size();

  const std::string prefix = id_prefix(coverage.adaptable, "map");
  // Cells at most 80 px a side, so that a 2 × 2 map stays a compact picture.
  const double left = 110, top = 34;
  const double plot_w = std::min(360.0, 80.0 * static_cast<double>(nx));
  const double plot_h = std::min(360.0, 80.0 * static_cast<double>(ny));
  const double cw = plot_w / static_cast<double>(nx), ch = plot_h / static_cast<double>(ny);
  // Crisp edges: anti-aliased seams between neighbouring cells would read as grid lines.
  std::string body = "<g shape-rendering=\"crispEdges\">";
  bool any_mixed = false, any_outside = false, any_overlap = false, any_gap = false;
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const CellResult& cell = map.cells[iy * nx + ix];
      // y grows upward, as on a plot: the first value at the bottom.
      const double x = left + cw * static_cast<double>(ix);
      const double y = top + plot_h - ch * static_cast<double>(iy + 1);
      std::string tooltip = x_axis.variable->name + " = " + x_axis.cells[ix].label + ", " +
                            y_axis.variable->name + " = " + y_axis.cells[iy].label + ": ";
      if (cell.outcomes.empty()) {
        any_outside = true;
        tooltip += "outside the domain";
        body += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(cw) +
                "\" height=\"" + num(ch) +
                "\" fill=\"#f4f4f4\" stroke=\"#fff\" "
                "stroke-width=\"0.5\"><title>" +
                detail::html_escape(tooltip) + "</title></rect>";
        continue;
      }
      // A cell whose outcome depends on the other variables is split into equal bands.
      std::string names;
      const double band = ch / static_cast<double>(cell.outcomes.size());
      std::size_t k = 0;
      std::string bands;
      for (int outcome : cell.outcomes) {
        const std::string fill = outcome == kGap ? "url(#" + prefix + "-gap)"
                                                 : std::string(detail::alternative_colour(outcome));
        bands += "<rect x=\"" + num(x) + "\" y=\"" + num(y + band * static_cast<double>(k)) +
                 "\" width=\"" + num(cw) + "\" height=\"" + num(band) + "\" fill=\"" + fill +
                 "\"/>";
        if (!names.empty()) names += " or ";
        names += outcome == kGap ? std::string("gap")
                 : static_cast<std::size_t>(outcome) < coverage.alternatives.size()
                     ? coverage.alternatives[outcome].name
                     : "alternative " + std::to_string(outcome + 1);
        ++k;
      }
      if (cell.outcomes.size() > 1) any_mixed = true;
      if (cell.outcomes.count(kGap)) any_gap = true;
      tooltip += names;
      if (cell.outcomes.size() > 1) tooltip += " (depends on the other variables)";
      if (cell.overlap) tooltip += "; two or more guards hold";
      if (cell.unknown) tooltip += "; a guard has no value in some state";
      body += "<g><title>" + detail::html_escape(tooltip) + "</title>" + bands;
      if (cell.overlap) {
        any_overlap = true;
        const double r = std::clamp(std::min(cw, ch) / 5, 1.5, 6.0);
        body += "<circle cx=\"" + num(x + cw / 2) + "\" cy=\"" + num(y + ch / 2) + "\" r=\"" +
                num(r) + "\" fill=\"" + kOverlapColour +
                "\" stroke=\"#fff\" stroke-width=\"0.75\"/>";
      }
      body += "</g>";
    }
  }
  body += "</g>";
  body += "<rect x=\"" + num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(plot_w) +
          "\" height=\"" + num(plot_h) + "\" fill=\"none\" stroke=\"#333\" stroke-width=\"1\"/>";

  for (const auto& [at, label] : ticks(x_axis))
    body += text_at(left + plot_w * at, top + plot_h + 16, label,
                    " text-anchor=\"middle\" font-size=\"11\"");
  for (const auto& [at, label] : ticks(y_axis))
    body += text_at(left - 6, top + plot_h - plot_h * at + 4, label,
                    " text-anchor=\"end\" font-size=\"11\"");
  body += text_at(left + plot_w / 2, top + plot_h + 34, x_axis.variable->name,
                  " text-anchor=\"middle\" font-weight=\"600\"");
  body += "<text x=\"14\" y=\"" + num(top + plot_h / 2) + "\" transform=\"rotate(-90 14 " +
          num(top + plot_h / 2) + ")\" text-anchor=\"middle\" font-weight=\"600\">" +
          detail::html_escape(y_axis.variable->name) + "</text>";

  std::vector<LegendRow> rows;
  for (std::size_t i = 0; i < coverage.alternatives.size(); ++i)
    rows.push_back({detail::alternative_colour(i),
                    coverage.alternatives[i].name + " — " + coverage.alternatives[i].requirement});
  if (any_gap) rows.push_back({"url(#" + prefix + "-gap)", "gap — no guard holds"});
  if (any_overlap) rows.push_back({kOverlapColour, "dot: two or more guards hold"});
  if (any_outside) rows.push_back({"#f4f4f4", "outside the domain (assumptions)"});
  double legend_top = top + plot_h + 52;
  std::string notes;
  std::string note;
  if (map.other_variables) note += "other variables tried at a few values each; ";
  if (any_mixed) note += "a banded cell's alternative depends on them; ";
  if (x_axis.sampled || y_axis.sampled) note += "numeric cells evaluated at their centre; ";
  if (!note.empty()) {
    note.resize(note.size() - 2);
    notes = text_at(kMargin, legend_top + 10, note, " font-size=\"11\" fill=\"#555\"");
    legend_top += 20;
  }
  const double height = legend_top + kLegendRow * static_cast<double>(rows.size()) + 4;
  // As wide as the plot or the longest line needs (about 7 px a character at 13 px).
  std::size_t longest = (x_axis.variable->name.size() + y_axis.variable->name.size() +
                         coverage.adaptable.size() + 36) *
                        7 / 6;
  for (const auto& row : rows) longest = std::max(longest, row.text.size() + 4);
  const double width = std::min(
      kWidth, std::max({left + plot_w + 30, kMargin + 22 + 7.0 * static_cast<double>(longest),
                        kMargin + 6.0 * static_cast<double>(note.size())}));
  std::string out = svg_open(width, height,
                             "Selected alternative of " + coverage.adaptable + " over " +
                                 x_axis.variable->name + " and " + y_axis.variable->name);
  out += patterns(prefix);
  out += text_at(kMargin, 18,
                 coverage.adaptable + ": selected alternative over " + x_axis.variable->name +
                     " × " + y_axis.variable->name,
                 " font-weight=\"600\"");
  out += body + notes + legend(rows, legend_top) + "</svg>";
  return out;
}

}  // namespace uabt::report
