// uabt's own output and the paper's generated tree conform to their missions.
#include <gtest/gtest.h>

#include "conform_test_util.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

struct Case {
  const char* mission;
  compile::SelectionStyle style;
};

class ShippedMission : public ::testing::TestWithParam<Case> {};

TEST_P(ShippedMission, CompiledOutputConformsWithoutFindings) {
  const load::Mission m = load_or_fail(mission_dir(GetParam().mission));
  ASSERT_FALSE(has_errors(m.findings)) << describe(m.findings);
  const bt::Document compiled = compile_or_fail(m, GetParam().style);
  const conform::Result r = conform::conform_tree(m, compiled);
  EXPECT_TRUE(r.findings.empty()) << describe(r.findings);
  EXPECT_GT(r.solver_queries, 0u);
}

TEST_P(ShippedMission, WrittenAndReadBackOutputConforms) {
  const load::Mission m = load_or_fail(mission_dir(GetParam().mission));
  const bt::Document compiled = compile_or_fail(m, GetParam().style);
  const bt::Document reread = parse_or_fail(bt::write_document(compiled));
  const conform::Result r = conform::conform_tree(m, reread);
  EXPECT_TRUE(r.findings.empty()) << describe(r.findings);
  for (const auto& f : r.findings) EXPECT_EQ(f.location.file, "compiled.xml");
}

INSTANTIATE_TEST_SUITE_P(
    AllStyles, ShippedMission,
    ::testing::Values(Case{"msl_curiosity", compile::SelectionStyle::sequence},
                      Case{"msl_curiosity", compile::SelectionStyle::reactive},
                      Case{"msl_curiosity_paper", compile::SelectionStyle::sequence},
                      Case{"msl_curiosity_paper", compile::SelectionStyle::reactive},
                      Case{"exploration", compile::SelectionStyle::sequence},
                      Case{"exploration", compile::SelectionStyle::reactive}),
    [](const auto& info) {
      return std::string(info.param.mission) +
             (info.param.style == compile::SelectionStyle::reactive ? "_reactive" : "_sequence");
    });

TEST(ShippedMission, V3OutputConforms) {
  const load::Mission m = load_or_fail(mission_dir("msl_curiosity"));
  const bt::Document compiled = compile_or_fail(m, compile::SelectionStyle::sequence, 3);
  bt::WriteOptions options;
  options.format = 3;
  const bt::Document reread = parse_or_fail(bt::write_document(compiled, options));
  EXPECT_EQ(reread.format, 3);
  const conform::Result r = conform::conform_tree(m, reread);
  EXPECT_TRUE(r.findings.empty()) << describe(r.findings);
}

TEST(ReplicationPackage, GeneratedTreeConforms) {
  const auto dir = replication_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no replication package";
  const load::Mission m = load_or_fail(dir);
  ASSERT_FALSE(has_errors(m.findings)) << describe(m.findings);
  std::vector<Finding> read_findings;
  auto doc = bt::read_document(dir / "output" / "concrete_mission.xml", {}, read_findings);
  ASSERT_TRUE(doc.has_value()) << describe(read_findings);
  EXPECT_EQ(doc->format, 3);
  const conform::Result r = conform::conform_tree(m, *doc);
  EXPECT_FALSE(has_errors(r.findings)) << describe(r.findings);
  EXPECT_TRUE(r.findings.empty()) << describe(r.findings);
}

}  // namespace
}  // namespace uabt::testing
