// write_document: golden bytes for v4 and v3, escaping, round trips, node models.
#include <gtest/gtest.h>

#include "bt/xml_io.hpp"
#include "bt_test_util.hpp"

namespace uabt::bt {
namespace {

using testing::describe;
using testing::parse_clean;

Node leaf(const std::string& tag,
          std::vector<std::pair<std::string, std::string>> attributes = {}) {
  Node node;
  node.tag = tag;
  node.attributes = std::move(attributes);
  return node;
}

Node parent(const std::string& tag, std::vector<Node> children,
            std::vector<std::pair<std::string, std::string>> attributes = {}) {
  Node node = leaf(tag, std::move(attributes));
  node.children = std::move(children);
  return node;
}

Document small_document() {
  Document doc;
  doc.main_tree = "MainTree";
  TreeDef main;
  main.id = "MainTree";
  main.root =
      parent("Sequence",
             {parent("Fallback", {leaf("IsInLocation"),
                                  leaf("SubTree", {{"ID", "navigation"}, {"_autoremap", "true"}})}),
              leaf("ScriptCondition", {{"code", "battery < 20 && terrain == 'rocks'"}}),
              leaf("Action", {{"ID", "MoveForward"}, {"speed", "2.0"}, {"time", "2"}}),
              leaf("OnDust"), leaf("Drill", {{"name", "drill \"deep\""}, {"depth", "3"}}),
              leaf("MoveForward", {{"speed", "1"}, {"heading", "{goal}"}})},
             {{"name", "root_sequence"}});
  TreeDef navigation;
  navigation.id = "navigation";
  navigation.root = parent("Inverter", {leaf("Condition", {{"ID", "IsRockAtLeft"}})});
  doc.trees = {main, navigation};
  return doc;
}

const char* const kGoldenV4 =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence name="root_sequence">
      <Fallback>
        <IsInLocation/>
        <SubTree ID="navigation" _autoremap="true"/>
      </Fallback>
      <ScriptCondition code="battery &lt; 20 &amp;&amp; terrain == 'rocks'"/>
      <MoveForward speed="2.0" time="2"/>
      <OnDust/>
      <Drill name="drill &quot;deep&quot;" depth="3"/>
      <MoveForward speed="1" heading="{goal}"/>
    </Sequence>
  </BehaviorTree>
  <BehaviorTree ID="navigation">
    <Inverter>
      <IsRockAtLeft/>
    </Inverter>
  </BehaviorTree>
  <TreeNodesModel>
    <Action ID="Drill">
      <input_port name="depth"/>
    </Action>
    <Condition ID="IsInLocation"/>
    <Condition ID="IsRockAtLeft"/>
    <Action ID="MoveForward">
      <input_port name="heading"/>
      <input_port name="speed"/>
      <input_port name="time"/>
    </Action>
    <Condition ID="OnDust"/>
  </TreeNodesModel>
</root>
)";

const char* const kGoldenV3 =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<root main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence name="root_sequence">
      <Fallback>
        <IsInLocation/>
        <SubTree ID="navigation" _autoremap="true"/>
      </Fallback>
      <ScriptCondition code="battery &lt; 20 &amp;&amp; terrain == 'rocks'"/>
      <MoveForward speed="2.0" time="2"/>
      <OnDust/>
      <Drill name="drill &quot;deep&quot;" depth="3"/>
      <MoveForward speed="1" heading="{goal}"/>
    </Sequence>
  </BehaviorTree>
  <BehaviorTree ID="navigation">
    <Inverter>
      <IsRockAtLeft/>
    </Inverter>
  </BehaviorTree>
</root>
)";

TEST(Writer, GoldenVersion4) {
  EXPECT_EQ(write_document(small_document()), kGoldenV4);
}

TEST(Writer, GoldenVersion3WithoutModels) {
  WriteOptions options;
  options.format = 3;
  options.with_node_models = false;
  EXPECT_EQ(write_document(small_document(), options), kGoldenV3);
}

TEST(Writer, ModelsComeFromTheDocumentWhenKnown) {
  Document doc = small_document();
  NodeModel model;
  model.family = "Action";
  model.id = "OnDust";  // a name that looks like a condition, declared as an action
  model.ports = {Port{"output_port", "level", "int", "", "dust level"}};
  NodeModel unused;
  unused.family = "Decorator";
  unused.id = "Throttle";
  NodeModel builtin;
  builtin.family = "Control";
  builtin.id = "Sequence";
  doc.node_models = {model, unused, builtin};
  const std::string out = write_document(doc);
  EXPECT_NE(out.find("    <Action ID=\"OnDust\">\n"
                     "      <output_port name=\"level\" type=\"int\">dust level</output_port>\n"
                     "    </Action>\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("    <Decorator ID=\"Throttle\"/>\n"), std::string::npos) << out;
  EXPECT_EQ(out.find("ID=\"Sequence\""), std::string::npos) << out;
}

TEST(Writer, FamilyGuesses) {
  const Document doc = parse_clean(
      "<root><BehaviorTree ID=\"A\"><Sequence>"
      "<HasFuel/><CanDrive/><CheckArm/><Onward/><Island/><Open/>"
      "<Guard><X/></Guard><Both><X/><Y/></Both><Condition ID=\"Odd\"/><SubTree ID=\"A\"/>"
      "<Adaptable ID=\"nav\"/></Sequence></BehaviorTree></root>");
  const std::string out = write_document(doc);
  const std::string models = out.substr(out.find("<TreeNodesModel>"));
  EXPECT_EQ(models,
            "<TreeNodesModel>\n"
            "    <Control ID=\"Both\"/>\n"
            "    <Condition ID=\"CanDrive\"/>\n"
            "    <Condition ID=\"CheckArm\"/>\n"
            "    <Decorator ID=\"Guard\"/>\n"
            "    <Condition ID=\"HasFuel\"/>\n"
            "    <Action ID=\"Island\"/>\n"
            "    <Condition ID=\"Odd\"/>\n"
            "    <Action ID=\"Onward\"/>\n"
            "    <Action ID=\"Open\"/>\n"
            "    <Action ID=\"X\"/>\n"
            "    <Action ID=\"Y\"/>\n"
            "  </TreeNodesModel>\n"
            "</root>\n");
}

TEST(Writer, ReservedAttributesAreNotPorts) {
  const Document doc = parse_clean(
      "<root><BehaviorTree ID=\"A\"><Drive name=\"d\" _skipIf=\"x\" _onSuccess=\"y\" "
      "__shared_blackboard=\"true\" speed=\"1\"/></BehaviorTree></root>");
  const std::string out = write_document(doc);
  EXPECT_NE(
      out.find("    <Action ID=\"Drive\">\n      <input_port name=\"speed\"/>\n    </Action>"),
      std::string::npos)
      << out;
}

TEST(Writer, ExplicitSyntaxIsCompactedOnlyForIdsThatAreXmlNames) {
  Document doc;
  TreeDef tree;
  tree.id = "A";
  tree.root = parent("Sequence", {leaf("Action", {{"ID", "MoveBase"}, {"goal", "1"}}),
                                  parent("Decorator", {leaf("AlwaysSuccess")}, {{"ID", "Cu<x"}}),
                                  leaf("Condition", {{"ID", "2fast"}})});
  doc.trees = {tree};
  const std::string out = write_document(doc, {4, false});
  EXPECT_NE(out.find("<MoveBase goal=\"1\"/>"), std::string::npos) << out;
  EXPECT_NE(out.find("<Decorator ID=\"Cu&lt;x\">"), std::string::npos) << out;
  EXPECT_NE(out.find("</Decorator>"), std::string::npos) << out;
  EXPECT_NE(out.find("<Condition ID=\"2fast\"/>"), std::string::npos) << out;
  std::vector<Finding> findings;
  const auto again = parse_document(out, "again.xml", findings);
  ASSERT_TRUE(again.has_value()) << out;
  const Node& root = again->trees.at(0).root;
  ASSERT_EQ(root.children.size(), 3u);
  EXPECT_EQ(root.children[0].kind(), "MoveBase");
  EXPECT_EQ(root.children[1].kind(), "Cu<x");
  EXPECT_EQ(root.children[2].kind(), "2fast");
}

TEST(Writer, EscapingRoundTrips) {
  Document doc;
  TreeDef tree;
  tree.id = "A";
  const std::string nasty = "a < b && c > d \"q\" 'single' tab\there\nnewline\r\n&amp; ünï";
  tree.root = leaf("Script", {{"code", nasty}});
  doc.trees = {tree};
  const std::string out = write_document(doc);
  EXPECT_NE(out.find("code=\"a &lt; b &amp;&amp; c &gt; d &quot;q&quot; 'single' "
                     "tab&#9;here&#10;newline&#13;&#10;&amp;amp; ünï\""),
            std::string::npos)
      << out;
  const Document again = parse_clean(out);
  EXPECT_EQ(*again.trees.at(0).root.attribute("code"), nasty);
}

TEST(Writer, RoundTripReadWriteRead) {
  const std::string source =
      "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\r\n"
      "  <BehaviorTree ID=\"Main\"><ReactiveSequence><IsSafe/>"
      "<RetryUntilSuccessful num_attempts=\"3\"><Drive speed=\"{v}\"/></RetryUntilSuccessful>"
      "<SubTree ID=\"Other\" _autoremap=\"true\"/></ReactiveSequence></BehaviorTree>\r\n"
      "  <BehaviorTree ID=\"Other\"><AlwaysSuccess/></BehaviorTree>\r\n"
      "  <TreeNodesModel><Condition ID=\"IsSafe\"/>"
      "<Action ID=\"Drive\"><input_port name=\"speed\" "
      "type=\"double\"/></Action></TreeNodesModel>\r\n"
      "</root>\r\n";
  const Document first = parse_clean(source);
  const std::string written = write_document(first);
  const Document second = parse_clean(written);
  ASSERT_EQ(second.trees.size(), first.trees.size());
  for (std::size_t i = 0; i < first.trees.size(); ++i) {
    EXPECT_EQ(second.trees[i].id, first.trees[i].id);
    EXPECT_EQ(second.trees[i].root, first.trees[i].root);
  }
  EXPECT_EQ(second.main_tree, first.main_tree);
  EXPECT_EQ(second.format, 4);
  ASSERT_EQ(second.node_models.size(), 2u);
  EXPECT_EQ(second.node_models[0].id, "Drive");
  EXPECT_EQ(second.node_models[0].ports.at(0).type, "double");
  EXPECT_EQ(write_document(second), written);  // a fixed point
  EXPECT_EQ(written.find('\r'), std::string::npos);
}

TEST(Writer, ExplicitSyntaxIsWrittenCompact) {
  const Document doc = parse_clean(
      "<root BTCPP_format=\"4\"><BehaviorTree ID=\"A\"><Control ID=\"ReactiveSequence\">"
      "<Condition ID=\"IsSafe\" name=\"safe\"/><Action "
      "ID=\"Go\"/></Control></BehaviorTree></root>");
  const std::string out = write_document(doc, WriteOptions{4, false});
  EXPECT_EQ(out,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n"
            "  <BehaviorTree ID=\"A\">\n"
            "    <ReactiveSequence>\n"
            "      <IsSafe name=\"safe\"/>\n"
            "      <Go/>\n"
            "    </ReactiveSequence>\n"
            "  </BehaviorTree>\n"
            "</root>\n");
}

TEST(Writer, MainTreeIsTheTreeThatRuns) {
  // The paper's files name "MainTree" but hold only dust_terrain.
  const Document doc = parse_clean(
      "<root main_tree_to_execute=\"MainTree\"><BehaviorTree ID=\"dust_terrain\"><Stop/>"
      "</BehaviorTree></root>");
  EXPECT_NE(
      write_document(doc).find("<root BTCPP_format=\"4\" main_tree_to_execute=\"dust_terrain\">"),
      std::string::npos);
  Document two = parse_clean(
      "<root><BehaviorTree ID=\"A\"><Stop/></BehaviorTree><BehaviorTree ID=\"B\"><Stop/>"
      "</BehaviorTree></root>");
  EXPECT_NE(write_document(two).find("<root BTCPP_format=\"4\">\n"), std::string::npos);
}

TEST(Writer, EmptyTreeIsSelfClosing) {
  Document doc;
  TreeDef tree;
  tree.id = "Empty";
  doc.trees = {tree};
  EXPECT_EQ(write_document(doc),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"Empty\">\n"
            "  <BehaviorTree ID=\"Empty\"/>\n"
            "</root>\n");
}

}  // namespace
}  // namespace uabt::bt
