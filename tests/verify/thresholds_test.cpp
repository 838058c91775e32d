// Numeric and enum guards: thresholds, their edges, and enum partitions.
#include <gtest/gtest.h>

#include <algorithm>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

TEST(Thresholds, ComplementaryIntegerThresholdsNeitherOverlapNorLeaveAGap) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 20 Mission shall satisfy selected_alt = nav_to_base\n"
      "High: In exploration if battery >= 20 Mission shall satisfy selected_alt = explore\n",
      "integer battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty());
  const auto& cov = r.coverage.at(0);
  EXPECT_TRUE(cov.counted);
  EXPECT_EQ(cov.states, 101u);
  EXPECT_EQ(cov.alternatives.at(0).states, 20u);
  EXPECT_EQ(cov.alternatives.at(1).states, 81u);
  EXPECT_GE(r.statistics.prefiltered, 1u);  // the overlap pair needs no solver call
}

TEST(Thresholds, StrictThresholdsOnBothSidesMissExactlyTheEdge) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 20 Mission shall satisfy selected_alt = nav_to_base\n"
      "High: In exploration if battery > 20 Mission shall satisfy selected_alt = explore\n",
      "integer battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(gaps[0]->witness, (State{{"battery", Value::of_int(20)}}));
  EXPECT_EQ(r.coverage.at(0).gap_region, (std::vector<std::string>{"battery = 20"}));
  EXPECT_EQ(r.coverage.at(0).gap_states, 1u);
  EXPECT_TRUE(findings_of(r, "guard-overlap").empty());
}

TEST(Thresholds, IntervalGapIsRenderedAsAnInterval) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 20 Mission shall satisfy selected_alt = nav_to_base\n"
      "High: In exploration if battery > 60 Mission shall satisfy selected_alt = explore\n",
      "integer battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "guard-gap").size(), 1u);
  EXPECT_EQ(r.coverage.at(0).gap_region, (std::vector<std::string>{"battery in [20, 60]"}));
  EXPECT_EQ(r.coverage.at(0).gap_states, 41u);
}

TEST(Thresholds, RealThresholdsLeaveTheEdgePointUncovered) {
  const load::Mission m = make_mission(
      "Flat: In exploration if slope < 20 Mission shall satisfy selected_alt = sand_alternative\n"
      "Steep: In exploration if slope > 20 Mission shall satisfy selected_alt = "
      "rocks_alternative\n",
      "real slope in [-45, 45]\n");
  const verify::Result r = verify_checked(m);
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  const Value* slope = find_value(gaps[0]->witness, "slope");
  ASSERT_NE(slope, nullptr);
  EXPECT_EQ(slope->kind, Value::Kind::real);
  EXPECT_EQ(slope->text, "20");
  EXPECT_EQ(r.coverage.at(0).gap_region, (std::vector<std::string>{"slope = 20"}));
  EXPECT_FALSE(r.coverage.at(0).counted);
  EXPECT_NE(r.coverage.at(0).not_counted_reason.find("real"), std::string::npos);
  EXPECT_TRUE(r.coverage.at(0).alternatives.at(0).reachable);
}

TEST(Thresholds, ClosedRealThresholdsOverlapAtTheEdge) {
  const load::Mission m = make_mission(
      "Flat: In exploration if slope <= 20.5 Mission shall satisfy selected_alt = "
      "sand_alternative\n"
      "Steep: In exploration if slope >= 20.5 Mission shall satisfy selected_alt = "
      "rocks_alternative\n",
      "real slope in [-45, 45]\n");
  const verify::Result r = verify_checked(m);
  const auto overlaps = findings_of(r, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(find_value(overlaps[0]->witness, "slope")->text, "20.5");  // 41/2, as people write it
  EXPECT_TRUE(findings_of(r, "guard-gap").empty());
}

TEST(Thresholds, RealGapBetweenThresholdsIsAnOpenInterval) {
  const load::Mission m = make_mission(
      "Flat: In exploration if slope < -10 Mission shall satisfy selected_alt = sand_alternative\n"
      "Steep: In exploration if slope >= 0.5 Mission shall satisfy selected_alt = "
      "rocks_alternative\n",
      "real slope in [-45, 45]\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "guard-gap").size(), 1u);
  EXPECT_EQ(r.coverage.at(0).gap_region, (std::vector<std::string>{"slope in [-10, 0.5)"}));
}

// Describing an overlap costs the question that finds it, one that shrinks the witness's cube
// of atoms to what the overlap needs and one per literal of that; when the cube left is made of
// the two guards' own conjuncts it is the whole overlap, and whether more of it is left needs
// no question. (2,000 windows, each overlapping the next 5, ask 9,985 questions fewer.)
TEST(Thresholds, AnOverlapOfTwoWindowsIsDescribedWithoutAskingWhetherMoreIsLeft) {
  auto verify_windows = [](const std::string& second) {
    return verify_checked(make_mission(
        "A: In exploration if battery >= 10 & battery <= 40 Mission shall satisfy selected_alt "
        "= slow\n"
        "B: In exploration if " +
            second +
            " Mission shall satisfy selected_alt = fast\n"
            "Safe: In exploration Mission shall satisfy selected_alt = stop\n",
        "integer battery in [0, 100]\n"));
  };
  const verify::Result overlapping = verify_windows("battery >= 30 & battery <= 60");
  const verify::Result apart = verify_windows("battery >= 50 & battery <= 60");
  const auto overlaps = findings_of(overlapping, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_NE(std::find(overlaps[0]->notes.begin(), overlaps[0]->notes.end(),
                      "both hold: battery in [30, 40]"),
            overlaps[0]->notes.end());
  EXPECT_TRUE(findings_of(apart, "guard-overlap").empty());
  // Whether A and B meet, the witness's cube (all four atoms), one question per atom of it;
  // apart, the pair is ruled out without the solver. Everything else is asked alike.
  EXPECT_EQ(overlapping.statistics.solver_queries, apart.statistics.solver_queries + 6);
}

TEST(Enums, PartitionOfThreeOfFourLiteralsLeavesTheFourthUncovered) {
  const load::Mission m = make_mission(
      "R1: In navigation if terrain = dust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if terrain = rocks Mission shall satisfy selected_alt = on_rocks\n"
      "R3: In navigation if sand = terrain Mission shall satisfy selected_alt = on_sand\n",
      "enum terrain in {dust, rocks, sand, mud}\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(findings_of(r, "guard-overlap").empty());
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(gaps[0]->witness, (State{{"terrain", Value::of_enum("mud")}}));
  EXPECT_EQ(r.coverage.at(0).gap_region, (std::vector<std::string>{"terrain = mud"}));
  EXPECT_EQ(r.statistics.prefiltered >= 3, true);  // all three overlap pairs are disjoint
  EXPECT_EQ(r.coverage.at(0).states, 4u);
  EXPECT_EQ(r.coverage.at(0).gap_states, 1u);
}

TEST(Enums, InequalityGuardsOverlapOnTheOtherLiterals) {
  const load::Mission m = make_mission(
      "R1: In navigation if terrain != dust Mission shall satisfy selected_alt = careful\n"
      "R2: In navigation if terrain != rocks Mission shall satisfy selected_alt = fast\n",
      "enum terrain in {dust, rocks, sand}\n");
  const verify::Result r = verify_checked(m);
  const auto overlaps = findings_of(r, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(overlaps[0]->witness, (State{{"terrain", Value::of_enum("sand")}}));
  EXPECT_TRUE(findings_of(r, "guard-gap").empty());
}

TEST(Enums, GapRegionOverSeveralLiteralsIsASet) {
  const load::Mission m = make_mission(
      "R1: In navigation if terrain = dust Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if terrain = rocks & OnSlope Mission shall satisfy selected_alt = "
      "on_rocks\n",
      "enum terrain in {dust, rocks, sand, mud}\nboolean OnSlope\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "guard-gap").size(), 1u);
  const auto& region = r.coverage.at(0).gap_region;
  // The gap is terrain in {sand, mud} or (not dust and no slope): its two prime cubes, in
  // whatever order the solver finds them.
  const std::set<std::string> cubes(region.begin(), region.end());
  EXPECT_EQ(cubes, (std::set<std::string>{"terrain in {sand, mud}",
                                          "terrain in {rocks, sand, mud} & !OnSlope"}));
}

}  // namespace
}  // namespace uabt::testing
