// Whole-tree checks: output ports, dead branches, reactive controls with several asynchronous
// children, node kinds (checks/tree-*.md).
#include <gtest/gtest.h>

#include "load/load_test_support.hpp"
#include "verify/tree/tree_checks.hpp"
#include "verify/verify.hpp"

namespace uabt::testing {
namespace {

const std::string kNodes =
    "<root BTCPP_format=\"4\">\n<TreeNodesModel>\n"
    "  <Condition ID=\"IsBatteryOk\"/>\n"
    "  <Action ID=\"Stop\"/>\n"
    "  <Action ID=\"Drill\"/>\n"
    "  <Action ID=\"PlanPath\">\n"
    "    <input_port name=\"goal\" default=\"0\"/>\n"
    "    <output_port name=\"path\"/>\n"
    "  </Action>\n"
    "  <Action ID=\"Measure\">\n"
    "    <output_port name=\"depth\" default=\"{depth}\"/>\n"
    "    <inout_port name=\"log\" default=\"{log}\"/>\n"
    "  </Action>\n"
    "</TreeNodesModel>\n</root>\n";

// The mission with `body` as on_dust's tree (and `nodes` as nodes.xml unless empty).
load::Mission mission_with_dust(const std::string& body, const std::string& nodes = kNodes,
                                const std::string& requirements = kTwoTerrains) {
  auto files = navigation_files(requirements);
  if (!nodes.empty()) files["nodes.xml"] = nodes;
  files["alternatives/navigation/on_dust.xml"] = alternative_tree("on_dust", body);
  TempMission dir(files);
  return load_dir(dir.dir());
}

std::vector<Finding> with(const std::vector<Finding>& all, const std::string& check) {
  std::vector<Finding> out;
  for (const auto& f : all)
    if (f.check == check) out.push_back(f);
  return out;
}

std::string text(const std::vector<Finding>& findings) {
  return format_text(findings, {});
}

TEST(TreeOutputPorts, LiteralIsAnErrorAtTheAttribute) {
  const load::Mission m = mission_with_dust(
      "<Sequence>\n      <Stop/>\n      <PlanPath goal=\"3\"   path=\"waypoints\"/>\n"
      "    </Sequence>");
  const auto all = verify::tree::check_trees(m);
  const auto found = with(all, "tree-output-literal");
  ASSERT_EQ(found.size(), 1u) << text(all);
  EXPECT_EQ(found[0].severity, Severity::error);
  EXPECT_EQ(found[0].location.file, "alternatives/navigation/on_dust.xml");
  EXPECT_EQ(found[0].location.line, 5);
  EXPECT_EQ(found[0].location.column, 28);  // path="waypoints"
  EXPECT_EQ(found[0].message,
            "output port 'path' of PlanPath is bound to the literal \"waypoints\": "
            "BehaviorTree.CPP's setOutput fails at run time (\"setOutput requires a blackboard "
            "pointer. Use {}\") and the value is lost");
  // The path through the tree: the <BehaviorTree>, then the Sequence.
  ASSERT_EQ(found[0].related.size(), 2u);
  EXPECT_EQ(found[0].related[0].message, "in <BehaviorTree ID=\"on_dust\">");
  EXPECT_EQ(found[0].related[0].location.line, 2);
  EXPECT_EQ(found[0].related[1].message, "in <Sequence>");
  EXPECT_EQ(found[0].related[1].location.line, 3);
  EXPECT_EQ(found[0].related[1].location.column, 5);
}

TEST(TreeOutputPorts, EmptyValueAndInOutLiteralAreErrors) {
  const load::Mission m = mission_with_dust(
      "<Sequence>\n      <PlanPath path=\"\"/>\n      <Measure log=\"x\"/>\n    </Sequence>");
  const auto found = with(verify::tree::check_trees(m), "tree-output-literal");
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NE(found[0].message.find("'path' of PlanPath is bound to nothing (path=\"\")"),
            std::string::npos);
  EXPECT_EQ(found[0].location.column, 17);
  EXPECT_NE(found[1].message.find("in/out port 'log' of Measure is bound to the literal \"x\""),
            std::string::npos);
}

TEST(TreeOutputPorts, BlackboardEntriesAndDefaultsPass) {
  const load::Mission m = mission_with_dust(
      "<Sequence>\n      <PlanPath path=\"{waypoints}\"/>\n      <PlanPath path=\"{=}\"/>\n"
      "      <Measure/>\n    </Sequence>");
  const auto all = verify::tree::check_trees(m);
  EXPECT_TRUE(with(all, "tree-output-literal").empty()) << text(all);
  EXPECT_TRUE(with(all, "tree-output-unbound").empty()) << text(all);
}

TEST(TreeOutputPorts, UnboundOutputWithoutEntryDefaultIsAWarning) {
  const load::Mission m = mission_with_dust("<PlanPath/>");
  const auto found = with(verify::tree::check_trees(m), "tree-output-unbound");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].severity, Severity::warning);
  EXPECT_EQ(found[0].location.line, 3);
  EXPECT_EQ(found[0].location.column, 5);
}

TEST(TreeDeadBranch, ChildAfterForceSuccessInAFallback) {
  const load::Mission m = mission_with_dust(
      "<Fallback name=\"reach\">\n      <ForceSuccess><Drill/></ForceSuccess>\n"
      "      <Stop/>\n      <Drill/>\n    </Fallback>");
  const auto all = verify::tree::check_trees(m);
  const auto found = with(all, "tree-dead-branch");
  ASSERT_EQ(found.size(), 1u) << text(all);
  EXPECT_EQ(found[0].severity, Severity::warning);
  EXPECT_EQ(found[0].location.line, 5);
  EXPECT_EQ(found[0].message,
            "<Stop> and the child after it are never ticked: <ForceSuccess> before it in "
            "<Fallback name=\"reach\"> never fails");
  ASSERT_EQ(found[0].related.size(), 3u);  // the <BehaviorTree>, the Fallback, the cause
  EXPECT_EQ(found[0].related[1].message, "in <Fallback name=\"reach\">");
  EXPECT_EQ(found[0].related[2].location.line, 4);
}

TEST(TreeDeadBranch, AfterAnInvertedAlwaysSuccessInASequence) {
  const load::Mission m = mission_with_dust(
      "<ReactiveSequence>\n      <Inverter><AlwaysSuccess/></Inverter>\n      <Stop/>\n"
      "    </ReactiveSequence>");
  const auto found = with(verify::tree::check_trees(m), "tree-dead-branch");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].message.find("never succeeds"), std::string::npos);
}

TEST(TreeDeadBranch, ElseBranchOfAConditionThatNeverFails) {
  const load::Mission m = mission_with_dust(
      "<IfThenElse>\n      <AlwaysSuccess/>\n      <Stop/>\n      <Drill/>\n    </IfThenElse>");
  const auto found = with(verify::tree::check_trees(m), "tree-dead-branch");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].location.line, 6);
  EXPECT_NE(found[0].message.find("the else-branch"), std::string::npos);
}

TEST(TreeDeadBranch, PreconditionsSkipsAndOrdinaryChildrenAreLive) {
  const load::Mission m = mission_with_dust(
      "<Sequence>\n      <Fallback>\n        <AlwaysSuccess _failureIf=\"true\"/>\n"
      "        <Stop/>\n      </Fallback>\n      <Fallback>\n"
      "        <ForceSuccess><Drill _skipIf=\"false\"/></ForceSuccess>\n        <Stop/>\n"
      "      </Fallback>\n      <Fallback>\n        <IsBatteryOk/>\n        <Stop/>\n"
      "      </Fallback>\n      <Sequence>\n        <ForceFailure><Drill/></ForceFailure>\n"
      "      </Sequence>\n    </Sequence>");
  const auto all = verify::tree::check_trees(m);
  EXPECT_TRUE(with(all, "tree-dead-branch").empty()) << text(all);
}

TEST(TreeAsyncReactive, TwoActionsUnderAReactiveSequence) {
  const load::Mission m = mission_with_dust(
      "<ReactiveSequence>\n      <IsBatteryOk/>\n      <Stop/>\n      "
      "<Sequence><Drill/></Sequence>\n"
      "    </ReactiveSequence>");
  const auto all = verify::tree::check_trees(m);
  const auto found = with(all, "tree-async-reactive");
  ASSERT_EQ(found.size(), 1u) << text(all);
  EXPECT_EQ(found[0].severity, Severity::warning);
  EXPECT_EQ(found[0].location.line, 6);
  EXPECT_EQ(found[0].related.back().location.line, 5);
  EXPECT_EQ(found[0].related[1].message, "in <ReactiveSequence>");
}

TEST(TreeAsyncReactive, ConditionsAndOneActionPass) {
  const load::Mission m = mission_with_dust(
      "<ReactiveFallback>\n      <IsBatteryOk/>\n      <ScriptCondition code=\"true\"/>\n"
      "      <Sequence><AlwaysSuccess/><Drill/></Sequence>\n    </ReactiveFallback>");
  const auto all = verify::tree::check_trees(m);
  EXPECT_TRUE(with(all, "tree-async-reactive").empty()) << text(all);
}

TEST(TreeAsyncReactive, WithoutNodesXmlDomainConditionsAreNotActions) {
  // OnDust is a condition the guards read; MoveForward is an action.
  const load::Mission m = mission_with_dust(
      "<ReactiveSequence>\n      <OnDust/>\n      <MoveForward/>\n    </ReactiveSequence>", "");
  const auto all = verify::tree::check_trees(m);
  EXPECT_TRUE(with(all, "tree-async-reactive").empty()) << text(all);
}

TEST(TreeKindMismatch, ExplicitConditionOfARegisteredAction) {
  const load::Mission m = mission_with_dust(
      "<Fallback>\n      <Condition ID=\"Drill\"/>\n      <Action ID=\"Stop\"/>\n"
      "      <Action ID=\"AlwaysFailure\"/>\n      <Action ID=\"IsBatteryOk\"/>\n    </Fallback>");
  const auto all = verify::tree::check_trees(m);
  const auto found = with(all, "tree-kind-mismatch");
  ASSERT_EQ(found.size(), 2u) << text(all);
  EXPECT_EQ(found[0].severity, Severity::error);
  EXPECT_EQ(found[0].location.line, 4);
  EXPECT_EQ(found[0].location.column, 7);
  EXPECT_EQ(found[0].message,
            "<Condition ID=\"Drill\"> but nodes.xml registers Drill as an Action: "
            "BehaviorTree.CPP builds the node from its ID and ignores the element name, so the "
            "tree does not do what it says");
  EXPECT_EQ(found[1].location.line, 7);
  EXPECT_NE(found[1].message.find("registers IsBatteryOk as a Condition"), std::string::npos);
}

TEST(TreeKindMismatch, GuardThatNamesAnAction) {
  const load::Mission m = mission_with_dust(
      "<Stop/>", kNodes,
      "Req1: In navigation if OnDust & !Drill Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if IsBatteryOk Mission shall satisfy selected_alt = on_rocks\n");
  const auto all = verify::tree::check_trees(m);
  const auto found = with(all, "tree-kind-mismatch");
  ASSERT_EQ(found.size(), 1u) << text(all);
  EXPECT_EQ(found[0].location.file, "requirements.fret");
  EXPECT_EQ(found[0].location.line, 1);
  EXPECT_EQ(found[0].location.column, 34);
  EXPECT_EQ(found[0].requirements, std::vector<std::string>{"Req1"});
}

TEST(TreeChecks, VerifyRunsThemOnEveryAlternative) {
  const load::Mission m = mission_with_dust("<PlanPath path=\"x\"/>");
  verify::Options options;
  options.threads = 1;
  const verify::Result r = verify::verify_mission(m, options);
  EXPECT_EQ(with(r.findings, "tree-output-literal").size(), 1u);
}

}  // namespace
}  // namespace uabt::testing
