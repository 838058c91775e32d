#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "gate/load_support.hpp"
#include "report/impact.hpp"
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
  auto mission = [](const std::string& threshold) {
    return std::map<std::string, std::string>{
        {"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
        {"domain.fret", "integer battery in [0, 100]\n"},
        {"requirements.fret", "Low: In nav if battery < " + threshold +
                                  " Mission shall satisfy selected_alt = a\n"
                                  "D: In nav Mission shall satisfy selected_alt = b\n"},
        {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
        {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")}};
  };
  uabt::testing::TempMission old_version(mission("20"), "old");
  uabt::testing::TempMission new_version(mission("30"), "new");
  Impact impact = selection_impact(load(old_version.dir()), load(new_version.dir()), {});
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

}  // namespace
}  // namespace uabt::verify
