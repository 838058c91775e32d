// A robot leaf's `{key}` ports in `uabt run`: an action writes the value a scenario gives for
// its output port when it completes, an input port whose entry nothing has written stops the
// tick at that node with BT.CPP's error, and a scenario's "outputs" are checked against the
// nodes' ports and types.
#include <gtest/gtest.h>

#include "runtime/runner.hpp"
#include "runtime/scenario.hpp"
#include "runtime/scenario_check.hpp"
#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

const char* kModels = R"(<TreeNodesModel>
  <Action ID="PlanOrbit"><output_port name="waypoint" type="int"/></Action>
  <Action ID="Burn"><input_port name="target" type="int"/></Action>
  <Action ID="Glide"/>
</TreeNodesModel>)";

bt::Document orbit(const std::string& first = "<PlanOrbit waypoint=\"{waypoint}\"/>") {
  return main_tree("<Sequence>" + first +
                       "<ScriptCondition name=\"near\" code=\"waypoint &lt; 5\"/>"
                       "<Burn target=\"{waypoint}\"/></Sequence>",
                   kModels);
}

TEST(BlackboardPortsRun, AnActionWritesTheScenariosOutputWhenItCompletes) {
  const bt::Document doc = orbit();
  for (const auto& [written, verdict] :
       std::vector<std::pair<int, std::string>>{{3, "success"}, {7, "failure"}}) {
    Runner runner(
        doc, parse_scenario(R"({"actions": {"PlanOrbit": {"ticks": 2, "outputs": {"waypoint": )" +
                                std::to_string(written) + "}}}}",
                            "s.json"));
    const RunResult run = runner.run();
    EXPECT_EQ(run.verdict, verdict);
    EXPECT_EQ(run.ticks, 2u);
    const ScriptValue* v = runner.engine().blackboard().get("waypoint");
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->to_string(), std::to_string(written));
  }
  // A run of the action says what that start writes.
  Runner runner(doc, parse_scenario(R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": 1},
      "runs": [{"ticks": 1, "outputs": {"waypoint": 9}}]}}})",
                                    "s.json"));
  EXPECT_EQ(runner.run().verdict, "failure");
  EXPECT_EQ(runner.engine().blackboard().get("waypoint")->to_string(), "9");
}

TEST(BlackboardPortsRun, AnInputPortNothingWroteStopsTheTickAtItsNodeWithBtcppsError) {
  // PlanOrbit writes nothing the scenario does not give: Burn's getInput() finds no entry.
  const bt::Document doc = main_tree(
      "<Sequence><PlanOrbit waypoint=\"{waypoint}\"/><Burn target=\"{waypoint}\"/></Sequence>",
      kModels);
  Runner runner(doc, parse_scenario("{}", "s.json"));
  const RunResult run = runner.run();
  EXPECT_EQ(run.verdict, "error");
  ASSERT_TRUE(run.error.has_value());
  EXPECT_EQ(runner.engine().info(run.error->node).kind, "Burn");
  EXPECT_EQ(run.error->message,
            "test.xml:1:120: Burn: input port 'target' reads {waypoint}, which nothing has "
            "written: getInput() failed because it was unable to find the key [target] remapped "
            "to [waypoint]");
  // Once written, the same read passes.
  Runner written(
      doc, parse_scenario(R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": 2}}}})", "s.json"));
  EXPECT_EQ(written.run().verdict, "success");
}

TEST(BlackboardPortsRun, ScenarioOutputsAreCheckedAgainstTheNodesPortsAndTypes) {
  ScenarioVocabulary v;
  v.leaves = {"PlanOrbit", "Burn", "Glide"};
  const bt::Document doc = orbit();
  for (const auto& model : doc.node_models) v.ports[model.id] = model.ports;
  const Scenario s = parse_scenario(R"({"actions": {
  "PlanOrbit": {"outputs": {"waypoit": 3}},
  "Burn": {"runs": [{"outputs": {"target": 1}}]},
  "Glide": {"outputs": {"x": 1}}
}, "events": []})",
                                    "s.json");
  EXPECT_EQ(check_scenario(s, v),
            (std::vector<std::string>{
                "s.json:3:34: error: 'Burn' has no output port in nodes.xml, so it writes no "
                "'target'",
                "s.json:4:25: error: 'Glide' has no output port in nodes.xml, so it writes no 'x'",
                "s.json:2:29: error: 'waypoit' is not an output port of 'PlanOrbit' (its output "
                "ports: waypoint) (did you mean 'waypoint'?)"}));
  const Scenario typed =
      parse_scenario(R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": 2.5}}}})", "t.json");
  EXPECT_EQ(check_scenario(typed, v),
            (std::vector<std::string>{
                "t.json:1:52: error: the value of output port 'waypoint' of 'PlanOrbit', 2.5, is "
                "not an integer (the port's type is int)"}));
  EXPECT_THROW(parse_scenario(R"({"actions": {"PlanOrbit": {"outputs": [3]}}})", "u.json"),
               ScenarioError);
}

}  // namespace
}  // namespace uabt::runtime::testing
