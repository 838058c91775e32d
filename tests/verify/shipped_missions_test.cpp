// The shipped missions (DESIGN §9) as the gate sees them, loaded from disk.
#include <gtest/gtest.h>

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
