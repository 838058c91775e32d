// The whole-tree checks of verify: blackboard read before write, types across the tree,
// literals against port types, and scripts the domain decides.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "load/mission.hpp"
#include "temp_mission.hpp"
#include "verify/verify.hpp"

namespace uabt::testing {
namespace {

const char* kRequirements =
    "Sand: In sampling if terrain = sand Mission shall satisfy selected_alt = scoop\n"
    "Other: In sampling Mission shall satisfy selected_alt = drill\n";
const char* kDomain =
    "real battery in [0, 100]\nenum terrain in {sand, rocks}\ninteger arm_angle in [0, 90]\n";
const char* kNodes = R"(<root BTCPP_format="4"><TreeNodesModel>
  <Condition ID="IsReady"/>
  <Action ID="Wait"/>
  <Action ID="Plan"><output_port name="path" type="std::string"/></Action>
  <Action ID="Follow"><input_port name="path" type="std::string"/>
    <input_port name="speed" type="double"/></Action>
  <Action ID="Count"><input_port name="n" type="int"/></Action>
  <Action ID="Scale"><input_port name="n" type="double"/></Action>
  <Action ID="Flag"><input_port name="on" type="bool"/></Action>
  <Action ID="Report"><input_port name="status" type="BT::NodeStatus"/></Action>
  <Action ID="Scoop"/><Action ID="Drill"/>
</TreeNodesModel></root>)";

// Verifies a mission whose main tree is `body` (then the adaptable node), with `scoop` as the
// scoop alternative's body.
verify::Result run(const std::string& body, const std::string& scoop = "<Scoop/>",
                   const std::string& extra_trees = "") {
  const std::string mission =
      "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
      "  <BehaviorTree ID=\"MainTree\">\n    <Sequence>\n" +
      body + "\n      <Adaptable ID=\"sampling\"/>\n    </Sequence>\n  </BehaviorTree>\n" +
      extra_trees + "</root>\n";
  TempMission m({{"mission.xml", mission},
                 {"requirements.fret", kRequirements},
                 {"domain.fret", kDomain},
                 {"nodes.xml", kNodes},
                 {"alternatives/sampling/scoop.xml", alternative_tree("scoop", scoop)},
                 {"alternatives/sampling/drill.xml", alternative_tree("drill", "<Drill/>")}});
  std::string error;
  auto loaded = load::load_mission(m.dir(), {}, error);
  EXPECT_TRUE(loaded.has_value()) << error;
  for (const auto& f : loaded->findings)
    if (f.severity == Severity::error) ADD_FAILURE() << "load: " << f.message;
  return verify::verify_mission(*loaded, {});
}

std::vector<Finding> of(const verify::Result& r, const std::string& check) {
  std::vector<Finding> out;
  for (const auto& f : r.findings)
    if (f.check == check) out.push_back(f);
  return out;
}

std::vector<std::string> related_messages(const Finding& f) {
  std::vector<std::string> out;
  for (const auto& r : f.related) out.push_back(r.message);
  return out;
}

TEST(ReadBeforeWrite, ScriptReadAfterAFallbackThatMayNotWriteIsReportedWithTheShortestPath) {
  const auto r =
      run("      <Fallback>\n"
          "        <Sequence><IsReady/><Script code=\"range := 12\"/></Sequence>\n"
          "        <Wait/>\n"
          "      </Fallback>\n"
          "      <ScriptCondition code=\"range &lt; 20\"/>");
  const auto found = of(r, "bb-read-before-write");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].location.file, "mission.xml");
  EXPECT_EQ(found[0].location.line, 8);
  EXPECT_EQ(found[0].location.column, 7);
  EXPECT_NE(found[0].message.find("'range'"), std::string::npos) << found[0].message;
  EXPECT_NE(found[0].message.find("Variable not found: range"), std::string::npos);
  EXPECT_EQ(related_messages(found[0]),
            (std::vector<std::string>{"ticks Sequence", "ticks Fallback", "ticks Sequence",
                                      "ticks IsReady", "IsReady fails", "ticks Wait",
                                      "Wait succeeds", "ticks ScriptCondition"}));
  EXPECT_EQ(found[0].related[3].location.line, 5);  // IsReady
}

TEST(ReadBeforeWrite, AWriteOnEveryPathIsClean) {
  const auto r =
      run("      <Fallback>\n"
          "        <Sequence><IsReady/><Script code=\"range := 12\"/></Sequence>\n"
          "        <Script code=\"range := 30\"/>\n"
          "      </Fallback>\n"
          "      <ScriptCondition code=\"range &lt; 20\"/>\n"
          "      <Plan path=\"{p}\"/><Follow path=\"{p}\" speed=\"1.5\"/>\n"
          "      <ScriptCondition code=\"battery &gt; 10 &amp;&amp; terrain == 'sand'\"/>");
  EXPECT_TRUE(of(r, "bb-read-before-write").empty());
  EXPECT_TRUE(of(r, "bb-type-conflict").empty());
  EXPECT_TRUE(of(r, "bb-literal-type").empty());
}

TEST(ReadBeforeWrite, InputPortBeforeTheOutputThatWritesItAndOneFindingPerDefect) {
  const auto r =
      run("      <Follow path=\"{p}\" speed=\"1\"/>\n"
          "      <Follow path=\"{p}\" speed=\"2\"/>\n"
          "      <Plan path=\"{p}\"/>");
  const auto found = of(r, "bb-read-before-write");
  ASSERT_EQ(found.size(), 1u);  // the second read is not reached: the first already failed
  EXPECT_EQ(found[0].location.line, 4);
  EXPECT_NE(found[0].message.find("input port 'path' ({p}) of Follow"), std::string::npos);
}

TEST(ReadBeforeWrite, AnAlternativeReadsWhatTheMissionWroteThroughAutoremap) {
  // The mission writes `depth` before the adaptable node: the alternative may read it.
  const auto clean = run("      <Script code=\"depth := 3\"/>",
                         "<Sequence><ScriptCondition code=\"depth &gt; 1\"/><Scoop/></Sequence>");
  EXPECT_TRUE(of(clean, "bb-read-before-write").empty());
  const auto unwritten =
      run("      <Wait/>", "<Sequence><ScriptCondition code=\"depth &gt; 1\"/><Scoop/></Sequence>");
  const auto found = of(unwritten, "bb-read-before-write");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].location.file, "alternatives/sampling/scoop.xml");
}

TEST(ReadBeforeWrite, SubTreeRemappingAndPrivateScopes) {
  const std::string sub =
      "  <BehaviorTree ID=\"Approach\">\n"
      "    <ScriptCondition code=\"goal &gt; 0\"/>\n"
      "  </BehaviorTree>\n";
  // goal is remapped to the parent's `target`, which is written first.
  const auto remapped = run(
      "      <Script code=\"target := 4\"/>\n      <SubTree ID=\"Approach\" goal=\"{target}\"/>",
      "<Scoop/>", sub);
  EXPECT_TRUE(of(remapped, "bb-read-before-write").empty());
  // A literal port sets the SubTree's own entry.
  const auto literal = run("      <SubTree ID=\"Approach\" goal=\"4\"/>", "<Scoop/>", sub);
  EXPECT_TRUE(of(literal, "bb-read-before-write").empty());
  // Without a remapping the SubTree's blackboard is its own: the parent's write is not seen.
  const auto isolated =
      run("      <Script code=\"goal := 4\"/>\n      <SubTree ID=\"Approach\"/>", "<Scoop/>", sub);
  ASSERT_EQ(of(isolated, "bb-read-before-write").size(), 1u);
  EXPECT_NE(of(isolated, "bb-read-before-write")[0].message.find("'goal' of Approach"),
            std::string::npos);
  // _autoremap: it is.
  const auto autoremap = run(
      "      <Script code=\"goal := 4\"/>\n      <SubTree ID=\"Approach\" _autoremap=\"true\"/>",
      "<Scoop/>", sub);
  EXPECT_TRUE(of(autoremap, "bb-read-before-write").empty());
}

TEST(ReadBeforeWrite, PreconditionsAndDecoratorsThatMaySkipTheWriter) {
  // _skipIf may skip the Script that writes x, and the Sequence goes on.
  const auto skipped =
      run("      <Script code=\"x := 1\" _skipIf=\"battery &lt; 5\"/>\n"
          "      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_EQ(of(skipped, "bb-read-before-write").size(), 1u);
  const auto inverted =
      run("      <Fallback><Inverter><IsReady/></Inverter><Script code=\"x := 1\"/></Fallback>\n"
          "      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_EQ(of(inverted, "bb-read-before-write").size(), 1u);
  const auto forced =
      run("      <ForceSuccess><Sequence><IsReady/><Script code=\"x := "
          "1\"/></Sequence></ForceSuccess>\n"
          "      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_EQ(of(forced, "bb-read-before-write").size(), 1u);
  const auto both_branches =
      run("      <IfThenElse><IsReady/><Script code=\"x := 1\"/><Script code=\"x := "
          "2\"/></IfThenElse>\n"
          "      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_TRUE(of(both_branches, "bb-read-before-write").empty());
  const auto parallel =
      run("      <Parallel success_count=\"1\"><Wait/><Script code=\"x := 1\"/></Parallel>\n"
          "      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_TRUE(of(parallel, "bb-read-before-write").empty());
  // RunOnce ticks its child before it ever skips it; Precondition may never tick it.
  const auto once =
      run("      <RunOnce><Script code=\"x := 1\"/></RunOnce>\n"
          "      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_TRUE(of(once, "bb-read-before-write").empty());
  const auto precondition =
      run("      <Precondition if=\"battery &gt; 5\" else=\"SUCCESS\"><Script code=\"x := 1\"/>"
          "</Precondition>\n      <ScriptCondition code=\"x == 1\"/>");
  EXPECT_EQ(of(precondition, "bb-read-before-write").size(), 1u);
  // `x = 1` needs x to exist; `x := x + 1` reads it first.
  const auto assign = run("      <Script code=\"x = 1\"/>");
  EXPECT_EQ(of(assign, "bb-read-before-write").size(), 1u);
  const auto increment = run("      <Script code=\"y := 0; x := y + 1\"/>");
  EXPECT_TRUE(of(increment, "bb-read-before-write").empty());
}

TEST(ReadBeforeWrite, BuiltInPortsReadExceptTheOnesBehaviorTreeCppWrites) {
  // LoopDouble writes `value` from the queue it reads; Repeat reads num_cycles.
  const auto loop =
      run("      <Script code=\"q := '1;2'\"/>\n"
          "      <LoopDouble queue=\"{q}\" value=\"{v}\"><Wait/></LoopDouble>\n"
          "      <Repeat num_cycles=\"{n}\"><Wait/></Repeat>");
  const auto found = of(loop, "bb-read-before-write");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].message.find("input port 'num_cycles' ({n}) of Repeat"), std::string::npos)
      << found[0].message;
}

TEST(ReadBeforeWrite, DomainVariablesAreTheRobotsAndAreNotReported) {
  const auto r = run("      <ScriptCondition code=\"battery &gt; 10\"/>");
  EXPECT_TRUE(of(r, "bb-read-before-write").empty());
}

TEST(TypeConflict, TwoPortTypesOnOneEntryAreReportedAtBothPlaces) {
  const auto r =
      run("      <Script code=\"n := 3\"/>\n"
          "      <Count n=\"{n}\"/>\n"
          "      <Scale n=\"{n}\"/>");
  const auto found = of(r, "bb-type-conflict");
  ASSERT_EQ(found.size(), 2u);
  std::vector<int> lines{found[0].location.line, found[1].location.line};
  std::sort(lines.begin(), lines.end());
  EXPECT_EQ(lines, (std::vector<int>{5, 6}));
  ASSERT_EQ(found[0].related.size(), 1u);
  EXPECT_NE(found[0].message.find("(int)"), std::string::npos) << found[0].message;
  EXPECT_NE(found[0].message.find("(double)"), std::string::npos) << found[0].message;
}

TEST(TypeConflict, AcrossSubTreeRemapping) {
  const std::string sub =
      "  <BehaviorTree ID=\"Go\">\n"
      "    <Scale n=\"{amount}\"/>\n"
      "  </BehaviorTree>\n";
  const auto r =
      run("      <Script code=\"k := 1\"/>\n      <Count n=\"{k}\"/>\n"
          "      <SubTree ID=\"Go\" amount=\"{k}\"/>",
          "<Scoop/>", sub);
  const auto found = of(r, "bb-type-conflict");
  ASSERT_EQ(found.size(), 2u);
  // A script's string that does not read as the port's number, and a number in a string entry.
  const auto script = run("      <Script code=\"n := 'many'\"/>\n      <Count n=\"{n}\"/>");
  EXPECT_EQ(of(script, "bb-type-conflict").size(), 2u);
  const auto fits = run("      <Script code=\"n := '12'\"/>\n      <Count n=\"{n}\"/>");
  EXPECT_TRUE(of(fits, "bb-type-conflict").empty());
}

TEST(LiteralType, ALiteralThatDoesNotConvertToThePortTypeIsAnError) {
  const auto r =
      run("      <Script code=\"p := 'a'\"/>\n"
          "      <Follow path=\"{p}\" speed=\"fast\"/>\n"
          "      <Count n=\"2.5\"/>\n"
          "      <Flag on=\"yes\"/>\n"
          "      <Flag on=\"True\"/>\n"
          "      <Count n=\"-7\"/>");
  const auto found = of(r, "bb-literal-type");
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].location.line, 5);
  EXPECT_NE(found[0].message.find("\"fast\""), std::string::npos);
  EXPECT_EQ(found[1].location.line, 6);
  EXPECT_EQ(found[2].location.line, 7);
}

TEST(LiteralType, ANodeStatusLiteralIsOneOfTheFiveStatusesAsTheSchemaSays) {
  // convertFromString<NodeStatus> knows IDLE, RUNNING, SUCCESS, FAILURE and SKIPPED only; the
  // check and `uabt schema` read one table of them.
  const auto r = run("      <Report status=\"SKIPPED\"/>\n      <Report status=\"DONE\"/>");
  const auto found = of(r, "bb-literal-type");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].location.line, 5);
  EXPECT_NE(found[0].message.find("\"DONE\""), std::string::npos) << found[0].message;
}

TEST(ScriptDecided, PreconditionsAndConditionsTheDomainDecideAreWarnings) {
  const auto r =
      run("      <ScriptCondition code=\"battery &lt;= 100\"/>\n"
          "      <Wait _skipIf=\"battery &gt; 100\"/>\n"
          "      <Wait _failureIf=\"terrain == 'sand' &amp;&amp; terrain == 'rocks'\"/>\n"
          "      <Wait _successIf=\"battery &lt; 50\"/>");
  const auto found = of(r, "script-decided");
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].severity, Severity::warning);
  EXPECT_EQ(found[0].location.line, 4);
  EXPECT_NE(found[0].message.find("always true"), std::string::npos) << found[0].message;
  EXPECT_NE(found[0].message.find("battery in [0, 100]"), std::string::npos);
  EXPECT_EQ(found[1].location.line, 5);
  EXPECT_NE(found[1].message.find("never true"), std::string::npos);
  EXPECT_EQ(found[2].location.line, 6);
  EXPECT_NE(found[2].message.find("never true"), std::string::npos);
}

TEST(ScriptOutOfRange, AnAssignmentAlwaysOutsideTheRangeIsAnErrorWithAWitness) {
  const auto r = run("      <Wait/>",
                     "<Sequence><Script code=\"arm_angle := 120\"/>"
                     "<Script code=\"arm_angle := battery + 91\"/>"
                     "<Script code=\"arm_angle := battery\"/><Scoop/></Sequence>");
  const auto found = of(r, "script-out-of-range");
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].location.file, "alternatives/sampling/scoop.xml");
  EXPECT_NE(found[0].message.find("120"), std::string::npos);
  EXPECT_NE(found[1].message.find("battery + 91"), std::string::npos);
  EXPECT_FALSE(found[1].witness.empty());
}

}  // namespace
}  // namespace uabt::testing
