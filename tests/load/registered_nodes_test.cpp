#include <gtest/gtest.h>

#include "load/load_test_support.hpp"

namespace uabt::load {
namespace {

using namespace uabt::testing;

const std::string kNodes =
    "<root BTCPP_format=\"4\">\n<TreeNodesModel>\n"
    "  <Condition ID=\"OnDust\"/>\n"
    "  <Condition ID=\"OnRocks\"/>\n"
    "  <Action ID=\"Stop\"/>\n"
    "  <Action ID=\"MoveForward\">\n"
    "    <input_port name=\"speed\"/>\n"
    "    <input_port name=\"time\" default=\"10\"/>\n"
    "    <output_port name=\"distance\"/>\n"
    "  </Action>\n"
    "</TreeNodesModel>\n</root>\n";

std::map<std::string, std::string> files_with(const std::string& dust_body) {
  auto files = navigation_files(kTwoTerrains);
  files["nodes.xml"] = kNodes;
  files["alternatives/navigation/on_dust.xml"] = alternative_tree("on_dust", dust_body);
  return files;
}

TEST(RegisteredNodes, EveryNodeRegisteredWithItsPortsPasses) {
  TempMission dir(
      files_with("<Sequence>\n      <MoveForward speed=\"0.5\" name=\"drive\" _skipIf=\"false\"/>\n"
                 "      <Action ID=\"Stop\"/>\n    </Sequence>"));
  Mission m = load_dir(dir.dir());
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
}

TEST(RegisteredNodes, UnknownNodeInAnAlternative) {
  TempMission dir(files_with("<Sequence>\n      <MoveFoward speed=\"0.5\"/>\n    </Sequence>"));
  Mission m = load_dir(dir.dir());
  const auto unknown = with_check(m, "ref-unknown-node");
  ASSERT_EQ(unknown.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(unknown[0]->severity, Severity::error);
  EXPECT_EQ(unknown[0]->location.file, "alternatives/navigation/on_dust.xml");
  EXPECT_EQ(unknown[0]->location.line, 4);
  EXPECT_EQ(unknown[0]->notes, std::vector<std::string>{"did you mean 'MoveForward'?"});
}

TEST(RegisteredNodes, UnknownNodeInTheMissionTree) {
  auto files = files_with("<Stop/>");
  files["mission.xml"] = mission_with(
      "    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n      <TakePicture/>\n"
      "    </Sequence>");
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  const auto unknown = with_check(m, "ref-unknown-node");
  ASSERT_EQ(unknown.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(unknown[0]->location.file, "mission.xml");
  EXPECT_EQ(unknown[0]->location.line, 5);
  EXPECT_NE(unknown[0]->message.find("'TakePicture'"), std::string::npos);
}

TEST(RegisteredNodes, BuiltInNodesNeedNoRegistration) {
  TempMission dir(
      files_with("<Sequence>\n      <AlwaysSuccess/>\n      <Script code=\"x := 1\"/>\n"
                 "      <Repeat num_cycles=\"2\"><Stop/></Repeat>\n    </Sequence>"));
  Mission m = load_dir(dir.dir());
  EXPECT_TRUE(with_check(m, "ref-unknown-node").empty()) << format_text(m.findings);
  EXPECT_TRUE(with_check(m, "ref-unknown-port").empty()) << format_text(m.findings);
}

TEST(RegisteredNodes, UnknownPort) {
  TempMission dir(files_with("<MoveForward sped=\"0.5\" speed=\"1\"/>"));
  Mission m = load_dir(dir.dir());
  const auto port = with_check(m, "ref-unknown-port");
  ASSERT_EQ(port.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(port[0]->message,
            "'sped' is not a port of MoveForward in nodes.xml (its ports: speed, time, "
            "distance): BehaviorTree.CPP refuses to load the tree");
  EXPECT_EQ(port[0]->notes, std::vector<std::string>{"did you mean 'speed'?"});
}

TEST(RegisteredNodes, MissingRequiredInputPort) {
  TempMission dir(files_with("<MoveForward/>"));
  Mission m = load_dir(dir.dir());
  const auto missing = with_check(m, "ref-missing-port");
  ASSERT_EQ(missing.size(), 1u) << "only speed: time has a default, distance is an output\n"
                                << format_text(m.findings);
  EXPECT_EQ(missing[0]->severity, Severity::warning);
  EXPECT_EQ(missing[0]->message,
            "input port 'speed' of MoveForward is not set and nodes.xml gives it no default: "
            "the node fails when it reads it");
}

// BT.CPP refuses to register one ID twice: the second entry is the error, naming the first.
TEST(RegisteredNodes, DuplicateIdIsAnErrorAtTheSecond) {
  auto files = files_with("<Stop/>");
  files["nodes.xml"] =
      "<root BTCPP_format=\"4\">\n<TreeNodesModel>\n"
      "  <Condition ID=\"OnDust\"/>\n"
      "  <Condition ID=\"OnRocks\"/>\n"
      "  <Action ID=\"Stop\"/>\n"
      "    <Action ID=\"OnDust\"/>\n"
      "</TreeNodesModel>\n</root>\n";
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  const auto duplicate = with_check(m, "ref-duplicate-id");
  ASSERT_EQ(duplicate.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(duplicate[0]->severity, Severity::error);
  EXPECT_EQ(duplicate[0]->message, "node ID 'OnDust' is registered twice in nodes.xml");
  EXPECT_EQ(duplicate[0]->location.file, "nodes.xml");
  EXPECT_EQ(duplicate[0]->location.line, 6);
  EXPECT_EQ(duplicate[0]->location.column, 5);
  EXPECT_EQ(duplicate[0]->notes,
            std::vector<std::string>{"first registered at nodes.xml:3:3 (as Condition): "
                                     "BehaviorTree.CPP refuses to register an ID twice"});
}

TEST(RegisteredNodes, WithoutNodesXmlNothingIsChecked) {
  auto files = navigation_files(kTwoTerrains);
  files["alternatives/navigation/on_dust.xml"] =
      alternative_tree("on_dust", "<AnyAction x=\"1\"/>");
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
}

}  // namespace
}  // namespace uabt::load
