#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"
#include "gate/load_support.hpp"
#include "report/impact.hpp"
#include "report/uplink_sections.hpp"
#include "smt/evaluate.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"
#include "verify/impact.hpp"

namespace uabt::verify {
namespace {

load::Mission load(const std::filesystem::path& dir,
                   std::vector<std::filesystem::path> uplinks = {}) {
  load::Mission m = uabt::testing::load_merged(dir, std::move(uplinks));
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  return m;
}

const SelectionChange* find_change(const NodeImpact& n, const std::string& from,
                                   const std::string& to) {
  for (const auto& c : n.changes)
    if (c.from == from && c.to == to) return &c;
  return nullptr;
}

TEST(Impact, MudUplinkMovesOnlyMudStatesFromHoldPositionToOnMud) {
  const auto dir = uabt::testing::mission_dir("msl_curiosity");
  load::Mission before = load(dir);
  load::Mission after = load(dir, {dir / "uplinks" / "on_mud"});
  Impact impact = selection_impact(before, after, {});
  EXPECT_TRUE(impact.findings.empty()) << format_text(impact.findings);
  ASSERT_EQ(impact.nodes.size(), 1u);
  const NodeImpact& n = impact.nodes[0];
  EXPECT_EQ(n.status, "changed");
  ASSERT_EQ(n.changes.size(), 1u) << report::impact_text(impact);
  const SelectionChange* c = find_change(n, "hold_position", "on_mud");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->to_requirement, "Req3");
  ASSERT_TRUE(n.counted);
  // OnDust, OnRocks, OnMud with "one terrain" and "mud alone": 4 states, one of them mud.
  EXPECT_EQ(n.states, 4u);
  EXPECT_EQ(n.changed_states, 1u);
  EXPECT_EQ(c->states, 1u);
  const Value* mud = find_value(c->example, "OnMud");
  ASSERT_NE(mud, nullptr);
  EXPECT_TRUE(mud->boolean);
  EXPECT_TRUE(smt::satisfies_domain(after.domain, c->example));
}

TEST(Impact, SameMissionIsUnchanged) {
  const auto dir = uabt::testing::mission_dir("exploration");
  Impact impact = selection_impact(load(dir), load(dir), {});
  ASSERT_EQ(impact.nodes.size(), 1u);
  EXPECT_EQ(impact.nodes[0].status, "unchanged");
  EXPECT_TRUE(impact.nodes[0].changes.empty());
}

TEST(Impact, ThresholdChangeOnIntegersIsCountedExactly) {
  auto requirements = [](const std::string& threshold) {
    return "Low: In nav if battery < " + threshold +
           " Mission shall satisfy selected_alt = a\n"
           "D: In nav Mission shall satisfy selected_alt = b\n";
  };
  const uabt::testing::TwoVersions v("nav", "integer battery in [0, 100]\n", requirements("20"),
                                     requirements("30"), {"a", "b"});
  Impact impact = selection_impact(load(v.old_version.dir()), load(v.new_version.dir()), {});
  ASSERT_EQ(impact.nodes.size(), 1u);
  const NodeImpact& n = impact.nodes[0];
  ASSERT_TRUE(n.counted);
  EXPECT_EQ(n.states, 101u);
  EXPECT_EQ(n.changed_states, 10u) << "battery 20..29";
  const SelectionChange* c = find_change(n, "b", "a");
  ASSERT_NE(c, nullptr) << report::impact_text(impact);
  const Value* battery = find_value(c->example, "battery");
  ASSERT_NE(battery, nullptr);
  EXPECT_GE(battery->integer, 20);
  EXPECT_LE(battery->integer, 29);
  EXPECT_EQ(find_change(n, "a", "b"), nullptr);
}

// A node `nav` that selects `slow` when `guard` holds and `fast` otherwise.
std::string windy_calm(const std::string& guard) {
  return "Windy: In nav if " + guard +
         " Mission shall satisfy selected_alt = slow\n"
         "Calm: In nav Mission shall satisfy selected_alt = fast\n";
}

// The impact of changing that guard.
Impact nav_impact(const std::string& domain, const std::string& old_guard,
                  const std::string& new_guard) {
  const uabt::testing::TwoVersions v("nav", domain, windy_calm(old_guard), windy_calm(new_guard),
                                     {"fast", "slow"});
  return selection_impact(load(v.old_version.dir()), load(v.new_version.dir()), {});
}

// The text of `uabt diff` up to the example state, which the solver picks.
std::string text_before_example(const Impact& impact) {
  const std::string text = report::impact_text(impact);
  return text.substr(0, text.find("    e.g. "));
}

double example_number(const nlohmann::json& change, const std::string& name) {
  return change["example"][name].get<double>();
}

TEST(Impact, AMovedRealBoundaryChangesAnExactShareOfTheSpace) {
  const Impact impact = nav_impact("real wind in [0, 10]\n", "wind > 6", "wind > 4");
  EXPECT_TRUE(impact.findings.empty()) << format_text(impact.findings);
  // (4, 6] of [0, 10] moves from fast to slow: exactly a fifth of the space.
  EXPECT_EQ(text_before_example(impact),
            "nav: changed (20.0% of the space changes its alternative)\n"
            "  fast (Calm) -> slow (Windy): 20.0% of the space\n");
  const auto json = nlohmann::json::parse(report::impact_json(impact));
  const auto& node = json["nodes"][0];
  EXPECT_EQ(node["counted"], false);
  EXPECT_TRUE(node["states"].is_null());
  EXPECT_TRUE(node["changed_states"].is_null());
  EXPECT_EQ(node["changed_share"], 0.2) << node.dump();
  EXPECT_EQ(node["changed_share_exact"], "1/5");
  EXPECT_EQ(node["not_counted_reason"], "the guards range over the real variable wind");
  ASSERT_EQ(node["changes"].size(), 1u) << node.dump();
  const auto& change = node["changes"][0];
  EXPECT_EQ(change["from"], "fast");
  EXPECT_EQ(change["to"], "slow");
  EXPECT_TRUE(change["states"].is_null());
  EXPECT_EQ(change["share"], 0.2);
  EXPECT_EQ(change["share_exact"], "1/5");
  EXPECT_GT(example_number(change, "wind"), 4);
  EXPECT_LE(example_number(change, "wind"), 6);
}

TEST(Impact, AChangeInOneEnumValueGivesTheExactMixedShare) {
  // Only at night, and only for wind in (2, 6]: 4 of 2 x 12.
  const Impact impact = nav_impact("enum light in {day, night}\nreal wind in [0, 12]\n", "wind > 6",
                                   "wind > 6 | light = night & wind > 2");
  EXPECT_EQ(text_before_example(impact),
            "nav: changed (16.7% (1/6) of the space changes its alternative)\n"
            "  fast (Calm) -> slow (Windy): 16.7% (1/6) of the space\n");
  const auto json = nlohmann::json::parse(report::impact_json(impact));
  const auto& node = json["nodes"][0];
  EXPECT_EQ(node["changed_share_exact"], "1/6") << node.dump();
  EXPECT_DOUBLE_EQ(node["changed_share"].get<double>(), 1.0 / 6);
  ASSERT_EQ(node["changes"].size(), 1u);
  EXPECT_EQ(node["changes"][0]["share_exact"], "1/6");
  EXPECT_EQ(node["changes"][0]["example"]["light"], "night");
}

TEST(Impact, AnAssumptionThatNarrowsTheRealRangeIsTheDenominator) {
  // The same move as above, (4, 6], now of [0, 8].
  const Impact impact =
      nav_impact("real wind in [0, 10]\nassume calm: wind <= 8\n", "wind > 6", "wind > 4");
  EXPECT_EQ(text_before_example(impact),
            "nav: changed (25.0% of the space changes its alternative)\n"
            "  fast (Calm) -> slow (Windy): 25.0% of the space\n");
  const auto json = nlohmann::json::parse(report::impact_json(impact));
  EXPECT_EQ(json["nodes"][0]["changed_share_exact"], "1/4");
  EXPECT_EQ(json["nodes"][0]["changed_share"], 0.25);
}

TEST(Impact, AShareOfTheWholeSpaceIsAJsonInteger) {
  // Every wind moves: the share is 1, written as the integer it is.
  const Impact impact = nav_impact("real wind in [0, 10]\n", "wind > 20", "wind >= 0");
  const std::string json = report::impact_json(impact);
  EXPECT_NE(json.find("\"changed_share\": 1,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"changed_share_exact\": \"1\","), std::string::npos) << json;
  EXPECT_EQ(text_before_example(impact),
            "nav: changed (100% of the space changes its alternative)\n"
            "  fast (Calm) -> slow (Windy): 100% of the space\n");
}

TEST(Impact, WhatTheSpaceCannotMeasureSaysWhy) {
  const Impact impact =
      nav_impact("real wind in [0, 10]\n", "wind * wind > 36", "wind * wind > 16");
  ASSERT_EQ(impact.nodes.size(), 1u);
  EXPECT_EQ(text_before_example(impact),
            "nav: changed (states not counted: the atom `wind * wind > 36` is not linear)\n"
            "  fast (Calm) -> slow (Windy)\n");
  const auto json = nlohmann::json::parse(report::impact_json(impact));
  EXPECT_TRUE(json["nodes"][0]["changed_share"].is_null());
  EXPECT_TRUE(json["nodes"][0]["changes"][0]["share"].is_null());
}

TEST(Impact, TheUplinkReportSaysAMeasuredShareAsTheCoverageSectionDoes) {
  const Impact impact = nav_impact("real wind in [0, 10]\n", "wind > 6", "wind > 4");
  const std::string markdown = report::detail::uplink_markdown({"u", {}, impact, {}});
  EXPECT_NE(markdown.find("- `nav`: 20.0% of the space changes its alternative\n"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| `fast` | `slow` | 20.0% of the space | `wind="), std::string::npos)
      << markdown;
  const std::string html = report::detail::uplink_html({"u", {}, impact, {}});
  EXPECT_NE(html.find("<code>nav</code>: 20.0% of the space changes its alternative</p>"),
            std::string::npos)
      << html;
  const auto findings = report::behaviour_change_findings(impact, load::Mission{});
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].message, "nav: 20.0% of the space changes its alternative");
  ASSERT_EQ(findings[0].notes.size(), 1u);
  EXPECT_EQ(findings[0].notes[0].rfind("fast (Calm) -> slow (Windy): 20.0% of the space, e.g. "
                                       "wind=",
                                       0),
            0u)
      << findings[0].notes[0];
}

}  // namespace
}  // namespace uabt::verify
