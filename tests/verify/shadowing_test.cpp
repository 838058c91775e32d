// guard-unsatisfiable and guard-shadowed, with minimal hiding sets.
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

TEST(Shadowing, ASpecialCaseBelowTheGeneralCaseIsShadowedByIt) {
  const load::Mission m = make_mission(
      "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if OnDust & OnRocks Mission shall satisfy selected_alt = careful\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  const verify::Result r = verify_checked(m);
  const auto shadowed = findings_of(r, "guard-shadowed");
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(shadowed[0]->requirements, (std::vector<std::string>{"R2", "R1"}));
  EXPECT_EQ(shadowed[0]->alternatives, (std::vector<std::string>{"careful", "on_dust"}));
  EXPECT_EQ(shadowed[0]->message,
            "R2 (careful) is never selected: whenever its guard holds, R1 (on_dust) holds too "
            "and comes first");
  EXPECT_EQ(shadowed[0]->location.line, 2);
  EXPECT_FALSE(r.coverage.at(0).alternatives.at(1).reachable);
  EXPECT_EQ(r.coverage.at(0).alternatives.at(1).states, 0u);
  EXPECT_EQ(r.coverage.at(0).alternatives.at(1).enabled_states, 1u);
  EXPECT_TRUE(findings_of(r, "guard-unsatisfiable").empty());
}

TEST(Shadowing, NamesTheMinimalSetOfHidersTwoOutOfThree) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 50 Mission shall satisfy selected_alt = slow\n"
      "Dust: In exploration if OnDust Mission shall satisfy selected_alt = dusty\n"
      "High: In exploration if battery >= 50 Mission shall satisfy selected_alt = fast\n"
      "Mid: In exploration if battery > 10 & battery < 90 Mission shall satisfy selected_alt = "
      "medium\n",
      "integer battery in [0, 100]\nboolean OnDust\n");
  const verify::Result r = verify_checked(m);
  const auto shadowed = findings_of(r, "guard-shadowed");
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(shadowed[0]->requirements, (std::vector<std::string>{"Mid", "Low", "High"}));
  EXPECT_EQ(shadowed[0]->alternatives, (std::vector<std::string>{"medium", "slow", "fast"}));
  EXPECT_NE(shadowed[0]->message.find("Low (slow) or High (fast)"), std::string::npos);
}

TEST(Shadowing, ShadowedOnlyTogetherWithAnAssumption) {
  // Without the assumption some state (OnDust and OnRocks both false, OnSand true) selects R3.
  const std::string reqs =
      "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
      "R3: In navigation if OnSand Mission shall satisfy selected_alt = on_sand\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  EXPECT_TRUE(findings_of(verify_checked(make_mission(reqs)), "guard-shadowed").empty());
  const load::Mission m = make_mission(
      reqs,
      "boolean OnDust, OnRocks, OnSand\nassume sand_is_rocky: OnSand -> (OnRocks | OnDust)\n");
  const verify::Result r = verify_checked(m);
  const auto shadowed = findings_of(r, "guard-shadowed");
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(shadowed[0]->requirements, (std::vector<std::string>{"R3", "R1", "R2"}));
}

TEST(Shadowing, DisjointEarlierGuardsAreNotAskedAbout) {
  const load::Mission m = make_mission(
      "R1: In navigation if terrain = dust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if terrain = rocks Mission shall satisfy selected_alt = on_rocks\n"
      "R3: In navigation if terrain = sand Mission shall satisfy selected_alt = on_sand\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n",
      "enum terrain in {dust, rocks, sand, mud}\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty());
  // 3 pairs disjoint for shadowing + 3 for overlap + the gap (default) at least.
  EXPECT_GE(r.statistics.prefiltered, 7u);
  EXPECT_EQ(r.coverage.at(0).alternatives.at(3).states, 1u);
}

TEST(Shadowing, ADefaultCoveredByTheGuardsIsASafetyNetNotAFinding) {
  const load::Mission m = make_mission(
      "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if !OnDust Mission shall satisfy selected_alt = on_rocks\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty());
  EXPECT_FALSE(r.coverage.at(0).alternatives.at(2).reachable);
  EXPECT_EQ(r.coverage.at(0).alternatives.at(2).states, 0u);
}

TEST(Unsatisfiable, ContradictoryThresholds) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 20 & battery > 30 Mission shall satisfy selected_alt = "
      "nav_to_base\n"
      "Safe: In exploration Mission shall satisfy selected_alt = explore\n",
      "integer battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  const auto unsat = findings_of(r, "guard-unsatisfiable");
  ASSERT_EQ(unsat.size(), 1u);
  EXPECT_EQ(unsat[0]->requirements, (std::vector<std::string>{"Low"}));
  EXPECT_TRUE(unsat[0]->witness.empty());
  EXPECT_EQ(r.findings.size(), 1u);  // no vacuity or overlap noise about a dead guard
  EXPECT_FALSE(r.coverage.at(0).alternatives.at(0).reachable);
}

TEST(Unsatisfiable, ThresholdOutsideTheDeclaredRange) {
  const load::Mission m = make_mission(
      "Over: In exploration if battery > 100 Mission shall satisfy selected_alt = nav_to_base\n"
      "Safe: In exploration Mission shall satisfy selected_alt = explore\n",
      "integer battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "guard-unsatisfiable").size(), 1u);
  EXPECT_NE(findings_of(r, "guard-unsatisfiable")[0]->message.find("under the domain"),
            std::string::npos);
}

TEST(Unsatisfiable, RuledOutByAnAssumption) {
  const load::Mission m = make_mission(
      "Both: In navigation if OnDust & OnRocks Mission shall satisfy selected_alt = careful\n"
      "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n",
      "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "guard-unsatisfiable").size(), 1u);
  EXPECT_TRUE(findings_of(r, "guard-overlap").empty());
  EXPECT_TRUE(findings_of(r, "guard-shadowed").empty());
}

TEST(Unsatisfiable, SatisfiableGuardIsNotReported) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 20 & battery > 10 Mission shall satisfy selected_alt = "
      "nav_to_base\n"
      "Safe: In exploration Mission shall satisfy selected_alt = explore\n",
      "integer battery in [0, 100]\n");
  EXPECT_TRUE(verify_checked(m).findings.empty());
}

}  // namespace
}  // namespace uabt::testing
