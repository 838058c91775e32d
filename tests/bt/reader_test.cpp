// Reading BT.CPP v3/v4 XML: syntax forms, positions, attributes, models.
#include <gtest/gtest.h>

#include "bt/xml_io.hpp"
#include "bt_test_util.hpp"

namespace uabt::bt {
namespace {

using testing::describe;
using testing::parse_clean;
using testing::with_check;

TEST(Reader, Version4CompactSyntax) {
  const Document doc = parse_clean(
      "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n"
      "  <BehaviorTree ID=\"Main\">\n"
      "    <Sequence name=\"s\">\n"
      "      <MoveForward speed=\"2\" time=\"{t}\"/>\n"
      "      <IsInLocation/>\n"
      "    </Sequence>\n"
      "  </BehaviorTree>\n"
      "</root>\n");
  EXPECT_EQ(doc.format, 4);
  EXPECT_EQ(doc.main_tree, "Main");
  EXPECT_EQ(doc.root_line, 1);
  ASSERT_NE(doc.main(), nullptr);
  const Node& seq = doc.main()->root;
  EXPECT_EQ(seq.tag, "Sequence");
  EXPECT_EQ(seq.line, 3);
  EXPECT_EQ(seq.column, 5);
  ASSERT_EQ(seq.children.size(), 2u);
  const Node& move = seq.children[0];
  EXPECT_EQ(move.kind(), "MoveForward");
  const std::vector<std::pair<std::string, std::string>> attributes = {{"speed", "2"},
                                                                       {"time", "{t}"}};
  EXPECT_EQ(move.attributes, attributes);
  EXPECT_EQ(move.line, 4);
  EXPECT_EQ(move.column, 7);
}

TEST(Reader, Version4ExplicitSyntaxKeepsTheTag) {
  const Document doc = parse_clean(
      "<root BTCPP_format=\"4\">\n"
      "  <BehaviorTree ID=\"Main\">\n"
      "    <Control ID=\"Sequence\">\n"
      "      <Condition ID=\"IsInLocation\" name=\"here\"/>\n"
      "      <Action ID=\"MoveForward\" speed=\"2\"/>\n"
      "      <Decorator ID=\"Inverter\"><Condition ID=\"OnDust\"/></Decorator>\n"
      "      <SubTree ID=\"Other\"/>\n"
      "    </Control>\n"
      "  </BehaviorTree>\n"
      "  <BehaviorTree ID=\"Other\"><AlwaysSuccess/></BehaviorTree>\n"
      "</root>\n");
  ASSERT_EQ(doc.trees.size(), 2u);
  EXPECT_EQ(doc.main(), nullptr);  // two trees, no main_tree_to_execute
  const Node& control = doc.trees[0].root;
  EXPECT_EQ(control.tag, "Control");
  EXPECT_EQ(control.kind(), "Sequence");
  EXPECT_EQ(control.children[0].tag, "Condition");
  EXPECT_EQ(control.children[0].kind(), "IsInLocation");
  EXPECT_EQ(control.children[1].kind(), "MoveForward");
  EXPECT_EQ(control.children[2].kind(), "Inverter");
  EXPECT_EQ(control.children[2].children[0].kind(), "OnDust");
  EXPECT_EQ(control.children[2].children[0].column, 32);
  EXPECT_EQ(control.children[3].kind(), "SubTree");  // SubTree's ID is its target, not its kind
  EXPECT_EQ(doc.trees[1].root.line, 10);
  EXPECT_EQ(doc.trees[1].root.column, 28);
}

TEST(Reader, FormatThreeWhenBtcppFormatIsAbsent) {
  const Document doc = parse_clean("<root><BehaviorTree ID=\"A\"><Stop/></BehaviorTree></root>");
  EXPECT_EQ(doc.format, 3);
  EXPECT_EQ(doc.main_tree, "");
  ASSERT_NE(doc.main(), nullptr);
  EXPECT_EQ(doc.main()->id, "A");
  EXPECT_EQ(parse_clean("<root BTCPP_format=\"3\"><BehaviorTree ID=\"A\"><Stop/></BehaviorTree>"
                        "</root>")
                .format,
            3);
}

TEST(Reader, UnsupportedFormatIsAFinding) {
  std::vector<Finding> findings;
  const auto doc = parse_document(
      "<root BTCPP_format=\"5\">\n<BehaviorTree ID=\"A\"><Stop/></BehaviorTree></root>", "f.xml",
      findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].check, "bt-xml");
  EXPECT_EQ(findings[0].message, "BTCPP_format must be 3 or 4, found '5'");
  EXPECT_EQ(findings[0].location.file, "f.xml");
  EXPECT_EQ(findings[0].location.line, 1);
  EXPECT_EQ(findings[0].location.column, 1);
}

TEST(Reader, MainTreeToExecuteWins) {
  const Document doc = parse_clean(
      "<root main_tree_to_execute = \"B\"><BehaviorTree ID=\"A\"><Stop/></BehaviorTree>"
      "<BehaviorTree ID=\"B\"><Stop/></BehaviorTree></root>");
  ASSERT_NE(doc.main(), nullptr);
  EXPECT_EQ(doc.main()->id, "B");
}

// BT.CPP ignores a <root> attribute it does not know: a misspelt main_tree_to_execute would
// silently run another tree, so it is an error at the attribute, read as meant.
TEST(Reader, MisspeltMainTreeToExecuteIsAnErrorAtTheAttribute) {
  for (const std::string trees : {"<BehaviorTree ID=\"A\"><Stop/></BehaviorTree>",
                                  "<BehaviorTree ID=\"A\"><Stop/></BehaviorTree><BehaviorTree "
                                  "ID=\"B\"><Stop/></BehaviorTree>"}) {
    std::vector<Finding> findings;
    const auto doc = parse_document(
        "<root BTCPP_format=\"4\"\n      main_tree_to_exectue=\"A\">" + trees + "</root>", "f.xml",
        findings);
    ASSERT_TRUE(doc.has_value());
    ASSERT_EQ(findings.size(), 1u) << describe(findings);
    EXPECT_EQ(findings[0].check, "bt-structure");
    EXPECT_EQ(findings[0].severity, Severity::error);
    EXPECT_EQ(findings[0].message,
              "unknown attribute 'main_tree_to_exectue' on <root>: BehaviorTree.CPP ignores it; "
              "did you mean 'main_tree_to_execute'?");
    EXPECT_EQ(findings[0].location.line, 2);
    EXPECT_EQ(findings[0].location.column, 7);
    ASSERT_NE(doc->main(), nullptr);
    EXPECT_EQ(doc->main()->id, "A");
  }
  // An attribute that is no near miss is left alone, as BT.CPP does.
  parse_clean(
      "<root BTCPP_format=\"4\" author=\"me\"><BehaviorTree "
      "ID=\"A\"><Stop/></BehaviorTree></root>");
}

TEST(Reader, PositionsOnCrlfAndMultiNodeLines) {
  // A tab counts as one column; CR does not start a line.
  const Document doc = parse_clean(
      "<root>\r\n"
      "\t<BehaviorTree ID=\"A\">\r\n"
      "\t\t<Sequence><X/><Y a=\"&lt;\"/>  <X/><Sequence><X/></Sequence></Sequence>\r\n"
      "\t</BehaviorTree>\r\n"
      "</root>\r\n");
  const TreeDef& tree = doc.trees.at(0);
  EXPECT_EQ(tree.line, 2);
  EXPECT_EQ(tree.column, 2);
  const Node& seq = tree.root;
  EXPECT_EQ(seq.line, 3);
  EXPECT_EQ(seq.column, 3);
  ASSERT_EQ(seq.children.size(), 4u);
  EXPECT_EQ(seq.children[0].column, 13);
  EXPECT_EQ(seq.children[1].column, 17);
  EXPECT_EQ(*seq.children[1].attribute("a"), "<");
  EXPECT_EQ(seq.children[2].column, 32);
  EXPECT_EQ(seq.children[3].column, 36);
  EXPECT_EQ(seq.children[3].children[0].column, 46);
  for (const Node& child : seq.children) EXPECT_EQ(child.line, 3);
}

TEST(Reader, ColumnsCountCharactersNotBytes) {
  const Document doc = parse_clean(
      "<root><BehaviorTree ID=\"A\"><Sequence><Say text=\"ünï\"/><Stop/></Sequence>"
      "</BehaviorTree></root>");
  const Node& seq = doc.trees.at(0).root;
  EXPECT_EQ(seq.children[0].column, 38);
  EXPECT_EQ(seq.children[1].column, 55);  // "ünï" is 3 characters, 6 bytes
}

TEST(Reader, CommentsCdataAndDeclarationsDoNotShiftPositions) {
  const Document doc = parse_clean(
      "\xEF\xBB\xBF<?xml version=\"1.0\"?><!-- <Fake/> --><root><BehaviorTree ID=\"A\">"
      "<Sequence><![CDATA[ <Fake/> ]]><X/></Sequence></BehaviorTree></root>");
  const Node& seq = doc.trees.at(0).root;
  EXPECT_EQ(seq.column, 65);
  ASSERT_EQ(seq.children.size(), 1u);
  EXPECT_EQ(seq.children[0].tag, "X");
  EXPECT_EQ(seq.children[0].column, 96);
}

TEST(Reader, TreeNodesModel) {
  const Document doc = parse_clean(
      "<root BTCPP_format=\"4\">\n"
      "  <BehaviorTree ID=\"A\"><MoveForward speed=\"1\"/></BehaviorTree>\n"
      "  <TreeNodesModel>\n"
      "    <Action ID=\"MoveForward\">\n"
      "      <input_port name=\"speed\" type=\"double\" default=\"1.0\">m/s</input_port>\n"
      "      <output_port name=\"done\"/>\n"
      "      <inout_port name=\"pose\" type=\"Pose\"/>\n"
      "    </Action>\n"
      "    <Condition ID=\"OnDust\"/>\n"
      "    <Decorator ID=\"Limit\"/>\n"
      "    <Control ID=\"Mine\"/>\n"
      "    <SubTree ID=\"Sub\"/>\n"
      "  </TreeNodesModel>\n"
      "</root>\n");
  ASSERT_EQ(doc.node_models.size(), 5u);
  const NodeModel& move = doc.node_models[0];
  EXPECT_EQ(move.family, "Action");
  EXPECT_EQ(move.id, "MoveForward");
  EXPECT_EQ(move.line, 4);
  ASSERT_EQ(move.ports.size(), 3u);
  EXPECT_EQ(move.ports[0].direction, "input_port");
  EXPECT_EQ(move.ports[0].name, "speed");
  EXPECT_EQ(move.ports[0].type, "double");
  EXPECT_EQ(move.ports[0].default_value, "1.0");
  EXPECT_EQ(move.ports[0].description, "m/s");
  EXPECT_EQ(move.ports[1].direction, "output_port");
  EXPECT_EQ(move.ports[2].direction, "inout_port");
  EXPECT_EQ(move.ports[2].type, "Pose");
  EXPECT_EQ(doc.node_models[1].family, "Condition");
  EXPECT_EQ(doc.node_models[2].family, "Decorator");
  EXPECT_EQ(doc.node_models[3].family, "Control");
  EXPECT_EQ(doc.node_models[4].family, "SubTree");
}

TEST(Reader, TwoTreeNodesModelsAreAFinding) {
  std::vector<Finding> findings;
  const auto doc = parse_document(
      "<root><BehaviorTree ID=\"A\"><X/></BehaviorTree>\n<TreeNodesModel/>\n<TreeNodesModel/>"
      "</root>",
      "f.xml", findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].check, "bt-structure");
  EXPECT_EQ(findings[0].location.line, 3);
}

TEST(Reader, UnknownTopLevelElementIsAWarning) {
  std::vector<Finding> findings;
  const auto doc = parse_document(
      "<root>\n  <Tree ID=\"A\"/>\n  <BehaviorTree ID=\"A\"><X/></BehaviorTree></root>", "f.xml",
      findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].check, "bt-xml");
  EXPECT_EQ(findings[0].severity, Severity::warning);
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_EQ(findings[0].location.column, 3);
  EXPECT_EQ(doc->trees.size(), 1u);
}

TEST(Reader, DocumentElementMustBeRoot) {
  std::vector<Finding> findings;
  EXPECT_FALSE(parse_document("<BehaviorTree ID=\"A\"><X/></BehaviorTree>", "f.xml", findings));
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].message, "the document element must be <root>, found <BehaviorTree>");
}

TEST(Reader, SecondDocumentElementIsAFinding) {
  std::vector<Finding> findings;
  const auto doc = parse_document(
      "<root><BehaviorTree ID=\"A\"><X/></BehaviorTree></root>\n  <root/>", "f.xml", findings);
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].message, "only one document element is allowed; <root> follows </root>");
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_EQ(findings[0].location.column, 3);
}

TEST(Reader, NeverThrowsOnTruncatedInput) {
  // Every prefix of a valid file: a document or findings, never an exception or a crash.
  const std::string text =
      "<?xml version=\"1.0\"?>\n<root BTCPP_format=\"4\"><!-- c --><BehaviorTree ID=\"A\">"
      "<Sequence><X a=\"&lt;\"/><![CDATA[x]]><include path=\"p\"/></Sequence></BehaviorTree>"
      "<TreeNodesModel><Action ID=\"X\"><input_port name=\"a\">d</input_port></Action>"
      "</TreeNodesModel></root>";
  for (std::size_t n = 0; n <= text.size(); ++n) {
    std::vector<Finding> findings;
    std::optional<Document> doc;
    ASSERT_NO_THROW(doc = parse_document(text.substr(0, n), "t.xml", findings)) << n;
    EXPECT_TRUE(doc.has_value() || has_errors(findings)) << n;
  }
}

TEST(Reader, BehaviorTreeNeedsExactlyOneChild) {
  std::vector<Finding> findings;
  const auto doc = parse_document(
      "<root>\n<BehaviorTree ID=\"Empty\"/>\n<BehaviorTree ID=\"Two\"><A/><B/></BehaviorTree>"
      "</root>",
      "f.xml", findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(with_check(findings, "bt-structure").size(), 2u) << describe(findings);
  EXPECT_EQ(findings[0].message, "<BehaviorTree ID=\"Empty\"> must have exactly 1 child, has 0");
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_EQ(findings[1].message, "<BehaviorTree ID=\"Two\"> must have exactly 1 child, has 2");
  EXPECT_EQ(doc->trees[0].root.tag, "");
  EXPECT_EQ(doc->trees[1].root.tag, "A");  // the first child is kept
}

TEST(Reader, ScriptCodeIsUnescaped) {
  const Document doc = parse_clean(
      "<root><BehaviorTree ID=\"A\"><ScriptCondition code=\"battery &lt; 20 &amp;&amp; "
      "terrain == 'rocks'\"/></BehaviorTree></root>");
  EXPECT_EQ(*doc.trees[0].root.attribute("code"), "battery < 20 && terrain == 'rocks'");
}

}  // namespace
}  // namespace uabt::bt
