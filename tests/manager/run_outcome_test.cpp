// How a run ends: a script error stops it (verdict error), max_ticks always ends it (verdict
// timeout), the outcome is printed once; and what --trace-level nodes adds.
#include <gtest/gtest.h>

#include "manager/manager.hpp"
#include "test_support.hpp"

namespace uabt::manager {
namespace {

using namespace uabt::runtime;  // the scenarios and traces the manager runs on

ManagerRun run_mission(const std::string& mission, const std::string& scenario_json,
                       ManagerOptions options = {}) {
  BehaviorTreeManager manager(uabt::testing::mission_dir(mission),
                              parse_scenario(scenario_json, "scenario.json"), options);
  return manager.run();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(RunOutcome, AScenarioThatNeverSetsBatteryStopsWithAScriptError) {
  // exploration's root Fallback first checks `battery < 20`: BT.CPP throws "Variable not
  // found: battery"; the run must not fall through to the exploration branch.
  const ManagerRun run =
      run_mission("exploration", R"({"initial": {"terrain": "sand", "slope": 3}})");
  EXPECT_EQ(run.verdict, "error");
  EXPECT_FALSE(run.finished);
  ASSERT_TRUE(run.error.has_value());
  EXPECT_EQ(run.error->tick, 1u);
  EXPECT_EQ(run.error->path, "MainTree/Fallback/Sequence[0]/ScriptCondition[0]");
  EXPECT_EQ(run.error->script, "battery < 20");
  EXPECT_NE(run.error->message.find("undefined blackboard key 'battery'"), std::string::npos);
  // The place in mission.xml the user wrote, not in the compiled tree held in memory.
  EXPECT_EQ(run.error->message.rfind("mission.xml:8:9: ScriptCondition: ", 0), 0u)
      << run.error->message;
  const std::string summary = trace_summary(run);
  EXPECT_EQ(summary.find("selects"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("mission success"), std::string::npos) << summary;
  EXPECT_NE(summary.find("mission error"), std::string::npos) << summary;
  const std::string lines = trace_json_lines(run.trace);
  EXPECT_NE(
      lines.find(R"("event":"error","node":"MainTree/Fallback/Sequence[0]/ScriptCondition[0]")"),
      std::string::npos)
      << lines;
  EXPECT_NE(lines.find(R"("script":"battery < 20")"), std::string::npos);
  EXPECT_NE(lines.find(R"("event":"done","verdict":"error")"), std::string::npos);
}

TEST(RunOutcome, AGuardReadingAnUnsetKeyPointsAtItsRequirement) {
  const ManagerRun run =
      run_mission("exploration", R"({"initial": {"battery": 90, "terrain": "sand"}})");
  ASSERT_TRUE(run.error.has_value());
  EXPECT_EQ(run.error->message.rfind("requirements.fret:3:", 0), 0u) << run.error->message;
  EXPECT_NE(run.error->message.find("undefined blackboard key 'slope'"), std::string::npos);
  EXPECT_EQ(run.error->path.rfind("MainTree/Fallback/Sequence[1]/SubTree[1]/exploration/", 0), 0u)
      << run.error->path;
}

TEST(RunOutcome, SuccessIsPrintedOnce) {
  const ManagerRun run =
      run_mission("exploration", R"({"initial": {"terrain": "sand", "slope": 3, "battery": 90}})");
  EXPECT_EQ(run.verdict, "success");
  const std::string summary = trace_summary(run);
  EXPECT_EQ(count(summary, "mission success"), 1u) << summary;
  EXPECT_NE(summary.find("exploration selects sand_alternative (Sand)"), std::string::npos)
      << summary;
}

TEST(RunOutcome, MaxTicksEndsARootThatStaysRunningWithTimeout) {
  // MoveForward never completes: the root runs for ever without max_ticks.
  const std::string scenario = R"({"max_ticks": 200000,
      "initial": {"OnDust": true, "IsInLocation": false},
      "actions": {"MoveForward": {"ticks": 1000000000}}})";
  const ManagerRun run = run_mission("msl_curiosity", scenario);
  EXPECT_EQ(run.verdict, "timeout");
  EXPECT_FALSE(run.finished);
  EXPECT_EQ(run.ticks, 200000u);
  EXPECT_EQ(run.status, NodeStatus::running);
  // What the run keeps does not grow with its length: select, status, done.
  EXPECT_LE(run.trace.size(), 4u) << trace_summary(run);
  EXPECT_EQ(run.trace.back().verdict, "timeout");

  ManagerOptions options;
  options.max_ticks = 30;  // --max-ticks overrides the scenario's
  const ManagerRun shorter = run_mission("msl_curiosity", scenario, options);
  EXPECT_EQ(shorter.verdict, "timeout");
  EXPECT_EQ(shorter.ticks, 30u);
}

TEST(RunOutcome, NodeTraceHasEveryStatusChangeAndWhatEachConditionRead) {
  ManagerOptions options;
  options.trace_nodes = true;
  const ManagerRun run = run_mission(
      "exploration", R"({"initial": {"terrain": "sand", "slope": 3, "battery": 12}})", options);
  EXPECT_EQ(run.verdict, "success");  // low battery: back to base
  const std::string lines = trace_json_lines(run.trace);
  EXPECT_NE(
      lines.find(
          R"({"tick":1,"event":"node","node":"MainTree/Fallback","from":"IDLE","to":"RUNNING"})"),
      std::string::npos)
      << lines;
  EXPECT_NE(
      lines.find(
          R"({"tick":1,"event":"condition","node":"MainTree/Fallback/Sequence[0]/ScriptCondition[0]","status":"success","reads":{"battery":12}})"),
      std::string::npos)
      << lines;
  // The completed root goes back to IDLE, as BT.CPP's tickOnce leaves it.
  EXPECT_NE(lines.find(R"("node":"MainTree/Fallback","from":"SUCCESS","to":"IDLE")"),
            std::string::npos);
  const std::string summary = trace_summary(run);
  EXPECT_NE(summary.find("ScriptCondition[0] read battery=12: success"), std::string::npos)
      << summary;
  EXPECT_EQ(count(summary, "mission success"), 1u);
}

TEST(RunOutcome, NodeTraceShowsWhatAnUnsetConditionRead) {
  ManagerOptions options;
  options.trace_nodes = true;
  const ManagerRun run =
      run_mission("msl_curiosity", R"({"max_ticks": 1, "initial": {"OnDust": true}})", options);
  const std::string lines = trace_json_lines(run.trace);
  EXPECT_NE(lines.find(R"("status":"failure","reads":{"IsInLocation":null})"), std::string::npos)
      << lines;
  EXPECT_NE(lines.find(R"("status":"success","reads":{"OnDust":true})"), std::string::npos);
}

}  // namespace
}  // namespace uabt::manager

namespace uabt::manager {
namespace {

using namespace uabt::runtime;  // the scenarios and traces the manager runs on

std::string scenario_errors(const std::string& mission, const std::string& json) {
  try {
    run_mission(mission, json);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioCheck, ValuesAreCheckedAgainstTheDomain) {
  // exploration/domain.fret: integer battery in [0, 100], real slope in [-45, 45],
  // enum terrain in {sand, rocks, unknown}.
  const std::string errors =
      scenario_errors("exploration",
                      "{\"initial\": {\"battery\": 150, \"slope\": 2.5,\n"
                      "             \"terrain\": \"mud\"},\n"
                      " \"events\": [{\"at\": 3, \"set\": {\"battery\": 0.5, \"slope\": true}}]}");
  EXPECT_NE(errors.find("scenario.json:1:25: error: battery = 150 is out of its range [0, 100] "
                        "(declared integer at domain.fret:1:"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("scenario.json:2:25: error: terrain = \"mud\" is not one of \"sand\", "
                        "\"rocks\", \"unknown\""),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("scenario.json:3:42: error: battery = 0.5 is not an integer"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("slope = true is not a number"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("slope = 2.5"), std::string::npos) << errors;
}

TEST(ScenarioCheck, UnknownNamesGetADidYouMean) {
  const std::string errors = scenario_errors(
      "msl_curiosity",
      "{\"initial\": {\"OnDustt\": true, \"IsArmInPosition(function=drilling)\": true},\n"
      " \"actions\": {\"MoveForwrd\": {\"ticks\": 3}, \"Drill\": {\"effects\": {\"IsDug\": "
      "true}}}}");
  EXPECT_NE(errors.find("scenario.json:1:14: error: 'OnDustt' is not a state variable, condition "
                        "or blackboard key of the mission (did you mean 'OnDust'?)"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("scenario.json:2:14: error: action 'MoveForwrd' is not a leaf of the "
                        "mission (did you mean 'MoveForward'?)"),
            std::string::npos)
      << errors;
  EXPECT_EQ(errors.find("IsArmInPosition"), std::string::npos) << errors;  // a leaf with a port
  EXPECT_EQ(errors.find("Drill"), std::string::npos) << errors;
}

TEST(ScenarioCheck, NamesAnUplinkBringsAreKnown) {
  // OnMud is declared by uplinks/on_mud only; the scenario sets it before the uplink arrives.
  const std::string errors = scenario_errors("msl_curiosity",
                                             R"({"max_ticks": 5, "initial": {"OnMud": true},
          "events": [{"at": 3, "uplink": "uplinks/on_mud"}]})");
  EXPECT_EQ(errors, "");
  EXPECT_NE(scenario_errors("msl_curiosity", R"({"max_ticks": 5, "initial": {"OnMud": true}})")
                .find("'OnMud' is not a state variable"),
            std::string::npos);
}

}  // namespace
}  // namespace uabt::manager
