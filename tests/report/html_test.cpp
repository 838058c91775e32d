#include <gtest/gtest.h>

#include <tinyxml2.h>

#include "fretish/expr.hpp"
#include "load/mission.hpp"
#include "report/reports.hpp"
#include "report_fixtures.hpp"
#include "test_support.hpp"
#include "verify/verify.hpp"

namespace uabt::report {
namespace {

using fretish::ExprKind;
using fretish::make_expr;
using fretish::make_identifier;
using fretish::make_number;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

bool well_formed_xml(const std::string& text) {
  tinyxml2::XMLDocument doc;
  return doc.Parse(text.c_str()) == tinyxml2::XML_SUCCESS;
}

fretish::Variable variable(std::string name, fretish::VarType type, std::string lower = {},
                           std::string upper = {}) {
  fretish::Variable v;
  v.name = std::move(name);
  v.type = type;
  v.lower = std::move(lower);
  v.upper = std::move(upper);
  return v;
}

fretish::SelectionRequirement selection(std::string id, std::string adaptable,
                                        std::string alternative, fretish::ExprPtr guard, int line) {
  fretish::SelectionRequirement s;
  s.id = std::move(id);
  s.adaptable = std::move(adaptable);
  s.alternative = std::move(alternative);
  s.guard = std::move(guard);
  s.location = {"requirements.fret", line, 1};
  return s;
}

fretish::Requirement requirement(std::string id, std::string text) {
  fretish::Requirement r;
  r.id = std::move(id);
  r.text = std::move(text);
  return r;
}

// The paper's MSL navigation node, as the loader would hand it over.
load::Mission msl_mission(bool one_terrain) {
  load::Mission mission;
  mission.name = "msl_curiosity_paper";
  mission.domain.variables = {variable("OnDust", fretish::VarType::boolean),
                              variable("OnRocks", fretish::VarType::boolean)};
  if (one_terrain) {
    fretish::Assumption a;
    a.name = "one_terrain";
    a.expr = make_expr(ExprKind::logical_not,
                       {make_expr(ExprKind::logical_and,
                                  {make_identifier("OnDust"), make_identifier("OnRocks")})});
    mission.domain.assumptions.push_back(a);
  }
  mission.requirements = {
      requirement("Req1", "In navigation if OnDust Mission shall satisfy selected_alt = on_dust"),
      requirement("Req2",
                  "In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks")};
  mission.selections = {selection("Req1", "navigation", "on_dust", make_identifier("OnDust"), 1),
                        selection("Req2", "navigation", "on_rocks", make_identifier("OnRocks"), 2)};
  return mission;
}

// The exploration node: numeric guards over battery and slope, overlapping, with a gap.
load::Mission exploration_mission() {
  load::Mission mission;
  mission.name = "exploration";
  mission.domain.variables = {variable("battery", fretish::VarType::integer, "0", "100"),
                              variable("slope", fretish::VarType::real, "-45", "45")};
  auto sand = make_expr(ExprKind::logical_and,
                        {make_expr(ExprKind::lt, {make_identifier("slope"), make_number("10")}),
                         make_expr(ExprKind::gt, {make_identifier("battery"), make_number("30")})});
  auto rocks = make_expr(ExprKind::ge, {make_identifier("slope"), make_number("5")});
  mission.requirements = {requirement("Sand",
                                      "In exploration if slope < 10 & battery > 30 "
                                      "Mission shall satisfy selected_alt = sand_alternative"),
                          requirement("Rocks",
                                      "In exploration if slope >= 5 Mission shall "
                                      "satisfy selected_alt = rocks_alternative")};
  mission.selections = {selection("Sand", "exploration", "sand_alternative", sand, 1),
                        selection("Rocks", "exploration", "rocks_alternative", rocks, 2)};
  return mission;
}

verify::Coverage exploration_coverage() {
  verify::Coverage c;
  c.adaptable = "exploration";
  c.counted = false;
  c.not_counted_reason = "slope is a real variable";
  c.alternatives = {testing::alternative("sand_alternative", "Sand", 0, 0, true),
                    testing::alternative("rocks_alternative", "Rocks", 0, 0, true)};
  c.variables = {"battery", "slope"};
  return c;
}

TEST(HtmlReport, VerdictAndSelfContainedPage) {
  const std::string html = to_html(testing::failing_input());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>\n", 0), 0u);
  EXPECT_TRUE(has(html, "<meta charset=\"utf-8\">"));
  EXPECT_TRUE(has(html, "<div class=\"badge\">FAIL</div>"));
  EXPECT_TRUE(has(html, "<h1>Mission msl_curiosity_paper</h1>"));
  EXPECT_TRUE(has(html, "<svg"));
  // Nothing is fetched: no URL at all, no script, no external style or image.
  EXPECT_FALSE(has(html, "http://"));
  EXPECT_FALSE(has(html, "https://"));
  EXPECT_FALSE(has(html, "<script"));
  EXPECT_FALSE(has(html, "<link"));
  EXPECT_FALSE(has(html, "src="));
  EXPECT_FALSE(has(html, "@import"));
  EXPECT_TRUE(has(to_html(testing::passing_input()), "<div class=\"badge\">PASS</div>"));
}

// The minimal conflicts of `uabt realizable` (and the gate) as a matrix: a row per conflict,
// linked to its finding, a column per requirement in any conflict.
TEST(HtmlReport, ConflictsAsAMatrixOfRequirements) {
  ReportInput input = testing::passing_input();
  EXPECT_FALSE(has(to_html(input), "id=\"realizability\""));
  const std::vector<std::vector<std::string>> conflicts{{"G1", "G2", "G3"}, {"G1", "G3", "G4"}};
  for (const auto& ids : conflicts) {
    Finding f = make_finding("requirements-unrealizable", "no behavior tree meets them together",
                             {"requirements.fret", 1, 5});
    f.requirements = ids;
    input.findings.push_back(f);
  }
  const std::string html = to_html(input);
  EXPECT_TRUE(has(html, "<a href=\"#realizability\">Realizability</a>"));
  EXPECT_TRUE(has(html, "<p>2 minimal sets of guarantees that no behavior tree meets together"));
  EXPECT_TRUE(has(html,
                  "<thead><tr><th>Conflict</th><th><code>G1</code></th><th><code>G2</code>"
                  "</th><th><code>G3</code></th><th><code>G4</code></th></tr></thead>"));
  EXPECT_TRUE(has(html,
                  "<tr><th><a href=\"#conflict-2\">2</a> <span class=\"meta\">error</span>"
                  "</th><td title=\"G1\">&#9679;</td><td></td><td title=\"G3\">&#9679;</td>"
                  "<td title=\"G4\">&#9679;</td></tr>"));
  EXPECT_EQ(count(html, "&#9679;"), 6u);
  // Each row's link lands on its finding.
  EXPECT_TRUE(has(html, "<article class=\"finding error\" id=\"conflict-1\">"));
  EXPECT_TRUE(has(html, "<article class=\"finding error\" id=\"conflict-2\">"));
}

TEST(HtmlReport, EveryFindingMessageEscaped) {
  const ReportInput input = testing::failing_input();
  const std::string html = to_html(input);
  EXPECT_TRUE(has(html, "expected &#39;shall&#39; after &lt;Adaptable&gt; | here"));
  EXPECT_FALSE(has(html, "<Adaptable>"));
  EXPECT_TRUE(has(html, "the guards of Req1 and Req2 both hold in some state"));
  EXPECT_TRUE(has(html, "no requirement of &#39;navigation&#39; holds in some state"));
  EXPECT_TRUE(
      has(html, "alternative &#39;spare&#39; of &#39;navigation&#39; is named by no requirement"));
  EXPECT_TRUE(has(html, "the guards of Arm1 and Arm2 both hold in some state"));
  EXPECT_EQ(count(html, "<article class=\"finding "), input.findings.size());
  EXPECT_EQ(count(html, "uabt explain guard-overlap"), 2u);
}

TEST(HtmlReport, FindingsGroupedByNodeWithWitnessTables) {
  const std::string html = to_html(testing::failing_input());
  const auto navigation = html.find("<h3>Adaptable node <code>navigation</code></h3>");
  const auto arm = html.find("<h3>Adaptable node <code>arm</code></h3>");
  const auto mission_wide = html.find("<h3>Mission-wide</h3>");
  ASSERT_NE(navigation, std::string::npos);
  ASSERT_NE(arm, std::string::npos);
  ASSERT_NE(mission_wide, std::string::npos);
  EXPECT_LT(navigation, arm);
  EXPECT_LT(arm, mission_wide);
  EXPECT_TRUE(has(html, "<tr><td><code>OnDust</code></td><td><code>true</code></td></tr>"));
  EXPECT_TRUE(has(html, "<tr><td><code>slope</code></td><td><code>1/3</code></td></tr>"));
  EXPECT_TRUE(has(html, "Node: <code>spare/Sequence[0]</code>"));
}

TEST(HtmlReport, CoverageInWords) {
  const std::string html = to_html(testing::failing_input());
  EXPECT_TRUE(has(html, "In 25.0% of the domain no guard holds: the adaptable node fails there."));
  // The gap and the overlap are highlighted rows of the decision table.
  EXPECT_TRUE(has(html,
                  "<tr class=\"gap\"><td><strong>gap</strong> <code>Req1</code> "
                  "<code>Req2</code></td><td><code>false</code></td><td><code>false</code></td>"));
  EXPECT_TRUE(has(html, "<tr class=\"overlap\"><td><strong>overlap</strong>"));
  EXPECT_TRUE(has(html, "table.decision tr.gap td { background"));
  EXPECT_TRUE(has(html,
                  "For example, no alternative is selected when <code>OnDust</code> = "
                  "<code>false</code>, <code>OnRocks</code> = <code>false</code>."));
  EXPECT_TRUE(has(html, "The state space was not measured, because slope is a real variable."));
  EXPECT_TRUE(has(html, "<strong>no, never</strong>"));
  EXPECT_TRUE(has(html, "The mission could not be loaded"));
}

// The map is drawn from what the verifier measured: verify the hand-built mission first.
verify::Coverage verified(load::Mission& mission, const std::string& adaptable) {
  load::AdaptableSite site;
  site.id = adaptable;
  site.tree_id = "MainTree";
  mission.adaptables = {site};
  return verify::verify_mission(mission, {}).coverage.at(0);
}

TEST(HtmlReport, RequirementsInPriorityOrderFromTheMission) {
  load::Mission mission = msl_mission(false);
  ReportInput input = testing::failing_input();
  input.mission = &mission;
  input.coverage[0] = verified(mission, "navigation");
  const std::string html = to_html(input);
  const auto req1 = html.find("<code>Req1</code>: In navigation if OnDust Mission shall");
  const auto req2 = html.find("<code>Req2</code>: In navigation if OnRocks Mission shall");
  ASSERT_NE(req1, std::string::npos);
  ASSERT_NE(req2, std::string::npos);
  EXPECT_LT(req1, req2);
  EXPECT_TRUE(has(html, "No selection requirement names this node")) << "arm has none";
  EXPECT_TRUE(has(html, "<h4>Where each alternative is selected</h4>"));
  EXPECT_FALSE(has(html, "http://"));
}

// bb-read-before-write's witness is the path of ticks from the root to the read: the page lists
// it in order, as the terminal does, not only SARIF.
TEST(HtmlReport, BlackboardReadBeforeWriteShowsItsPathOfTicks) {
  std::string error;
  const auto mission = load::load_mission(testing::mission_dir("blackboard_defects"), {}, error);
  ASSERT_TRUE(mission) << error;
  ReportInput input;
  input.mission_name = "blackboard_defects";
  input.findings = verify::verify_mission(*mission, {}).findings;
  input.mission = &*mission;
  const std::string html = to_html(input);
  EXPECT_TRUE(
      has(html,
          "<ol class=\"meta related\">\n"
          "<li><code>mission.xml:6:5</code> ticks Sequence &#39;survey&#39;</li>\n"
          "<li><code>mission.xml:7:7</code> ticks Fallback &#39;find_target&#39;</li>\n"
          "<li><code>mission.xml:8:9</code> ticks Sequence &#39;locate&#39;</li>\n"
          "<li><code>mission.xml:9:11</code> ticks IsTargetVisible</li>\n"
          "<li><code>mission.xml:9:11</code> IsTargetVisible fails</li>\n"
          "<li><code>mission.xml:12:9</code> ticks Wait</li>\n"
          "<li><code>mission.xml:12:9</code> Wait succeeds</li>\n"
          "<li><code>mission.xml:14:7</code> ticks ScriptCondition &#39;in_reach&#39;</li>\n"
          "</ol>\n"))
      << html;
}

TEST(HtmlReport, ByteIdenticalAcrossCalls) {
  const load::Mission mission = exploration_mission();
  ReportInput input = testing::failing_input();
  input.adaptables.push_back("exploration");
  input.coverage.push_back(exploration_coverage());
  input.mission = &mission;
  EXPECT_EQ(to_html(input), to_html(input));
  EXPECT_EQ(to_html(testing::passing_input()), to_html(testing::passing_input()));
}

TEST(CoverageSvg, PartitionBarAndLegend) {
  const verify::Coverage coverage = testing::failing_input().coverage[0];
  const std::string svg = coverage_svg(coverage);
  EXPECT_TRUE(well_formed_xml(svg));
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  // One segment per alternative with states, in priority order, then the hatched gap.
  const auto dust = svg.find("fill=\"#0072b2\" stroke=\"#fff\"");
  const auto rocks = svg.find("fill=\"#e69f00\" stroke=\"#fff\"");
  const auto gap = svg.find("-gap)\" stroke=\"#fff\"");
  ASSERT_NE(dust, std::string::npos);
  ASSERT_NE(rocks, std::string::npos);
  ASSERT_NE(gap, std::string::npos);
  EXPECT_LT(dust, rocks);
  EXPECT_LT(rocks, gap);
  // Segment widths are proportional: 2, 1 and 1 of 4 states over a 700-wide bar.
  EXPECT_TRUE(has(svg, "<rect x=\"10\" y=\"28\" width=\"350\" height=\"36\" fill=\"#0072b2\""));
  EXPECT_TRUE(has(svg, "<rect x=\"360\" y=\"28\" width=\"175\" height=\"36\" fill=\"#e69f00\""));
  // The legend uses the same colours and says the counts.
  EXPECT_TRUE(has(svg, "fill=\"#0072b2\" stroke=\"#333\""));
  EXPECT_TRUE(has(svg, "on_dust — Req1: selected in 2 states (50.0%)"));
  EXPECT_TRUE(
      has(svg, "on_rocks — Req2: selected in 1 state (25.0%); its guard holds in 2 (50.0%)"));
  EXPECT_TRUE(has(svg, "gap — no guard holds, the node fails: 1 state (25.0%)"));
  EXPECT_TRUE(has(svg, "overlap — two or more guards hold (gauge under the bar): 1 state (25.0%)"));
  EXPECT_TRUE(has(svg, "#d62728"));
}

TEST(CoverageSvg, NotCountedSaysWhy) {
  const verify::Coverage coverage = testing::failing_input().coverage[1];
  const std::string svg = coverage_svg(coverage);
  EXPECT_TRUE(well_formed_xml(svg));
  EXPECT_TRUE(has(svg, "not counted: slope is a real variable"));
  EXPECT_TRUE(has(svg, "retract — Arm2: never selected"));
  EXPECT_TRUE(has(svg, "reach — Arm1: selected in some state"));
}

TEST(CoverageSvg, EscapesNames) {
  verify::Coverage coverage = testing::failing_input().coverage[0];
  coverage.adaptable = "nav<&>";
  coverage.alternatives[0].name = "a\"b";
  const std::string svg = coverage_svg(coverage);
  EXPECT_TRUE(well_formed_xml(svg));
  EXPECT_TRUE(has(svg, "nav&lt;&amp;&gt;"));
}

TEST(CoverageMapSvg, BooleanNodeShowsEachState) {
  load::Mission mission = msl_mission(false);
  const std::string svg = coverage_map_svg(mission, verified(mission, "navigation"));
  ASSERT_FALSE(svg.empty());
  EXPECT_TRUE(well_formed_xml(svg));
  EXPECT_TRUE(has(svg, "<title>OnDust &amp; OnRocks: on_dust; two or more guards hold</title>"));
  EXPECT_TRUE(has(svg, "<title>!OnDust &amp; OnRocks: on_rocks</title>"));
  EXPECT_TRUE(has(svg, "<title>!OnDust &amp; !OnRocks: gap (no guard holds)"));
  // The overlap is the whole cell hatched and outlined over its alternative's colour, with a
  // legend entry, not a dot at its centre.
  EXPECT_TRUE(has(svg,
                  "<rect class=\"overlap\" x=\"284\" y=\"52\" width=\"220\" height=\"150\" "
                  "fill=\"url(#uabt-map-84d2a3c65f-overlap-mark)\" stroke=\"#4d4d4d\" "
                  "stroke-width=\"1.5\" stroke-dasharray=\"4 2\"><title>OnDust &amp; OnRocks: "
                  "on_dust; two or more guards hold</title></rect>"))
      << svg;
  EXPECT_TRUE(has(svg, "<pattern id=\"uabt-map-84d2a3c65f-overlap-mark\""));
  EXPECT_TRUE(has(svg,
                  "fill=\"url(#uabt-map-84d2a3c65f-overlap-mark)\" stroke=\"#333\" "
                  "stroke-width=\"0.5\"/><text x=\"32\" y=\""));
  EXPECT_TRUE(has(svg,
                  ">hatched, dashed outline: two or more guards hold (the first in priority "
                  "order is selected)</text>"));
  EXPECT_FALSE(has(svg, "<circle"));
}

TEST(CoverageMapSvg, AssumptionsLeaveImpossibleStatesEmpty) {
  load::Mission mission = msl_mission(true);
  const std::string svg = coverage_map_svg(mission, verified(mission, "navigation"));
  EXPECT_FALSE(has(svg, "<title>OnDust &amp; OnRocks:"));
  EXPECT_FALSE(has(svg, "<circle"));
}

TEST(CoverageMapSvg, RealVariablesAreDrawnAtTheirExactBoundaries) {
  load::Mission mission = exploration_mission();
  const std::string svg = coverage_map_svg(mission, verified(mission, "exploration"));
  ASSERT_FALSE(svg.empty());
  EXPECT_TRUE(well_formed_xml(svg));
  // slope on x with cells cut at 5 and 10, battery on y cut between 30 and 31.
  EXPECT_TRUE(has(svg, "over slope and battery"));
  EXPECT_TRUE(has(svg, ">5</text>"));
  EXPECT_TRUE(has(svg, ">10</text>"));
  // Equal neighbours merge: the overlap from slope = 5 up to 10, the gap below battery 31.
  EXPECT_TRUE(has(svg,
                  "<title>slope in [5, 10) &amp; battery in [31, 100]: sand_alternative; two "
                  "or more guards hold</title>"));
  EXPECT_TRUE(has(svg, "<title>slope in [-45, 5) &amp; battery in [0, 30]: gap (no guard holds)"));
}

// depth and pressure with the domain's sloped assumption 8 * pressure <= depth + 80: the cell
// depth in (0, 50) & pressure in (5, 20) holds states above the line the assumption rules out,
// so the gap there is the quadrilateral (0, 5) (50, 5) (50, 16.25) (0, 10), not its box.
TEST(CoverageMapSvg, ACellASlopedAssumptionCutsIsDrawnAsItsPolygon) {
  load::Mission mission;
  mission.name = "dive";
  mission.domain.variables = {variable("depth", fretish::VarType::real, "0", "100"),
                              variable("pressure", fretish::VarType::real, "0", "20")};
  fretish::Assumption slope;
  slope.name = "slope";
  slope.expr = make_expr(ExprKind::le,
                         {make_expr(ExprKind::mul, {make_number("8"), make_identifier("pressure")}),
                          make_expr(ExprKind::add, {make_identifier("depth"), make_number("80")})});
  mission.domain.assumptions.push_back(std::move(slope));
  auto shallow =
      make_expr(ExprKind::logical_and,
                {make_expr(ExprKind::lt, {make_identifier("depth"), make_number("50")}),
                 make_expr(ExprKind::lt, {make_identifier("pressure"), make_number("5")})});
  auto deep = make_expr(ExprKind::ge, {make_identifier("depth"), make_number("50")});
  mission.selections = {selection("Shallow", "dive", "slow", std::move(shallow), 1),
                        selection("Deep", "dive", "fast", std::move(deep), 2)};
  const verify::Coverage coverage = verified(mission, "dive");
  ASSERT_TRUE(coverage.measured) << coverage.not_measured_reason;
  EXPECT_EQ(coverage.gap_share.text, "65/256");
  const std::string svg = coverage_map_svg(mission, coverage);
  ASSERT_TRUE(well_formed_xml(svg));
  // x: depth 0..100 over 64..504 px; y: pressure 0..20 over 352..52 px.
  EXPECT_TRUE(has(svg, "<polygon points=\"64,277 284,277 284,108.25 64,202\" fill=\"url(#")) << svg;
  EXPECT_FALSE(has(svg, "<rect x=\"64\" y=\"108.25\" width=\"220\" height=\"168.75\""))
      << "the cell's bounding box paints states the assumption rules out";
}

TEST(CoverageMapSvg, BoundaryOverlapIsALine) {
  load::Mission mission = exploration_mission();
  mission.selections[0].guard =
      make_expr(ExprKind::le, {make_identifier("slope"), make_number("10")});
  mission.selections[1].guard =
      make_expr(ExprKind::ge, {make_identifier("slope"), make_number("10")});
  const auto coverage = verified(mission, "exploration");
  EXPECT_EQ(coverage.overlap_share.text, "0");
  const std::string svg = coverage_map_svg(mission, coverage);
  // slope = 10 has width 0: drawn as a line, not hidden.
  EXPECT_TRUE(
      has(svg, "<title>slope = 10: sand_alternative; two or more guards hold</title></line>"))
      << svg;
}

TEST(CoverageMapSvg, OnePanelPerEnumValue) {
  load::Mission mission = exploration_mission();
  fretish::Variable terrain = variable("terrain", fretish::VarType::enumeration);
  terrain.enum_values = {"sand", "rocks", "unknown"};
  mission.domain.variables.push_back(terrain);
  mission.selections[0].guard =
      make_expr(ExprKind::logical_and,
                {make_expr(ExprKind::eq, {make_identifier("terrain"), make_identifier("sand")}),
                 mission.selections[0].guard});
  const std::string svg = coverage_map_svg(mission, verified(mission, "exploration"));
  EXPECT_TRUE(has(svg, "one panel per value of terrain"));
  for (const char* panel :
       {">terrain = sand</text>", ">terrain = rocks</text>", ">terrain = unknown</text>"})
    EXPECT_TRUE(has(svg, panel)) << panel;
  EXPECT_TRUE(has(svg, "&amp; terrain = rocks: gap (no guard holds)"));
}

TEST(CoverageMapSvg, TinyGapIsWidenedAndLabelledWithItsExactShare) {
  load::Mission mission = exploration_mission();
  mission.selections[0].guard =
      make_expr(ExprKind::lt, {make_identifier("slope"), make_number("44.991")});
  mission.selections[1].guard =
      make_expr(ExprKind::ge, {make_identifier("battery"), make_number("200")});
  const auto coverage = verified(mission, "exploration");
  EXPECT_EQ(coverage.gap_share.text, "1/10000");
  const std::string svg = coverage_map_svg(mission, coverage);
  EXPECT_TRUE(has(svg, ">gap &lt;0.1% (1/10000)</text>")) << svg;
}

TEST(CoverageMapSvg, OneVariableGivesAStrip) {
  load::Mission mission = msl_mission(false);
  mission.selections.pop_back();
  const std::string svg = coverage_map_svg(mission, verified(mission, "navigation"));
  EXPECT_TRUE(has(svg, "<title>Selected alternative of navigation over OnDust</title>"));
}

}  // namespace
}  // namespace uabt::report
