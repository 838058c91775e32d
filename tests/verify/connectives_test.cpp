// Guards built with unless, xor, -> chains, <-> and ite: the verdicts follow FRET's meaning.
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

TEST(Connectives, UnlessIsTheComplementOfIf) {
  const load::Mission m = make_mission(
      "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation unless OnDust Mission shall satisfy selected_alt = on_rocks\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().message;
  EXPECT_EQ(r.coverage.at(0).gap_states, 0u);
  EXPECT_EQ(r.coverage.at(0).overlap_states, 0u);
}

TEST(Connectives, UnlessOverlapsTheGuardItDoesNotNegate) {
  const load::Mission m = make_mission(
      "R1: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
      "R2: In navigation unless OnDust Mission shall satisfy selected_alt = careful\n");
  const verify::Result r = verify_checked(m);
  const auto overlaps = findings_of(r, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(*find_value(overlaps[0]->witness, "OnRocks"), Value::of_bool(true));
  EXPECT_EQ(*find_value(overlaps[0]->witness, "OnDust"), Value::of_bool(false));
  ASSERT_EQ(findings_of(r, "guard-gap").size(), 1u);
  EXPECT_EQ(r.coverage.at(0).gap_region, (std::vector<std::string>{"!OnRocks & OnDust"}));
}

TEST(Connectives, XorBothAndNeitherPartitionTwoBooleans) {
  const load::Mission m = make_mission(
      "One: In navigation if OnDust xor OnRocks Mission shall satisfy selected_alt = one\n"
      "Both: In navigation if OnDust & OnRocks Mission shall satisfy selected_alt = both\n"
      "None: In navigation if !OnDust & !OnRocks Mission shall satisfy selected_alt = none\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().message;
  const auto& cov = r.coverage.at(0);
  EXPECT_EQ(cov.alternatives.at(0).states, 2u);
  EXPECT_EQ(cov.alternatives.at(1).states, 1u);
  EXPECT_EQ(cov.alternatives.at(2).states, 1u);
}

TEST(Connectives, ImplicationChainsAreRightAssociative) {
  // a -> b -> c is a -> (b -> c): false exactly when a & b & !c, which the second guard covers.
  // Read left-associatively it would leave !a & !c uncovered.
  const load::Mission m = make_mission(
      "R1: In navigation if A -> B -> C Mission shall satisfy selected_alt = x\n"
      "R2: In navigation if A & B & !C Mission shall satisfy selected_alt = y\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().message;
  EXPECT_EQ(r.coverage.at(0).alternatives.at(0).states, 7u);
}

TEST(Connectives, IffAndBooleanEqualityMeanTheSame) {
  const load::Mission m = make_mission(
      "R1: In navigation if A <-> B Mission shall satisfy selected_alt = x\n"
      "R2: In navigation if A != B Mission shall satisfy selected_alt = y\n"
      "R3: In navigation if (A = B) & C Mission shall satisfy selected_alt = z\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(findings_of(r, "guard-gap").empty());
  const auto shadowed = findings_of(r, "guard-shadowed");
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(shadowed[0]->requirements, (std::vector<std::string>{"R3", "R1"}));
}

TEST(Connectives, IteAndArithmeticFunctions) {
  const load::Mission m = make_mission(
      "R1: In exploration if absInt(battery - 50) <= 10 Mission shall satisfy selected_alt = mid\n"
      "R2: In exploration if maxInt(battery, 70) = battery Mission shall satisfy selected_alt = "
      "high\n"
      "R3: In exploration if ite(OnRocks, battery < 40, battery < 30) Mission shall satisfy "
      "selected_alt = low\n",
      "integer battery in [0, 100]\nboolean OnRocks\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(findings_of(r, "guard-overlap").empty());
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  // Uncovered: battery in [30, 39] without rocks, [40, 69] except [40, 60], i.e. [61, 69].
  const auto& cov = r.coverage.at(0);
  EXPECT_TRUE(cov.counted);
  EXPECT_EQ(cov.states, 202u);
  EXPECT_EQ(cov.gap_states, 10u + 2u * 9u);
}

}  // namespace
}  // namespace uabt::testing
