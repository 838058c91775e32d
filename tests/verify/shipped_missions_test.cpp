// The shipped missions (ARCHITECTURE §9) as the gate sees them, loaded from disk.
#include <gtest/gtest.h>

#include <algorithm>

#include "test_support.hpp"
#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

load::Mission load(const std::string& name) {
  std::string error;
  auto m = load::load_mission(mission_dir(name), {}, error);
  if (!m) throw std::runtime_error(name + ": " + error);
  return std::move(*m);
}

TEST(ShippedMissions, PaperMissionFailsWithTheOverlapAndTheGap) {
  const load::Mission m = load("msl_curiosity_paper");
  const verify::Result r = verify_checked(m);
  EXPECT_EQ(findings_of(r, "guard-overlap").size(), 1u);
  EXPECT_EQ(findings_of(r, "guard-gap").size(), 1u);
  EXPECT_TRUE(has_errors(r.findings));
}

TEST(ShippedMissions, CuriosityMissionPasses) {
  const load::Mission m = load("msl_curiosity");
  const verify::Result r = verify_checked(m);
  EXPECT_FALSE(has_errors(r.findings)) << r.findings.front().message;
  ASSERT_FALSE(r.coverage.empty());
  EXPECT_TRUE(r.coverage[0].counted);
  EXPECT_EQ(r.coverage[0].gap_states, 0u);
}

TEST(ShippedMissions, ExplorationMissionPassesAndIsNotCountedOverReals) {
  const load::Mission m = load("exploration");
  const verify::Result r = verify_checked(m);
  EXPECT_FALSE(has_errors(r.findings)) << r.findings.front().message;
  ASSERT_FALSE(r.coverage.empty());
  EXPECT_FALSE(r.coverage[0].counted);
  for (const auto& a : r.coverage[0].alternatives) EXPECT_TRUE(a.reachable) << a.requirement;
  for (const auto& f : r.findings) std::cout << f.check << ": " << f.message << "\n";
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

TEST(ShippedMissions, PlanetaryLandingPartitionsItsSpaceExactly) {
  std::string error;
  const load::Mission m = load::load_mission(mission_dir("planetary_landing"), {}, error).value();
  const verify::Result r = verify_checked(m);
  EXPECT_FALSE(has_errors(r.findings));
  const auto& c = r.coverage.at(0);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  // wind [0, 40] x 101 batteries x 4 terrains; Nominal: flat, wind < 15, battery 11..100.
  EXPECT_EQ(c.measure.text, "16160");
  EXPECT_EQ(c.alternatives[0].share.text, "135/1616");  // 15 * 90 / 16160
  EXPECT_EQ(c.alternatives[1].share.text, "405/1616");  // 3 terrains
  EXPECT_EQ(c.alternatives[2].share.text, "225/404");   // 25 * 90 * 4 / 16160
  EXPECT_EQ(c.alternatives[3].share.text, "11/101");    // batteries 0..10
  EXPECT_EQ(c.gap_share.text, "0");
  EXPECT_EQ(c.overlap_share.text, "0");
  EXPECT_TRUE(c.gap_regions.empty());
  EXPECT_TRUE(c.overlap_regions.empty());
}

TEST(ShippedMissions, UnsafeLandingListsTheBoundaryOverlapAndBothGaps) {
  std::string error;
  const load::Mission m =
      load::load_mission(mission_dir("planetary_landing_unsafe"), {}, error).value();
  const verify::Result r = verify_checked(m);
  const auto& c = r.coverage.at(0);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(c.overlap_share.text, "0");
  ASSERT_EQ(c.overlap_regions.size(), 1u);
  EXPECT_EQ(c.overlap_regions[0].text(), "wind = 15 & battery in [11, 100] & terrain = flat");
  EXPECT_EQ(c.overlap_regions[0].requirements, (std::vector<std::string>{"Nominal", "Hover"}));
  // battery = 10 (1/101) and wind in (39.96, 40] for batteries 10..100 (0.04/40 * 91/101).
  EXPECT_EQ(c.gap_share.text, "109/10100");
  std::vector<std::string> gaps;
  for (const auto& g : c.gap_regions) gaps.push_back(g.text() + " : " + g.share.text);
  std::sort(gaps.begin(), gaps.end());
  EXPECT_EQ(gaps,
            (std::vector<std::string>{"battery = 10 : 1/101",
                                      "wind in (39.96, 40] & battery in [10, 100] : 91/101000"}));
}

}  // namespace
}  // namespace uabt::testing
