// Ground truth for bb-read-before-write: the witness path verify reports, played in the
// runtime (BehaviorTree.CPP 4.10's tick semantics), throws at the node the finding names, with
// the entry it names; the path that writes first does not.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "compile/compile.hpp"
#include "load/mission.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario.hpp"
#include "temp_mission.hpp"
#include "verify/verify.hpp"

namespace uabt::testing {
namespace {

const char* kNodes = R"(<root BTCPP_format="4"><TreeNodesModel>
  <Condition ID="IsReady"/><Condition ID="HasSample"/>
  <Action ID="Wait"/><Action ID="Scoop"/><Action ID="Drill"/>
  <Action ID="Locate"><output_port name="range" type="int"/></Action>
  <Action ID="Approach"><input_port name="goal" type="int"/></Action>
</TreeNodesModel></root>)";

struct Case {
  const char* name;
  std::string mission_body;
  std::string scoop_body;
  std::string key;  // the entry the run must miss
};

// The scenario that takes the witness path: each leaf result on it is what the world answers.
std::string scenario_for(const Finding& f) {
  std::map<std::string, bool> conditions{{"IsReady", true}, {"HasSample", true}};
  std::map<std::string, std::string> actions;
  for (const auto& step : f.related) {
    const std::string& text = step.message;
    const auto space = text.find(' ');
    const std::string node = text.substr(0, space);
    const bool fails = text.ends_with(" fails");
    const bool succeeds = text.ends_with(" succeeds");
    if (!fails && !succeeds) continue;
    if (conditions.count(node) != 0) conditions[node] = succeeds;
    if (node == "Wait" || node == "Scoop" || node == "Drill")
      actions[node] = fails ? "failure" : "success";
  }
  std::string json = "{\"max_ticks\": 3, \"initial\": {\"terrain\": \"sand\", \"battery\": 50";
  for (const auto& [name, value] : conditions)
    json += ", \"" + name + "\": " + (value ? "true" : "false");
  json += "}, \"actions\": {";
  bool first = true;
  for (const auto& [name, result] : actions) {
    json += std::string(first ? "" : ", ") + "\"" + name + "\": {\"result\": \"" + result + "\"}";
    first = false;
  }
  return json + "}}";
}

TEST(ReadBeforeWriteGroundTruth, TheWitnessPathThrowsInTheRuntimeAtTheReportedNode) {
  const std::vector<Case> cases = {
      {"fallback",
       "<Fallback><Sequence><IsReady/><Script code=\"range := 12\"/></Sequence><Wait/>"
       "</Fallback>\n      <ScriptCondition code=\"range &lt; 20\"/>",
       "<Scoop/>", "range"},
      {"inverter",
       "<Fallback><Inverter><HasSample/></Inverter><Script code=\"depth := 2\"/></Fallback>",
       "<Sequence><ScriptCondition code=\"depth &gt; 1\"/><Scoop/></Sequence>", "depth"},
      {"if_then_else",
       "<IfThenElse><IsReady/><Script code=\"mode := 1\"/><Wait/></IfThenElse>\n"
       "      <Script code=\"speed := mode * 2\"/>",
       "<Scoop/>", "mode"},
      // An input port's getInput() finds no entry: the robot's node throws there.
      {"input_port",
       "<Fallback><Sequence><IsReady/><Locate range=\"{range}\"/></Sequence><Wait/>"
       "</Fallback>\n      <Approach goal=\"{range}\"/>",
       "<Scoop/>", "range"},
      {"skip_if",
       "<Script code=\"tries := 0\" _skipIf=\"battery &gt; 40\"/>\n"
       "      <Script code=\"tries += 1\"/>",
       "<Scoop/>", "tries"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string mission =
        "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
        "  <BehaviorTree ID=\"MainTree\">\n    <Sequence>\n      " +
        c.mission_body + "\n      <Adaptable ID=\"sampling\"/>\n    </Sequence>\n" +
        "  </BehaviorTree>\n</root>\n";
    TempMission m(
        {{"mission.xml", mission},
         {"requirements.fret",
          "Sand: In sampling if terrain = sand Mission shall satisfy selected_alt = scoop\n"
          "Other: In sampling Mission shall satisfy selected_alt = drill\n"},
         {"domain.fret", "real battery in [0, 100]\nenum terrain in {sand, rocks}\n"},
         {"nodes.xml", kNodes},
         {"alternatives/sampling/scoop.xml", alternative_tree("scoop", c.scoop_body)},
         {"alternatives/sampling/drill.xml", alternative_tree("drill", "<Drill/>")}});
    std::string error;
    auto loaded = load::load_mission(m.dir(), {}, error);
    ASSERT_TRUE(loaded.has_value()) << error;
    const verify::Result verified = verify::verify_mission(*loaded, {});
    std::vector<Finding> found;
    for (const auto& f : verified.findings)
      if (f.check == "bb-read-before-write") found.push_back(f);
    ASSERT_EQ(found.size(), 1u);
    const Finding& f = found.front();
    EXPECT_NE(f.message.find("'" + c.key + "'"), std::string::npos) << f.message;

    const compile::Result compiled = compile::compile_mission(*loaded, {});
    ASSERT_TRUE(compiled.ok);
    const std::string witness = scenario_for(f);
    runtime::Runner runner(compiled.document, runtime::parse_scenario(witness, "witness.json"), {},
                           *loaded->nodes);
    const runtime::RunResult run = runner.run();
    ASSERT_EQ(run.verdict, "error") << witness;
    ASSERT_TRUE(run.error.has_value());
    const SourceLocation& at = runner.engine().info(run.error->node).location;
    EXPECT_EQ(at.line, f.location.line) << run.error->message;
    EXPECT_EQ(at.column, f.location.column) << run.error->message;
    EXPECT_NE(run.error->message.find(c.key), std::string::npos) << run.error->message;
  }
}

TEST(ReadBeforeWriteGroundTruth, ThePathThatWritesFirstRunsWithoutError) {
  TempMission m(
      {{"mission.xml", mission_with("    <Sequence>\n      <Fallback><Sequence><IsReady/>"
                                    "<Script code=\"range := 12\"/></Sequence><Wait/></Fallback>\n"
                                    "      <ScriptCondition code=\"range &lt; 20\"/>\n"
                                    "      <Adaptable ID=\"sampling\"/>\n    </Sequence>")},
       {"requirements.fret",
        "Sand: In sampling if terrain = sand Mission shall satisfy selected_alt = scoop\n"
        "Other: In sampling Mission shall satisfy selected_alt = drill\n"},
       {"domain.fret", "real battery in [0, 100]\nenum terrain in {sand, rocks}\n"},
       {"nodes.xml", kNodes},
       {"alternatives/sampling/scoop.xml", alternative_tree("scoop", "<Scoop/>")},
       {"alternatives/sampling/drill.xml", alternative_tree("drill", "<Drill/>")}});
  std::string error;
  auto loaded = load::load_mission(m.dir(), {}, error);
  ASSERT_TRUE(loaded.has_value()) << error;
  const compile::Result compiled = compile::compile_mission(*loaded, {});
  ASSERT_TRUE(compiled.ok);
  runtime::Runner runner(
      compiled.document,
      runtime::parse_scenario(
          "{\"max_ticks\": 3, \"initial\": {\"terrain\": \"sand\", \"battery\": 50, "
          "\"IsReady\": true}}",
          "writes.json"),
      {}, *loaded->nodes);
  EXPECT_EQ(runner.run().verdict, "success");
}

}  // namespace
}  // namespace uabt::testing
