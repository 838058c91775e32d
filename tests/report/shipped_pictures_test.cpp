// Every gap and overlap the verifier reports on a shipped mission is a listed region and is
// visible in the HTML picture: a drawn shape of the map holds its witness.
#include <gtest/gtest.h>

#include <cmath>

#include "load/mission.hpp"
#include "report/common.hpp"
#include "report/reports.hpp"
#include "test_support.hpp"
#include "verify/verify.hpp"

namespace uabt::report {
namespace {

// Where a witness lies along an axis of the map, in the map's coordinates.
double coordinate(const verify::MapAxis& axis, const fretish::Domain& domain, const State& state) {
  const Value* v = find_value(state, axis.variable);
  if (v == nullptr) return NAN;
  switch (v->kind) {
    case Value::Kind::boolean: return v->boolean ? 1.5 : 0.5;
    case Value::Kind::integer: return static_cast<double>(v->integer);
    case Value::Kind::real: return v->real;
    case Value::Kind::enumeration: {
      const auto* var = domain.find(axis.variable);
      for (std::size_t k = 0; var && k < var->enum_values.size(); ++k)
        if (var->enum_values[k] == v->text) return static_cast<double>(k) + 0.5;
      return NAN;
    }
  }
  return NAN;
}

// Closed containment in a convex polygon, a segment or a point.
bool holds_point(const std::vector<std::pair<double, double>>& pts, double x, double y) {
  constexpr double eps = 1e-9;
  if (pts.size() == 1)
    return std::fabs(pts[0].first - x) < eps && std::fabs(pts[0].second - y) < eps;
  if (pts.size() == 2) {
    const auto [ax, ay] = pts[0];
    const auto [bx, by] = pts[1];
    const double cross = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
    return std::fabs(cross) < eps && x >= std::min(ax, bx) - eps && x <= std::max(ax, bx) + eps &&
           y >= std::min(ay, by) - eps && y <= std::max(ay, by) + eps;
  }
  int sign = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto [ax, ay] = pts[i];
    const auto [bx, by] = pts[(i + 1) % pts.size()];
    const double cross = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
    if (std::fabs(cross) < eps) continue;
    const int s = cross > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return true;
}

void expect_reported_states_drawn(const std::string& name) {
  SCOPED_TRACE(name);
  std::string error;
  auto mission = load::load_mission(testing::mission_dir(name), {}, error);
  ASSERT_TRUE(mission) << error;
  const verify::Result result = verify::verify_mission(*mission, {});
  std::size_t checked = 0;
  for (const auto& f : result.findings) {
    if (f.check != "guard-gap" && f.check != "guard-overlap") continue;
    const bool gap = f.check == "guard-gap";
    const verify::Coverage* c = nullptr;
    for (const auto& cov : result.coverage)
      if (cov.adaptable == f.adaptable) c = &cov;
    ASSERT_NE(c, nullptr);
    // A listed region.
    EXPECT_FALSE((gap ? c->gap_regions : c->overlap_regions).empty()) << f.message;
    // A drawn shape that holds the witness.
    ASSERT_TRUE(c->map.has_value());
    const auto& map = *c->map;
    const double x = coordinate(map.x, mission->domain, f.witness);
    const double y = map.y ? coordinate(*map.y, mission->domain, f.witness) : 0.5;
    std::string panel_label;
    if (!map.panel_variable.empty()) {
      const Value* v = find_value(f.witness, map.panel_variable);
      ASSERT_NE(v, nullptr);
      panel_label = map.panel_variable + " = " + v->to_string();
      if (v->kind == Value::Kind::boolean)
        panel_label = (v->boolean ? "" : "!") + map.panel_variable;
    }
    const verify::MapShape* drawn = nullptr;
    for (const auto& panel : map.panels) {
      if (panel.label != panel_label) continue;
      for (const auto& shape : panel.shapes) {
        const bool is_gap =
            std::find(shape.outcomes.begin(), shape.outcomes.end(), -1) != shape.outcomes.end();
        if ((gap ? is_gap : shape.overlap) && holds_point(shape.points, x, y)) drawn = &shape;
      }
    }
    ASSERT_NE(drawn, nullptr) << "no gap/overlap shape holds the witness of: " << f.message;
    const std::string svg = coverage_map_svg(*mission, *c);
    EXPECT_NE(svg.find("<title>" + detail::html_escape(drawn->where) + ": "), std::string::npos)
        << drawn->where;
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

TEST(ShippedPictures, EveryReportedGapAndOverlapIsDrawn) {
  expect_reported_states_drawn("msl_curiosity_paper");
  expect_reported_states_drawn("planetary_landing_unsafe");
}

}  // namespace
}  // namespace uabt::report
