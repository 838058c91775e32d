// The benchmark families (tests/bench/prove_families.*) at small sizes: the generated missions
// load, pass the gate and get the verdicts the families promise, so the generator cannot rot.
#include "bench/prove_families.hpp"
#include "prove_support.hpp"

namespace uabt::testing {
namespace {

void expect_answers(const bench::FamilyMission& family) {
  ASSERT_TRUE(std::filesystem::exists(family.dir / "mission.xml"));
  const prove::Result r = prove_dir(family.dir);
  EXPECT_TRUE(r.complete);
  ASSERT_EQ(r.answers.size(), family.verdicts.size());
  for (const prove::Answer& a : r.answers) {
    EXPECT_EQ(prove::verdict_name(a.verdict), family.verdicts.at(a.requirement)) << a.requirement;
    if (family.violation_ticks.count(a.requirement)) {
      EXPECT_EQ(a.depth, family.violation_ticks.at(a.requirement)) << a.requirement;
      ASSERT_TRUE(a.counterexample);
    }
  }
}

TEST(ProveFamilies, BinaryTreeOf23Nodes) {
  TempMission scratch({});
  const auto family = bench::generate_binary_tree(scratch.dir() / "binary", 23, 2);
  EXPECT_EQ(family.tree_nodes, 24);
  const std::string xml = read_all(family.dir / "mission.xml");
  // 11 Fallbacks, 12 leaves: 6 checks and 6 actions.
  std::size_t fallbacks = 0, checks = 0;
  for (auto at = xml.find("<Fallback>"); at != std::string::npos;
       at = xml.find("<Fallback>", at + 1))
    ++fallbacks;
  for (auto at = xml.find("<ScriptCondition"); at != std::string::npos;
       at = xml.find("<ScriptCondition", at + 1))
    ++checks;
  EXPECT_EQ(fallbacks, 11u);
  EXPECT_EQ(checks, 6u);
  expect_answers(family);
}

TEST(ProveFamilies, BinaryTreeWithThreeCounters) {
  TempMission scratch({});
  expect_answers(bench::generate_binary_tree(scratch.dir() / "binary", 71, 3));
}

TEST(ProveFamilies, ChecklistOfFive) {
  TempMission scratch({});
  const auto family = bench::generate_checklist(scratch.dir() / "checklist", 5);
  EXPECT_EQ(family.tree_nodes, 19);
  expect_answers(family);
}

TEST(ProveFamilies, BadSizesAreRefused) {
  TempMission scratch({});
  EXPECT_THROW(bench::generate_binary_tree(scratch.dir() / "b", 24), std::invalid_argument);
  EXPECT_THROW(bench::generate_checklist(scratch.dir() / "c", 0), std::invalid_argument);
}

}  // namespace
}  // namespace uabt::testing
