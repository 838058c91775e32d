// The paper's replication package, read as it is (BT.CPP v3, CRLF, a tree on one line).
#include <gtest/gtest.h>

#include "bt/structure.hpp"
#include "bt/xml_io.hpp"
#include "bt_test_util.hpp"
#include "test_support.hpp"

namespace uabt::bt {
namespace {

using testing::describe;

class Replication : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = uabt::testing::replication_dir();
    if (!std::filesystem::is_directory(dir_)) GTEST_SKIP() << "replication package not present";
  }

  Document read(const std::string& relative) {
    std::vector<Finding> findings;
    ReadOptions options;
    options.confine_to = dir_;
    std::optional<Document> doc = read_document(dir_ / relative, options, findings);
    EXPECT_TRUE(findings.empty()) << describe(findings);
    EXPECT_TRUE(doc.has_value());
    return doc ? *doc : Document{};
  }

  std::filesystem::path dir_;
};

TEST_F(Replication, MissionIsVersion3WithAnAdaptableLeaf) {
  const Document doc = read("mission/mission.xml");
  EXPECT_EQ(doc.file, "mission/mission.xml");
  EXPECT_EQ(doc.format, 3);
  EXPECT_EQ(doc.main_tree, "MainTree");
  ASSERT_EQ(doc.trees.size(), 1u);
  const TreeDef* main = doc.main();
  ASSERT_NE(main, nullptr);
  EXPECT_EQ(main->id, "MainTree");
  EXPECT_EQ(main->file, "mission/mission.xml");
  EXPECT_EQ(main->line, 2);
  EXPECT_EQ(main->column, 5);
  const Node& root = main->root;
  EXPECT_EQ(root.tag, "Sequence");
  ASSERT_EQ(root.children.size(), 3u);
  const Node& adaptable = root.children[0].children[1];
  EXPECT_EQ(adaptable.tag, "Adaptable");
  ASSERT_NE(adaptable.attribute("ID"), nullptr);
  EXPECT_EQ(*adaptable.attribute("ID"), "navigation");
  EXPECT_EQ(adaptable.line, 6);
  EXPECT_EQ(adaptable.column, 17);
  const Node& drilling = root.children[2].children[0].children[0];
  EXPECT_EQ(drilling.kind(), "IsArmInPosition");
  ASSERT_EQ(drilling.attributes.size(), 1u);
  EXPECT_EQ(drilling.attributes[0].first, "function");
  EXPECT_EQ(drilling.attributes[0].second, "drilling");
  EXPECT_TRUE(check_structure({main}, StructureOptions{}).empty());
}

TEST_F(Replication, Alt1IsCrlfAndItsMainTreeIsTheOnlyTree) {
  const Document doc = read("resource/navigation/alt1/alt1.xml");
  EXPECT_EQ(doc.main_tree, "MainTree");  // as written, though no tree has that ID
  const TreeDef* main = doc.main();
  ASSERT_NE(main, nullptr);
  EXPECT_EQ(main->id, "dust_terrain");
  const Node& move = main->root.children[1];
  EXPECT_EQ(move.tag, "MoveForward");
  EXPECT_EQ(move.line, 8);
  EXPECT_EQ(move.column, 13);
  ASSERT_EQ(move.attributes.size(), 2u);
  EXPECT_EQ(move.attributes[0], (std::pair<std::string, std::string>{"time", "2"}));
  EXPECT_EQ(move.attributes[1], (std::pair<std::string, std::string>{"speed", "2.0"}));
  for (const auto& [name, value] : move.attributes) {
    EXPECT_EQ(value.find('\r'), std::string::npos) << name;
  }
}

TEST_F(Replication, Alt2HasSpacesAroundEqualsAndTabs) {
  const Document doc = read("resource/navigation/alt2/alt2.xml");
  EXPECT_EQ(doc.main_tree, "MainTree");
  const TreeDef* main = doc.main();
  ASSERT_NE(main, nullptr);
  EXPECT_EQ(main->id, "rock_terrain");
  EXPECT_EQ(main->column, 2);  // after one tab
  const Node& inverter = main->root.children[0].children[0];
  EXPECT_EQ(inverter.tag, "Inverter");
  EXPECT_EQ(inverter.line, 5);
  EXPECT_EQ(inverter.column, 5);
  EXPECT_EQ(inverter.children[0].tag, "IsTowardObject");
  EXPECT_TRUE(check_structure({main}, StructureOptions{}).empty());
}

TEST_F(Replication, ConcreteMissionHasTreesOnOneLine) {
  const Document doc = read("output/concrete_mission.xml");
  std::vector<std::string> ids;
  for (const TreeDef& tree : doc.trees) ids.push_back(tree.id);
  const std::vector<std::string> expected = {"MainTree",     "navigation",
                                             "dust_terrain", "adapt1_alt1_conditions",
                                             "rock_terrain", "adapt1_alt2_conditions"};
  EXPECT_EQ(ids, expected);
  // Line 33: <BehaviorTree ID="navigation"><Fallback><Sequence><SubTree ID="adapt1_alt1_conditions"
  // />… (columns computed independently from the raw file)
  const TreeDef* navigation = doc.find_tree("navigation");
  ASSERT_NE(navigation, nullptr);
  EXPECT_EQ(navigation->line, 33);
  EXPECT_EQ(navigation->column, 1);
  const Node& fallback = navigation->root;
  EXPECT_EQ(fallback.line, 33);
  EXPECT_EQ(fallback.column, 31);
  const Node& first = fallback.children[0];
  EXPECT_EQ(first.column, 41);
  EXPECT_EQ(first.children[0].column, 51);
  EXPECT_EQ(first.children[1].column, 90);
  const Node& second = fallback.children[1];
  EXPECT_EQ(second.column, 130);
  EXPECT_EQ(second.children[0].column, 140);
  EXPECT_EQ(second.children[1].column, 179);
  EXPECT_EQ(*second.children[1].attribute("ID"), "rock_terrain");
  const TreeDef* dust = doc.find_tree("dust_terrain");
  ASSERT_NE(dust, nullptr);
  EXPECT_EQ(dust->line, 33);
  EXPECT_EQ(dust->column, 245);
  EXPECT_EQ(dust->root.line, 34);
  EXPECT_EQ(dust->root.column, 9);

  std::vector<const TreeDef*> trees;
  for (const TreeDef& tree : doc.trees) trees.push_back(&tree);
  StructureOptions compiled;
  compiled.allow_adaptable = false;
  EXPECT_TRUE(check_structure(trees, compiled).empty());
}

TEST_F(Replication, ConcreteMissionRoundTrips) {
  const Document doc = read("output/concrete_mission.xml");
  const std::string written = write_document(doc);
  std::vector<Finding> findings;
  const std::optional<Document> again = parse_document(written, "again.xml", findings);
  ASSERT_TRUE(again.has_value()) << describe(findings);
  EXPECT_TRUE(findings.empty()) << describe(findings);
  ASSERT_EQ(again->trees.size(), doc.trees.size());
  for (std::size_t i = 0; i < doc.trees.size(); ++i) {
    EXPECT_EQ(again->trees[i].id, doc.trees[i].id);
    EXPECT_EQ(again->trees[i].root, doc.trees[i].root) << doc.trees[i].id;
  }
  EXPECT_EQ(again->format, 4);
  EXPECT_EQ(again->main_tree, "MainTree");
  EXPECT_EQ(write_document(*again), written);
}

}  // namespace
}  // namespace uabt::bt
