// The paper's Mars Science Laboratory navigation node, as the paper states it and as uabt's
// shipped mission fixes it.
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

const char* const kPaperRequirements =
    "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
    "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n";

TEST(PaperCase, TwoGuardsWithoutDomainOverlapOnceAndLeaveOneGap) {
  const load::Mission m = make_mission(kPaperRequirements);
  const verify::Result r = verify_checked(m);
  const auto overlaps = findings_of(r, "guard-overlap");
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(overlaps.size(), 1u);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(r.findings.size(), 2u);

  const Finding& overlap = *overlaps[0];
  EXPECT_EQ(overlap.severity, Severity::error);
  EXPECT_EQ(overlap.adaptable, "navigation");
  EXPECT_EQ(overlap.requirements, (std::vector<std::string>{"Req1", "Req2"}));
  EXPECT_EQ(overlap.alternatives, (std::vector<std::string>{"on_dust", "on_rocks"}));
  EXPECT_EQ(overlap.message,
            "Req1 (on_dust) and Req2 (on_rocks) can both hold: the Fallback picks on_dust and "
            "on_rocks is never considered in this state");
  EXPECT_EQ(overlap.witness,
            (State{{"OnDust", Value::of_bool(true)}, {"OnRocks", Value::of_bool(true)}}));
  EXPECT_EQ(overlap.location.file, "requirements.fret");
  EXPECT_EQ(overlap.location.line, 2);

  const Finding& gap = *gaps[0];
  EXPECT_EQ(gap.witness,
            (State{{"OnDust", Value::of_bool(false)}, {"OnRocks", Value::of_bool(false)}}));
  ASSERT_EQ(r.coverage.size(), 1u);
  EXPECT_EQ(r.coverage[0].gap_region, (std::vector<std::string>{"!OnDust & !OnRocks"}));

  const verify::Coverage& cov = r.coverage[0];
  EXPECT_TRUE(cov.counted);
  EXPECT_EQ(cov.states, 4u);
  EXPECT_EQ(cov.gap_states, 1u);
  EXPECT_EQ(cov.overlap_states, 1u);
  ASSERT_EQ(cov.alternatives.size(), 2u);
  EXPECT_EQ(cov.alternatives[0].states, 2u);
  EXPECT_EQ(cov.alternatives[1].states, 1u);
  EXPECT_EQ(cov.alternatives[1].enabled_states, 2u);
  EXPECT_TRUE(cov.alternatives[0].reachable);
  EXPECT_TRUE(cov.alternatives[1].reachable);
  RecordProperty("solver_queries", static_cast<int>(r.statistics.solver_queries));
  RecordProperty("prefiltered", static_cast<int>(r.statistics.prefiltered));
  std::cout << "paper case: " << r.statistics.solver_queries << " solver queries, "
            << r.statistics.prefiltered << " pre-filtered\n";
}

TEST(PaperCase, AllowOverlapMakesTheOverlapAWarning) {
  verify::Options options;
  options.allow_overlap = true;
  const verify::Result r = verify_checked(make_mission(kPaperRequirements), options);
  const auto overlaps = findings_of(r, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(overlaps[0]->severity, Severity::warning);
}

TEST(PaperCase, OneTerrainAssumptionAndSafeDefaultLeaveNothingToReport) {
  const load::Mission m =
      make_mission(std::string(kPaperRequirements) +
                       "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n",
                   "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().check << ": " << r.findings.front().message;
  const verify::Coverage& cov = r.coverage.at(0);
  EXPECT_TRUE(cov.counted);
  EXPECT_EQ(cov.states, 3u);
  EXPECT_EQ(cov.gap_states, 0u);
  EXPECT_EQ(cov.overlap_states, 0u);
  EXPECT_EQ(cov.alternatives.at(2).name, "hold_position");
  EXPECT_EQ(cov.alternatives.at(2).states, 1u);
  EXPECT_TRUE(cov.alternatives.at(2).reachable);
  std::cout << "paper case fixed: " << r.statistics.solver_queries << " solver queries, "
            << r.statistics.prefiltered << " pre-filtered\n";
}

TEST(PaperCase, AssumptionAloneRemovesTheOverlapButNotTheGap) {
  const load::Mission m = make_mission(
      kPaperRequirements, "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(findings_of(r, "guard-overlap").empty());
  EXPECT_EQ(findings_of(r, "guard-gap").size(), 1u);
}

TEST(PaperCase, DefaultAloneRemovesTheGapButNotTheOverlap) {
  const load::Mission m =
      make_mission(std::string(kPaperRequirements) +
                   "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  const verify::Result r = verify_checked(m);
  EXPECT_EQ(findings_of(r, "guard-overlap").size(), 1u);
  EXPECT_TRUE(findings_of(r, "guard-gap").empty());
}

}  // namespace
}  // namespace uabt::testing
