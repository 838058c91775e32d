// The whole-tree checks as a user meets them: `uabt verify` on the shipped
// missions/blackboard_defects, in text and SARIF, and `uabt explain` for each check.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_support.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

TEST(WholeTreeCli, BlackboardDefectsFailsWithOneFindingOfEachCheck) {
  const CliRun run =
      run_uabt_in((source_dir() / "missions" / "blackboard_defects").string(), "verify .");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  for (const char* line : {
           "mission.xml:14:7: error: blackboard entry 'target_range' is read by the script "
           "`target_range < 20` of ScriptCondition before anything writes it, on a path of 8 "
           "ticks from the root",
           "mission.xml:9:11: note: IsTargetVisible fails\n",
           "mission.xml:12:9: note: Wait succeeds\n",
           "mission.xml:15:7: error: blackboard entry 'target_range' is used by port 'range' of "
           "ReportRange (int) and by port 'goal' of MoveTo (double): BehaviorTree.CPP refuses "
           "to mix the two types in one entry [bb-type-conflict]\n",
           "mission.xml:16:7: error: blackboard entry 'target_range' is used by port 'goal' of "
           "MoveTo (double) and by port 'range' of ReportRange (int)",
           "mission.xml:16:7: error: port 'speed' of MoveTo is \"fast\", which does not convert "
           "to its type double (nodes.xml): BehaviorTree.CPP's getInput() fails there "
           "[bb-literal-type]\n",
           "alternatives/sampling/drill.xml:6:7: warning: the condition `battery > 100` of "
           "Drill _skipIf is never true in the domain, so it never skips the node: because of "
           "battery in [0, 100] [script-decided]\n",
           "alternatives/sampling/scoop.xml:6:7: error: `arm_angle := 120` of Script assigns "
           "arm_angle the value 120, which is outside integer arm_angle in [0, 90] in every "
           "state of the domain [script-out-of-range]\n",
       })
    EXPECT_NE(run.out.find(line), std::string::npos) << line << "\n---\n" << run.out;
}

TEST(WholeTreeCli, SarifCarriesTheWitnessPathAsRelatedLocations) {
  const CliRun run =
      run_uabt_in(source_dir().string(), "verify missions/blackboard_defects --format sarif");
  EXPECT_EQ(run.exit_code, 1);
  const auto sarif = nlohmann::json::parse(run.out);
  int seen = 0;
  for (const auto& result : sarif["runs"][0]["results"]) {
    if (result["ruleId"] != "bb-read-before-write") continue;
    ++seen;
    const auto& related = result["relatedLocations"];
    ASSERT_EQ(related.size(), 8u);
    EXPECT_EQ(related[4]["message"]["text"], "IsTargetVisible fails");
    EXPECT_EQ(related[4]["physicalLocation"]["region"]["startLine"], 9);
    EXPECT_EQ(related[4]["physicalLocation"]["artifactLocation"]["uri"],
              "missions/blackboard_defects/mission.xml");
  }
  EXPECT_EQ(seen, 1);
}

TEST(WholeTreeCli, EveryWholeTreeCheckIsExplained) {
  for (const char* id : {"bb-read-before-write", "bb-type-conflict", "bb-literal-type",
                         "script-decided", "script-out-of-range"}) {
    const CliRun run = run_uabt_in(source_dir().string(), std::string("explain ") + id);
    EXPECT_EQ(run.exit_code, 0) << id;
    EXPECT_NE(run.out.find("## How to fix it"), std::string::npos) << id;
  }
}

}  // namespace
}  // namespace uabt::testing
