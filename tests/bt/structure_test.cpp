// check_structure: each BehaviorTree.CPP load rule, violated and respected.
#include <gtest/gtest.h>

#include "bt/structure.hpp"
#include "bt/xml_io.hpp"
#include "bt_test_util.hpp"

namespace uabt::bt {
namespace {

using testing::describe;

// Parses `xml` (which must read cleanly) and checks all its trees.
std::vector<Finding> check(const std::string& xml, const StructureOptions& options = {}) {
  const Document doc = testing::parse_clean(xml, "s.xml");
  std::vector<const TreeDef*> trees;
  for (const TreeDef& tree : doc.trees) trees.push_back(&tree);
  return check_structure(trees, options);
}

std::string in_tree(const std::string& body, const std::string& id = "T") {
  return "<root BTCPP_format=\"4\"><BehaviorTree ID=\"" + id + "\">" + body +
         "</BehaviorTree></root>";
}

// Exactly one finding, with this message; returns it for more checks.
Finding only(const std::vector<Finding>& findings, const std::string& message) {
  EXPECT_EQ(findings.size(), 1u) << describe(findings);
  if (findings.empty()) return Finding{};
  EXPECT_EQ(findings[0].check, "bt-structure");
  EXPECT_EQ(findings[0].message, message);
  return findings[0];
}

TEST(Structure, DecoratorNeedsExactlyOneChild) {
  const Finding f = only(check("<root>\n<BehaviorTree ID=\"T\">\n  <Inverter><A/><B/></Inverter>"
                               "</BehaviorTree></root>"),
                         "Inverter must have exactly 1 child, has 2");
  EXPECT_EQ(f.location.file, "s.xml");
  EXPECT_EQ(f.location.line, 3);
  EXPECT_EQ(f.location.column, 3);
  only(check(in_tree("<Sequence><RetryUntilSuccessful num_attempts=\"2\"/></Sequence>")),
       "RetryUntilSuccessful must have exactly 1 child, has 0");
  EXPECT_TRUE(check(in_tree("<Inverter><A/></Inverter>")).empty());
  EXPECT_TRUE(check(in_tree("<Decorator ID=\"Timeout\" msec=\"5\"><A/></Decorator>")).empty());
}

TEST(Structure, ControlNeedsChildren) {
  only(check(in_tree("<Sequence/>")), "Sequence must have at least 1 child, has 0");
  only(check(in_tree("<Control ID=\"Fallback\"/>")), "Fallback must have at least 1 child, has 0");
  EXPECT_TRUE(check(in_tree("<ReactiveFallback><A/></ReactiveFallback>")).empty());
}

TEST(Structure, ControlMaximumWhereTheTableHasOne) {
  only(check(in_tree("<IfThenElse><A/></IfThenElse>")),
       "IfThenElse must have 2 to 3 children, has 1");
  only(check(in_tree("<WhileDoElse><A/><B/><C/><D/></WhileDoElse>")),
       "WhileDoElse must have 2 to 3 children, has 4");
  only(check(in_tree("<Switch2 variable=\"{v}\" case_1=\"a\" case_2=\"b\"><A/><B/></Switch2>")),
       "Switch2 must have exactly 3 children, has 2");
  EXPECT_TRUE(check(in_tree("<IfThenElse><A/><B/></IfThenElse>")).empty());
  EXPECT_TRUE(check(in_tree("<IfThenElse><A/><B/><C/></IfThenElse>")).empty());
}

TEST(Structure, LeavesHaveNoChildren) {
  only(check(in_tree("<AlwaysSuccess><A/></AlwaysSuccess>")),
       "AlwaysSuccess is an action and must have no children, has 1");
  only(check(in_tree("<ScriptCondition code=\"x\"><A/></ScriptCondition>")),
       "ScriptCondition is a condition and must have no children, has 1");
  only(check(in_tree("<MoveForward><A/><B/></MoveForward>")),
       "MoveForward is a leaf (an action or condition) and must have no children, has 2");
  only(check(in_tree("<Condition ID=\"IsSafe\"><A/></Condition>")),
       "IsSafe is a condition and must have no children, has 1");
  EXPECT_TRUE(check(in_tree("<MoveForward speed=\"1\"/>")).empty());
}

TEST(Structure, ModelledCustomControlsAndDecoratorsMayHaveChildren) {
  StructureOptions options;
  options.node_models = {NodeModel{"Decorator", "Throttle", {}, 0, 0, ""},
                         NodeModel{"Control", "Vote", {}, 0, 0, ""}};
  EXPECT_TRUE(check(in_tree("<Vote><Throttle><A/></Throttle><B/></Vote>"), options).empty());
  only(check(in_tree("<Throttle><A/><B/></Throttle>"), options),
       "Throttle must have exactly 1 child, has 2");
  only(check(in_tree("<Vote/>"), options), "Vote must have at least 1 child, has 0");
  EXPECT_TRUE(check(in_tree("<Decorator ID=\"Custom\"><A/></Decorator>")).empty());
}

TEST(Structure, SubTreeRules) {
  const std::string other = "<BehaviorTree ID=\"Other\"><A/></BehaviorTree>";
  EXPECT_TRUE(check("<root><BehaviorTree ID=\"T\"><SubTree ID=\"Other\"/></BehaviorTree>" + other +
                    "</root>")
                  .empty());
  only(check(in_tree("<SubTree ID=\"X\"/>")), "SubTree 'X' names no tree");
  only(check(in_tree("<SubTree/>")), "<SubTree> needs an ID");
  const auto children = check(
      "<root><BehaviorTree ID=\"T\"><SubTree ID=\"Other\"><A/></SubTree>"
      "</BehaviorTree>" +
      other + "</root>");
  only(children, "SubTree must have no children, has 1");
  only(check(in_tree("<SubTreePlus ID=\"Y\" __autoremap=\"1\"/>")),
       "SubTreePlus 'Y' names no tree");
}

TEST(Structure, SubTreeTargetsAcrossDocuments) {
  // A mission and an alternative: the SubTree resolves among all trees given.
  const Document mission = testing::parse_clean(in_tree("<SubTree ID=\"alt\"/>", "Main"), "m.xml");
  const Document alternative = testing::parse_clean(in_tree("<Go/>", "alt"), "a.xml");
  EXPECT_TRUE(check_structure({&mission.trees[0], &alternative.trees[0]}, {}).empty());
  const auto alone = check_structure({&mission.trees[0]}, {});
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(alone[0].location.file, "m.xml");
}

TEST(Structure, SubTreeCycles) {
  const auto findings = check(
      "<root>\n"
      "<BehaviorTree ID=\"A\"><Sequence><SubTree ID=\"B\"/><X/></Sequence></BehaviorTree>\n"
      "<BehaviorTree ID=\"B\"><Fallback><SubTree ID=\"C\"/></Fallback></BehaviorTree>\n"
      "<BehaviorTree ID=\"C\"><SubTree ID=\"A\"/></BehaviorTree>\n"
      "<BehaviorTree ID=\"D\"><SubTree ID=\"D\"/></BehaviorTree>\n"
      "<BehaviorTree ID=\"E\"><SubTree ID=\"A\"/></BehaviorTree>\n"
      "</root>");
  ASSERT_EQ(findings.size(), 2u) << describe(findings);
  EXPECT_EQ(findings[0].message, "SubTree cycle: A → B → C → A");
  EXPECT_EQ(findings[0].location.line, 4);
  EXPECT_EQ(findings[0].location.column, 22);
  EXPECT_EQ(findings[1].message, "SubTree cycle: D → D");
  EXPECT_EQ(findings[1].location.line, 5);
  // A diamond is not a cycle.
  EXPECT_TRUE(check("<root><BehaviorTree ID=\"A\"><Sequence><SubTree ID=\"B\"/><SubTree ID=\"C\"/>"
                    "</Sequence></BehaviorTree><BehaviorTree ID=\"B\"><SubTree ID=\"C\"/>"
                    "</BehaviorTree><BehaviorTree ID=\"C\"><X/></BehaviorTree></root>")
                  .empty());
}

TEST(Structure, LongSubTreeChainIsNotRecursedInto) {
  // 20000 trees, each calling the next, the last calling the first: one cycle, no stack overflow.
  std::vector<TreeDef> trees(20000);
  std::vector<const TreeDef*> pointers;
  for (std::size_t i = 0; i < trees.size(); ++i) {
    trees[i].id = "T" + std::to_string(i);
    trees[i].file = "chain.xml";
    trees[i].root.tag = "SubTree";
    trees[i].root.set_attribute("ID", "T" + std::to_string((i + 1) % trees.size()));
    pointers.push_back(&trees[i]);
  }
  const auto findings = check_structure(pointers, {});
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].message,
            "SubTree cycle: T0 → T1 → T2 → T3 → T4 → T5 → T6 → T7 → T8 → T9 → … (19989 more) → "
            "T19999 → T0");
}

TEST(Structure, DepthLimit) {
  // Built in memory: the XML reader refuses such depth before this check could see it.
  TreeDef tree;
  tree.id = "Deep";
  tree.file = "deep.xml";
  Node* node = &tree.root;
  for (int depth = 1; depth <= 300; ++depth) {
    node->tag = depth == 300 ? "X" : "Inverter";
    node->line = depth;
    node->column = 1;
    if (depth < 300) node = &node->children.emplace_back();
  }
  const auto findings = check_structure({&tree}, {});
  const Finding f = only(findings, "nesting deeper than " + std::to_string(kMaxDepth) +
                                       " below <BehaviorTree>: its file would nest elements "
                                       "deeper than " +
                                       std::to_string(kMaxXmlDepth) +
                                       ", which tinyxml2 (BehaviorTree.CPP's XML parser) "
                                       "refuses; split the tree into SubTrees");
  EXPECT_EQ(f.location.line, kMaxDepth + 1);

  TreeDef ok;
  ok.id = "Ok";
  node = &ok.root;
  for (int depth = 1; depth <= kMaxDepth; ++depth) {
    node->tag = depth == kMaxDepth ? "X" : "Inverter";
    if (depth < kMaxDepth) node = &node->children.emplace_back();
  }
  EXPECT_TRUE(check_structure({&ok}, {}).empty());
}

TEST(Structure, AdaptableRules) {
  EXPECT_TRUE(
      check(in_tree("<Fallback><IsThere/><Adaptable ID=\"navigation\"/></Fallback>")).empty());
  only(check(in_tree("<Adaptable ID=\"nav\"><A/></Adaptable>")),
       "<Adaptable> must have no children, has 1");
  only(check(in_tree("<Adaptable/>")), "<Adaptable> needs an ID");
  only(check(in_tree("<Adaptable ID=\"a b\"/>")),
       "invalid adaptable ID 'a b': IDs must not be empty or contain space, tab, newline or any "
       "of < > & \" ' / \\ : * ? | .");
  StructureOptions compiled;
  compiled.allow_adaptable = false;
  only(check(in_tree("<Adaptable ID=\"nav\"/>"), compiled),
       "<Adaptable ID=\"nav\"> left in a compiled tree: compilation replaces every adaptable node");
}

TEST(Structure, IdRules) {
  only(check(in_tree("<A/>", "a b")),
       "invalid tree ID 'a b': IDs must not be empty or contain space, tab, newline or any of "
       "< > & \" ' / \\ : * ? | .");
  only(check(in_tree("<A/>", "nav.main")),
       "invalid tree ID 'nav.main': IDs must not be empty or contain space, tab, newline or any "
       "of < > & \" ' / \\ : * ? | .");
  only(check(in_tree("<Action ID=\"Go:Now\"/>")),
       "invalid ID 'Go:Now': IDs must not be empty or contain space, tab, newline or any of "
       "< > & \" ' / \\ : * ? | .");
  only(check(in_tree("<Go.Now/>")),
       "invalid ID 'Go.Now': IDs must not be empty or contain space, tab, newline or any of "
       "< > & \" ' / \\ : * ? | .");
  only(check(in_tree("<Action/>")), "<Action> needs an ID");
  only(check("<root><BehaviorTree><A/></BehaviorTree></root>"), "<BehaviorTree> needs an ID");
  EXPECT_TRUE(check(in_tree("<Go_Now-2/>", "tree_1-x")).empty());
}

TEST(Structure, TreeIdMustNotBeARegisteredNodeName) {
  only(check(in_tree("<A/>", "Sequence")),
       "a tree ID must not equal a registered node name 'Sequence'");
  StructureOptions robot;
  robot.known_nodes = {"MoveForward"};
  robot.known_nodes_given = true;
  only(check(in_tree("<A/>", "MoveForward"), robot),
       "a tree ID must not equal a registered node name 'MoveForward'");
  EXPECT_TRUE(check(in_tree("<A/>", "MoveForward")).empty());  // nodes.xml not given
}

TEST(Structure, DuplicateTreeIds) {
  const auto findings = check(
      "<root>\n<BehaviorTree ID=\"A\"><X/></BehaviorTree>\n"
      "<BehaviorTree ID=\"A\"><Y/></BehaviorTree></root>");
  const Finding f = only(findings, "tree ID 'A' is defined more than once (first at s.xml:2)");
  EXPECT_EQ(f.location.line, 3);
}

TEST(Structure, FindingsAreSortedAndComplete) {
  const auto findings = check(
      "<root>\n"
      "<BehaviorTree ID=\"T\">\n"
      "  <Sequence>\n"
      "    <Inverter/>\n"
      "    <SubTree ID=\"missing\"/>\n"
      "    <Stop><X/></Stop>\n"
      "  </Sequence>\n"
      "</BehaviorTree></root>");
  ASSERT_EQ(findings.size(), 3u) << describe(findings);
  EXPECT_EQ(findings[0].location.line, 4);
  EXPECT_EQ(findings[1].location.line, 5);
  EXPECT_EQ(findings[2].location.line, 6);
  EXPECT_EQ(findings[2].message,
            "Stop is a leaf (an action or condition) and must have no children, has 1");
  EXPECT_EQ(check_structure({}, {}).size(), 0u);
}

}  // namespace
}  // namespace uabt::bt
