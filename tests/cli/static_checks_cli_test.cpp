// The whole-tree checks as users meet them (SARIF with the path through the tree), and
// `uabt schema` checked by a real validator, xmllint.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

namespace fs = std::filesystem;

const std::string kNodes =
    "<root BTCPP_format=\"4\">\n<TreeNodesModel>\n"
    "  <Condition ID=\"OnDust\"/>\n  <Condition ID=\"OnRocks\"/>\n"
    "  <Action ID=\"Stop\"/>\n"
    "  <Action ID=\"MoveForward\">\n"
    "    <input_port name=\"speed\" type=\"double\"/>\n"
    "    <input_port name=\"time\" type=\"int\" default=\"10\"/>\n"
    "    <output_port name=\"distance\" type=\"double\"/>\n"
    "  </Action>\n"
    "</TreeNodesModel>\n</root>\n";

const std::string kRequirements =
    "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
    "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
    "Safe: In navigation Mission shall satisfy selected_alt = on_rocks\n";

std::map<std::string, std::string> mission_files(const std::string& dust_body) {
  return {
      {"mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                   "      <Stop/>\n    </Sequence>")},
      {"requirements.fret", kRequirements},
      {"nodes.xml", kNodes},
      {"alternatives/navigation/on_dust.xml", alternative_tree("on_dust", dust_body)},
      {"alternatives/navigation/on_rocks.xml", alternative_tree("on_rocks")},
  };
}

std::string shell_quote(const fs::path& p) {
  return "'" + p.string() + "'";
}

// xmllint's verdict on `file` against `schema`: 0 valid.
CliRun xmllint(const fs::path& schema, const fs::path& file) {
  return run_shell("xmllint --noout --schema " + shell_quote(schema) + " " + shell_quote(file) +
                   " 2>&1");
}

bool have_xmllint() {
  return run_shell("command -v xmllint >/dev/null").exit_code == 0;
}

TEST(StaticChecksCli, SarifCarriesThePathThroughTheTree) {
  TempMission dir(
      mission_files("<Sequence name=\"drive\">\n      <MoveForward speed=\"1\" distance=\"far\"/>\n"
                    "    </Sequence>"));
  const CliRun run = run_uabt_in(dir.dir().string(), "verify . --format sarif 2>/dev/null");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  const auto sarif = nlohmann::json::parse(run.out);
  const nlohmann::json* found = nullptr;
  for (const auto& r : sarif["runs"][0]["results"])
    if (r["ruleId"] == "tree-output-literal") found = &r;
  ASSERT_NE(found, nullptr) << run.out;
  const auto& region = (*found)["locations"][0]["physicalLocation"]["region"];
  EXPECT_EQ(region["startLine"], 4);
  EXPECT_EQ(region["startColumn"], 30);
  const auto& related = (*found)["relatedLocations"];
  ASSERT_EQ(related.size(), 2u);
  EXPECT_EQ(related[0]["message"]["text"], "in <BehaviorTree ID=\"on_dust\">");
  EXPECT_EQ(related[1]["message"]["text"], "in <Sequence name=\"drive\">");
  EXPECT_EQ(related[1]["physicalLocation"]["region"]["startLine"], 3);
}

TEST(StaticChecksCli, ExplainAndChecksListTheTreeChecks) {
  for (const char* id : {"tree-output-literal", "tree-output-unbound", "tree-dead-branch",
                         "tree-async-reactive", "tree-kind-mismatch"}) {
    const CliRun run = run_uabt_in(".", std::string("explain ") + id);
    EXPECT_EQ(run.exit_code, 0) << id;
    EXPECT_NE(run.out.find("## How to fix it"), std::string::npos) << run.out;
  }
}

TEST(SchemaCli, DeterministicAndWrittenOnlyWhenAsked) {
  TempMission dir(mission_files("<Stop/>"));
  const CliRun first = run_uabt_in(dir.dir().string(), "schema nodes.xml -o nodes.xsd");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const std::string bytes = read_all(dir.dir() / "nodes.xsd");
  const CliRun second = run_uabt_in(dir.dir().string(), "schema nodes.xml");
  EXPECT_EQ(second.out, bytes);
  EXPECT_NE(bytes.find("<xs:element name=\"MoveForward\" type=\"node_MoveForward\"/>"),
            std::string::npos);
  EXPECT_NE(bytes.find("<xs:attribute name=\"speed\" type=\"doubleOrBlackboardType\" "
                       "use=\"required\"/>"),
            std::string::npos);
  EXPECT_NE(bytes.find("<xs:attribute name=\"time\" type=\"integerOrBlackboardType\"/>"),
            std::string::npos);
  const CliRun missing = run_uabt_in(dir.dir().string(), "schema absent.xml -o x.xsd");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir.dir() / "x.xsd"));
}

TEST(SchemaCli, HasBtCpp410sAsyncSequenceAndAsyncFallback) {
  TempMission dir(mission_files("<Stop/>"));
  const CliRun run = run_uabt_in(dir.dir().string(), "schema nodes.xml");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  for (const char* id : {"AsyncSequence", "AsyncFallback"}) {
    const std::string name(id);
    EXPECT_NE(run.out.find("<xs:element name=\"" + name + "\" type=\"node_" + name + "\"/>"),
              std::string::npos)
        << id;
    EXPECT_NE(run.out.find("<xs:complexType name=\"node_" + name +
                           "\">\n    <xs:group ref=\"oneNodeGroup\" minOccurs=\"1\" "
                           "maxOccurs=\"unbounded\"/>"),
              std::string::npos)
        << id;
  }
}

TEST(SchemaCli, XmllintAcceptsGoodTreesAndRejectsWhatTheLoaderRejects) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint (libxml2-utils) is not installed";
  TempMission dir(mission_files("<Stop/>"));
  ASSERT_EQ(run_uabt_in(dir.dir().string(), "schema nodes.xml -o nodes.xsd").exit_code, 0);
  const fs::path xsd = dir.dir() / "nodes.xsd";
  auto write = [&](const std::string& name, const std::string& body) {
    const fs::path p = dir.dir() / name;
    std::ofstream(p) << alternative_tree("t", body);
    return p;
  };
  const fs::path good = write(
      "good.xml",
      "<ReactiveSequence name=\"go\" _skipIf=\"done\">\n      <OnDust/>\n"
      "      <Condition ID=\"OnRocks\"/>\n      <Repeat num_cycles=\"{n}\">\n"
      "        <MoveForward speed=\"0.5\" distance=\"{d}\" _onSuccess=\"done := true\"/>\n"
      "      </Repeat>\n      <Action ID=\"Stop\"/>\n      <SubTree ID=\"other\" x=\"{y}\"/>\n"
      "    </ReactiveSequence>");
  const CliRun ok = xmllint(xsd, good);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_EQ(xmllint(xsd, dir.dir() / "mission.xml").exit_code, 0);

  // Each defect the loader reports in a tree, rejected by the schema too.
  const std::vector<std::pair<std::string, std::string>> defects = {
      {"ref-unknown-node", "<MoveFoward speed=\"1\" distance=\"{d}\"/>"},
      {"ref-unknown-node (explicit)", "<Action ID=\"MoveFoward\"/>"},
      {"ref-unknown-port", "<MoveForward speed=\"1\" distance=\"{d}\" sped=\"2\"/>"},
      {"ref-missing-port", "<MoveForward distance=\"{d}\"/>"},
      {"tree-output-literal", "<MoveForward speed=\"1\" distance=\"far\"/>"},
      {"tree-kind-mismatch", "<Condition ID=\"Stop\"/>"},
      {"bt-structure (decorator with two children)", "<Inverter><Stop/><Stop/></Inverter>"},
      {"port type", "<MoveForward speed=\"fast\" distance=\"{d}\"/>"},
  };
  for (const auto& [defect, body] : defects) {
    const CliRun bad = xmllint(xsd, write("bad.xml", body));
    EXPECT_NE(bad.exit_code, 0) << defect << " passed the schema:\n" << body;
  }
}

// A port named like an attribute BT.CPP reads itself (_skipIf) or named xmlns gets no attribute
// of its own: xmllint compiles the schema (it refused "Duplicate attribute use '_skipIf'" and an
// attribute named xmlns), and a node using _skipIf as every node may validates.
TEST(SchemaCli, XmllintCompilesTheSchemaOfPortsNamedLikeReservedAttributes) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint (libxml2-utils) is not installed";
  TempMission dir(mission_files("<Stop/>"));
  std::ofstream(dir.dir() / "nodes.xml")
      << "<root BTCPP_format=\"4\">\n<TreeNodesModel>\n  <Action ID=\"Stop\">\n"
         "    <input_port name=\"_skipIf\" type=\"int\"/>\n    <input_port name=\"xmlns\"/>\n"
         "    <input_port name=\"speed\" type=\"double\"/>\n  </Action>\n"
         "</TreeNodesModel>\n</root>\n";
  ASSERT_EQ(run_uabt_in(dir.dir().string(), "schema nodes.xml -o nodes.xsd").exit_code, 0);
  const fs::path tree = dir.dir() / "tree.xml";
  std::ofstream(tree) << alternative_tree("t", "<Stop speed=\"1.5\" _skipIf=\"done\"/>");
  const CliRun ok = xmllint(dir.dir() / "nodes.xsd", tree);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  std::ofstream(tree) << alternative_tree("t", "<Stop _skipIf=\"done\"/>");
  EXPECT_NE(xmllint(dir.dir() / "nodes.xsd", tree).exit_code, 0) << "speed is required";
}

// Every shipped mission's trees, alternatives and uplinked alternatives validate against the
// schema of the nodes its compiled tree registers (its <TreeNodesModel>).
TEST(SchemaCli, EveryShippedMissionValidates) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint (libxml2-utils) is not installed";
  TempMission out({});
  const fs::path missions = fs::path(UABT_SOURCE_DIR) / "missions";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(missions)) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    const fs::path compiled = out.dir() / (name + ".xml");
    const fs::path xsd = out.dir() / (name + ".xsd");
    ASSERT_EQ(run_uabt_in(".", "compile " + shell_quote(entry.path()) + " -o " +
                                   shell_quote(compiled) + " 2>/dev/null")
                  .exit_code,
              0);
    ASSERT_EQ(
        run_uabt_in(".", "schema " + shell_quote(compiled) + " -o " + shell_quote(xsd)).exit_code,
        0);
    for (const auto& file : fs::recursive_directory_iterator(entry.path())) {
      if (file.path().extension() != ".xml") continue;
      if (file.path().string().find("/uplinks/") != std::string::npos) continue;
      const CliRun run = xmllint(xsd, file.path());
      // blackboard_defects shows the whole-tree checks: its speed="fast" for a double port
      // (bb-literal-type) is what the schema must refuse too.
      const bool defect = name == "blackboard_defects" && file.path().filename() == "mission.xml";
      EXPECT_EQ(run.exit_code == 0, !defect) << run.out;
      if (defect) {
        EXPECT_NE(run.out.find("'speed': 'fast'"), std::string::npos) << run.out;
      }
      ++checked;
    }
    // An uplink package's alternatives: against the schema of the merged mission.
    if (!fs::is_directory(entry.path() / "uplinks")) continue;
    for (const auto& package : fs::directory_iterator(entry.path() / "uplinks")) {
      const fs::path report = out.dir() / (name + "-" + package.path().filename().string());
      run_uabt_in(".", "gate " + shell_quote(entry.path()) + " --uplink " +
                           shell_quote(package.path()) + " --out " + shell_quote(report) +
                           " >/dev/null 2>&1");
      fs::path merged_tree = report / "compiled.xml";
      if (!fs::exists(merged_tree)) merged_tree = report / "compiled.rejected.xml";
      ASSERT_TRUE(fs::exists(merged_tree)) << package.path();
      const fs::path merged_xsd = report / "nodes.xsd";
      ASSERT_EQ(
          run_uabt_in(".", "schema " + shell_quote(merged_tree) + " -o " + shell_quote(merged_xsd))
              .exit_code,
          0);
      for (const auto& file : fs::recursive_directory_iterator(package.path())) {
        if (file.path().extension() != ".xml") continue;
        const CliRun run = xmllint(merged_xsd, file.path());
        EXPECT_EQ(run.exit_code, 0) << file.path() << "\n" << run.out;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace uabt::testing
