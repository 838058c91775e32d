// <include path="…">: relative to the including file, confined, acyclic.
#include <gtest/gtest.h>

#include "bt/xml_io.hpp"
#include "bt_test_util.hpp"

namespace uabt::bt {
namespace {

using testing::describe;
using testing::TempDir;

std::string tree(const std::string& id) {
  return "<BehaviorTree ID=\"" + id + "\"><Do" + id + "/></BehaviorTree>";
}

std::optional<Document> read(const TempDir& dir, const std::string& file,
                             std::vector<Finding>& findings, const std::string& confine = "") {
  ReadOptions options;
  options.confine_to = dir.path() / confine;
  options.display_base = dir.path();
  return read_document(dir.path() / file, options, findings);
}

TEST(Include, TreesAreInsertedWhereTheIncludeStands) {
  TempDir dir;
  dir.write("mission.xml", "<root main_tree_to_execute=\"Main\">\n" + tree("Main") +
                               "\n  <include path=\"lib/nav.xml\"/>\n" + tree("Last") + "</root>");
  dir.write("lib/nav.xml", "<root>\n<include path=\"deeper/util.xml\"/>\n" + tree("Nav") +
                               "<TreeNodesModel><Action ID=\"DoNav\"/></TreeNodesModel></root>");
  dir.write("lib/deeper/util.xml", "<root>" + tree("Util") + "</root>");
  std::vector<Finding> findings;
  const auto doc = read(dir, "mission.xml", findings);
  ASSERT_TRUE(doc.has_value());
  EXPECT_TRUE(findings.empty()) << describe(findings);
  std::vector<std::string> ids, files;
  for (const TreeDef& t : doc->trees) {
    ids.push_back(t.id);
    files.push_back(t.file);
  }
  EXPECT_EQ(ids, (std::vector<std::string>{"Main", "Util", "Nav", "Last"}));
  EXPECT_EQ(files, (std::vector<std::string>{"mission.xml", "lib/deeper/util.xml", "lib/nav.xml",
                                             "mission.xml"}));
  EXPECT_EQ(doc->file, "mission.xml");
  EXPECT_EQ(doc->find_tree("Nav")->line, 3);
  ASSERT_EQ(doc->node_models.size(), 1u);
  EXPECT_EQ(doc->node_models[0].id, "DoNav");
}

TEST(Include, EscapingTheMissionDirectory) {
  TempDir dir;
  dir.write("outside.xml", "<root>" + tree("Out") + "</root>");
  dir.write("m/mission.xml",
            "<root>" + tree("Main") + "\n<include path=\"../outside.xml\"/></root>");
  std::vector<Finding> findings;
  const auto doc = read(dir, "m/mission.xml", findings, "m");
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].check, "bt-structure");
  EXPECT_EQ(findings[0].message, "include path '../outside.xml' leaves the mission directory");
  EXPECT_EQ(findings[0].location.file, "m/mission.xml");
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_EQ(findings[0].location.column, 1);
  EXPECT_EQ(doc->trees.size(), 1u);
}

TEST(Include, SymlinkOutOfTheMissionDirectory) {
  TempDir dir;
  dir.write("outside.xml", "<root>" + tree("Out") + "</root>");
  dir.write("m/mission.xml", "<root>" + tree("Main") + "<include path=\"link.xml\"/></root>");
  std::error_code ec;
  std::filesystem::create_symlink(dir.path() / "outside.xml", dir.path() / "m/link.xml", ec);
  if (ec) GTEST_SKIP() << "cannot create symlinks here";
  std::vector<Finding> findings;
  const auto doc = read(dir, "m/mission.xml", findings, "m");
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_NE(findings[0].message.find("leaves the mission directory"), std::string::npos);
}

TEST(Include, AbsoluteMissingAndWithoutPath) {
  TempDir dir;
  const std::string absolute = (dir.path() / "lib.xml").generic_string();
  dir.write("lib.xml", "<root>" + tree("Lib") + "</root>");
  dir.write("mission.xml", "<root>" + tree("Main") + "\n<include path=\"" + absolute +
                               "\"/>\n<include path=\"nope.xml\"/>\n<include/>\n"
                               "<include ros_pkg=\"pkg\" path=\"lib.xml\"/></root>");
  std::vector<Finding> findings;
  const auto doc = read(dir, "mission.xml", findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 4u) << describe(findings);
  sort_findings(findings);
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_NE(findings[0].message.find("is absolute"), std::string::npos);
  EXPECT_EQ(findings[1].location.line, 3);
  EXPECT_EQ(findings[1].message, "included file 'nope.xml' does not exist");
  EXPECT_EQ(findings[2].location.line, 4);
  EXPECT_EQ(findings[2].message, "<include> needs a path attribute");
  EXPECT_EQ(findings[3].location.line, 5);
  EXPECT_NE(findings[3].message.find("ros_pkg"), std::string::npos);
  for (const Finding& f : findings) EXPECT_EQ(f.check, "bt-structure");
  EXPECT_EQ(doc->trees.size(), 1u);
}

TEST(Include, CycleIsDetected) {
  TempDir dir;
  dir.write("a.xml", "<root>" + tree("A") + "<include path=\"sub/b.xml\"/></root>");
  dir.write("sub/b.xml", "<root>" + tree("B") + "\n<include path=\"../a.xml\"/></root>");
  std::vector<Finding> findings;
  const auto doc = read(dir, "a.xml", findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].message, "include cycle: a.xml → sub/b.xml → a.xml");
  EXPECT_EQ(findings[0].location.file, "sub/b.xml");
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_EQ(doc->trees.size(), 2u);
}

TEST(Include, SelfIncludeAndDiamond) {
  TempDir dir;
  dir.write("self.xml", "<root>" + tree("S") + "<include path=\"./self.xml\"/></root>");
  std::vector<Finding> findings;
  ASSERT_TRUE(read(dir, "self.xml", findings).has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].message, "include cycle: self.xml → self.xml");

  dir.write("top.xml",
            "<root>" + tree("Top") + "<include path=\"l.xml\"/><include path=\"r.xml\"/></root>");
  dir.write("l.xml", "<root><include path=\"shared.xml\"/>" + tree("L") + "</root>");
  dir.write("r.xml", "<root><include path=\"shared.xml\"/>" + tree("R") + "</root>");
  dir.write("shared.xml", "<root>" + tree("Shared") + "</root>");
  findings.clear();
  const auto doc = read(dir, "top.xml", findings);
  ASSERT_TRUE(doc.has_value());
  EXPECT_TRUE(findings.empty()) << describe(findings);
  std::vector<std::string> ids;
  for (const TreeDef& t : doc->trees) ids.push_back(t.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"Top", "Shared", "L", "R"}));
}

TEST(Include, BrokenIncludedFileReportsItsOwnLocation) {
  TempDir dir;
  dir.write("mission.xml", "<root>" + tree("Main") + "<include path=\"bad.xml\"/></root>");
  dir.write("bad.xml", "<root>\n<BehaviorTree ID=\"X\"><A></BehaviorTree></root>");
  std::vector<Finding> findings;
  const auto doc = read(dir, "mission.xml", findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].check, "bt-xml");
  EXPECT_EQ(findings[0].location.file, "bad.xml");
  EXPECT_EQ(findings[0].location.line, 2);
}

TEST(Include, TextInMemoryCannotInclude) {
  std::vector<Finding> findings;
  const auto doc = parse_document("<root>" + tree("A") + "<include path=\"x.xml\"/></root>",
                                  "mem.xml", findings);
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].check, "bt-structure");
  EXPECT_EQ(findings[0].location.file, "mem.xml");
}

}  // namespace
}  // namespace uabt::bt
