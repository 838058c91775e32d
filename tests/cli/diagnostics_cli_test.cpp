// Diagnostics as a flight team meets them: the real binary, run from a directory other than
// the mission's, compared with golden output (tests/cli/golden/).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;

using UabtRun = uabt::testing::CliRun;

// `uabt ARGS` in `dir`; `streams` picks what is captured ("2>&1": both, "2>/dev/null": stdout).
UabtRun uabt_in(const fs::path& dir, const std::string& args, const std::string& streams = "2>&1") {
  return uabt::testing::run_shell("cd '" + dir.string() + "' && '" + UABT_BINARY + "' " + args +
                                  " " + streams);
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

void replace_in(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = read(p);
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  write(p, text);
}

std::string golden(const std::string& name) {
  return read(uabt::testing::source_dir() / "tests/cli/golden" / name);
}

// A workspace: `root/` holds copies of shipped missions, uabt runs in `root`.
class Workspace {
 public:
  Workspace() : temp_({}) {}
  fs::path root() const { return temp_.dir(); }
  fs::path copy(const std::string& mission, const std::string& as) const {
    fs::copy(uabt::testing::mission_dir(mission), root() / as, fs::copy_options::recursive);
    return root() / as;
  }

 private:
  uabt::testing::TempMission temp_;
};

TEST(Diagnostics, TypoIsUndeclaredWithDidYouMeanAndNothingElse) {
  Workspace ws;
  const fs::path m = ws.copy("msl_curiosity", "msl_typo");
  replace_in(m / "requirements.fret", "if OnRocks", "if OnRokcs");
  const UabtRun run = uabt_in(ws.root(), "verify msl_typo");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, golden("typo.txt"));
}

TEST(Diagnostics, TypoWithoutDeclaredVocabularyIsAWarningNamingBoth) {
  Workspace ws;
  const fs::path m = ws.copy("msl_curiosity_paper", "paper_typo");
  write(m / "requirements.fret", read(m / "requirements.fret") +
                                     "Req3: In navigation if OnRokcs & OnDust Mission shall "
                                     "satisfy selected_alt = on_rocks\n");
  const UabtRun run = uabt_in(ws.root(), "verify paper_typo");
  EXPECT_NE(run.out.find("paper_typo/requirements.fret:6:24: warning: 'OnRokcs' in requirement "
                         "Req3 is 1 edit away from 'OnRocks'"),
            std::string::npos)
      << run.out;
}

TEST(Diagnostics, EveryNodeAgainstNodesXml) {
  Workspace ws;
  const fs::path m = ws.copy("msl_curiosity", "msl_nodes");
  // The robot's nodes, without TakePicture, and MoveForward without a `time` port.
  write(m / "nodes.xml",
        "<root BTCPP_format=\"4\">\n  <TreeNodesModel>\n"
        "    <Condition ID=\"OnDust\"/>\n    <Condition ID=\"OnRocks\"/>\n"
        "    <Condition ID=\"IsInLocation\"/>\n    <Condition ID=\"IsTowardObject\"/>\n"
        "    <Condition ID=\"IsRockAtLeft\"/>\n    <Condition ID=\"IsRockAtRight\"/>\n"
        "    <Condition ID=\"IsArmInPosition\"><input_port name=\"function\"/></Condition>\n"
        "    <Condition ID=\"IsDug\"/>\n    <Condition ID=\"IsContainerEmpty\"/>\n"
        "    <Condition ID=\"IsPictureTaken\"/>\n"
        "    <Action ID=\"Stop\"/>\n    <Action ID=\"OpenToolArm\"/>\n    <Action ID=\"Drill\"/>\n"
        "    <Action ID=\"Trickle\"/>\n    <Action ID=\"CloseToolArm\"/>\n"
        "    <Action ID=\"WaitForGroundCommand\"/>\n"
        "    <Action ID=\"TurnRight\"><input_port name=\"angle\"/></Action>\n"
        "    <Action ID=\"TurnLeft\"><input_port name=\"angle\"/></Action>\n"
        "    <Action ID=\"MoveForward\"><input_port name=\"speed\"/></Action>\n"
        "    <Action ID=\"MoveBackward\">\n      <input_port name=\"speed\"/>\n"
        "      <input_port name=\"time\"/>\n      <input_port name=\"distance\"/>\n"
        "    </Action>\n"
        "  </TreeNodesModel>\n</root>\n");
  const UabtRun run = uabt_in(ws.root(), "verify msl_nodes");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, golden("nodes.txt"));
}

TEST(Diagnostics, ShalTypoIsOneSyntaxErrorAndTheNodeNotVerified) {
  Workspace ws;
  const fs::path m = ws.copy("msl_curiosity_paper", "paper_shal");
  replace_in(m / "requirements.fret", "OnRocks Mission shall", "OnRocks Mission shal");
  const UabtRun run = uabt_in(ws.root(), "verify paper_shal");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, golden("cascade_shal.txt"));
}

TEST(Diagnostics, EmptyRangeStopsTheGuardChecks) {
  Workspace ws;
  const fs::path m = ws.copy("exploration", "explore_range");
  replace_in(m / "domain.fret", "integer battery in [0, 100]", "integer battery in [100, 0]");
  const UabtRun run = uabt_in(ws.root(), "verify explore_range");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, golden("cascade_empty_range.txt"));
}

TEST(Diagnostics, PathsOpenFromWhereUabtRuns) {
  Workspace ws;
  const fs::path m = ws.copy("msl_curiosity", "msl_typo");
  replace_in(m / "requirements.fret", "if OnRocks", "if OnRokcs");
  fs::create_directories(ws.root() / "elsewhere");
  const std::string at = "requirements.fret:4:24: error: 'OnRokcs'";
  // The first line is the node's verification-skipped warning; the error follows.
  EXPECT_NE(uabt_in(ws.root(), "verify msl_typo").out.find("\nmsl_typo/" + at), std::string::npos);
  EXPECT_NE(uabt_in(ws.root(), "verify ./msl_typo/").out.find("\nmsl_typo/" + at),
            std::string::npos);
  EXPECT_NE(uabt_in(m, "verify .").out.find("\n" + at), std::string::npos);
  EXPECT_NE(uabt_in(ws.root() / "elsewhere", "verify ../msl_typo").out.find("\n../msl_typo/" + at),
            std::string::npos);
  // An absolute mission path inside the working directory prints relative to it.
  EXPECT_NE(uabt_in(ws.root(), "verify '" + m.string() + "'").out.find("\nmsl_typo/" + at),
            std::string::npos);
  // findings.txt of the gate reads like the terminal.
  uabt_in(ws.root(), "gate msl_typo --out report");
  EXPECT_NE(read(ws.root() / "report/findings.txt").find("\nmsl_typo/" + at), std::string::npos)
      << read(ws.root() / "report/findings.txt");
}

TEST(Diagnostics, ATerminalGetsTheSourceLineWithACaret) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  Workspace ws;
  const fs::path m = ws.copy("msl_curiosity", "msl_typo");
  replace_in(m / "requirements.fret", "if OnRocks", "if OnRokcs");
  // script(1) gives uabt a terminal as its standard error.
  const std::string command = "cd '" + ws.root().string() + "' && script -qc \"'" +
                              std::string(UABT_BINARY) + "' verify msl_typo\" /dev/null";
  const std::string out = uabt::testing::run_shell(command).out;
  EXPECT_NE(out.find("msl_typo/requirements.fret:4:24: error: 'OnRokcs' in requirement Req2 is "
                     "not declared in domain.fret [ref-undeclared]\r\n"
                     "   4 | Req2: In navigation if OnRokcs Mission shall satisfy selected_alt = "
                     "on_rocks\r\n"
                     "     |                        ^\r\n"),
            std::string::npos)
      << out;
}

nlohmann::json sarif_of(const fs::path& dir, const std::string& args) {
  const UabtRun run = uabt_in(dir, args + " --format sarif", "2>/dev/null");
  return nlohmann::json::parse(run.out, nullptr, false);
}

TEST(Diagnostics, SarifIsRelativeToTheSourceRoot) {
  Workspace ws;
  fs::create_directories(ws.root() / "repo/.git");
  fs::create_directories(ws.root() / "repo/missions");
  fs::copy(uabt::testing::mission_dir("msl_curiosity_paper"), ws.root() / "repo/missions/paper",
           fs::copy_options::recursive);
  const fs::path absolute = ws.root() / "repo/missions/paper";
  // From outside the work tree, with an absolute path: still relative to the git top.
  for (const auto& [where, mission] :
       {std::pair{ws.root(), absolute.string()},
        std::pair{ws.root() / "repo/missions", std::string("paper")}}) {
    const auto sarif = sarif_of(where, "verify '" + mission + "'");
    ASSERT_FALSE(sarif.is_discarded());
    const auto& run = sarif["runs"][0];
    EXPECT_TRUE(run["originalUriBaseIds"].contains("%SRCROOT%"));
    for (const auto& result : run["results"]) {
      const auto& artifact = result["locations"][0]["physicalLocation"]["artifactLocation"];
      EXPECT_EQ(artifact["uri"], "missions/paper/requirements.fret") << result.dump();
      EXPECT_EQ(artifact["uriBaseId"], "%SRCROOT%");
    }
  }
  const auto rooted =
      sarif_of(ws.root(), "verify '" + absolute.string() + "' --source-root repo/missions");
  EXPECT_EQ(rooted["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]
                  ["uri"],
            "paper/requirements.fret");
}

TEST(Diagnostics, SarifOverlapNamesTheOtherRequirementAndTheGapSpansTheNode) {
  const auto sarif = sarif_of(uabt::testing::source_dir(), "verify missions/msl_curiosity_paper");
  ASSERT_FALSE(sarif.is_discarded());
  bool overlap = false, gap = false;
  for (const auto& result : sarif["runs"][0]["results"]) {
    const auto& region = result["locations"][0]["physicalLocation"]["region"];
    if (result["ruleId"] == "guard-overlap") {
      overlap = true;
      EXPECT_EQ(region["startLine"], 5);
      ASSERT_EQ(result["relatedLocations"].size(), 1u) << result.dump();
      const auto& related = result["relatedLocations"][0];
      EXPECT_EQ(related["physicalLocation"]["region"]["startLine"], 4);
      EXPECT_EQ(related["physicalLocation"]["artifactLocation"]["uri"],
                "missions/msl_curiosity_paper/requirements.fret");
      EXPECT_EQ(related["message"]["text"], "the other requirement, Req1 (on_dust)");
      const auto notes = result["properties"]["notes"].dump();
      EXPECT_NE(notes.find("both hold: OnDust & OnRocks"), std::string::npos) << notes;
    }
    if (result["ruleId"] == "guard-gap") {
      gap = true;
      EXPECT_EQ(region["startLine"], 4) << "the node's first requirement";
      EXPECT_EQ(region["endLine"], 5) << "to its last";
    }
  }
  EXPECT_TRUE(overlap);
  EXPECT_TRUE(gap);
}

TEST(Diagnostics, AFailingGateKeepsTheCandidateAsRejected) {
  Workspace ws;
  ws.copy("msl_curiosity_paper", "paper");
  ws.copy("msl_curiosity", "msl");
  EXPECT_EQ(uabt_in(ws.root(), "gate paper --out out").exit_code, 1);
  EXPECT_FALSE(fs::exists(ws.root() / "out/compiled.xml"));
  EXPECT_TRUE(fs::exists(ws.root() / "out/compiled.rejected.xml"));
  EXPECT_EQ(uabt_in(ws.root(), "gate msl --out out").exit_code, 0);
  EXPECT_TRUE(fs::exists(ws.root() / "out/compiled.xml"));
  EXPECT_FALSE(fs::exists(ws.root() / "out/compiled.rejected.xml"));
}

TEST(Diagnostics, CompileSaysItDidNotVerify) {
  const UabtRun run = uabt_in(uabt::testing::source_dir(), "compile missions/msl_curiosity_paper",
                              "2>&1 >/dev/null");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out,
            "uabt: msl_curiosity_paper: compiled, not verified: `uabt gate` proves the guards "
            "and the tree\n");
}

TEST(Diagnostics, ConformSaysConforms) {
  Workspace ws;
  const std::string compiled = (ws.root() / "c.xml").string();
  ASSERT_EQ(
      uabt_in(uabt::testing::source_dir(), "compile missions/exploration -o '" + compiled + "'")
          .exit_code,
      0);
  const UabtRun run =
      uabt_in(uabt::testing::source_dir(), "conform missions/exploration '" + compiled + "'");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "exploration: conforms\n");
}

TEST(Diagnostics, ChecksListsTheCatalogue) {
  const UabtRun text = uabt_in(uabt::testing::source_dir(), "checks");
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("ref-undeclared (error, load): "), std::string::npos) << text.out;
  const UabtRun table = uabt_in(uabt::testing::source_dir(), "checks --format markdown");
  EXPECT_EQ(table.out.find("| check | severity | stage | what it catches |\n"), 0u);
  EXPECT_NE(table.out.find("| `guard-gap` | error | verify |"), std::string::npos);
  const UabtRun typo = uabt_in(uabt::testing::source_dir(), "explain guard-overlpa");
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.out.find("did you mean 'guard-overlap'?"), std::string::npos) << typo.out;
}

// --- an uplink package outside the mission (issue 23, point 6) ------------------------------

// The file of each "file:line:col: severity:" line (indented ones too: `run` prints a rejected
// package's findings under its event) and of each "uplink DIR verdict" line.
std::vector<std::string> printed_paths(const std::string& out) {
  static const std::regex located(R"(^\s*([^\s:][^:]*?)(?::\d+)*: (error|warning|note): )");
  static const std::regex uplink(R"(^tick \d+: uplink (\S+) (accepted|rejected))");
  std::vector<std::string> paths;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_search(line, m, located) || std::regex_search(line, m, uplink))
      paths.push_back(m[1]);
  }
  return paths;
}

// Files of a findings.json (relative to the mission) and of a SARIF log (relative to the
// source root, the current directory here, or absolute file URIs).
std::vector<std::string> json_paths(const nlohmann::json& findings) {
  std::vector<std::string> paths;
  for (const auto& f : findings["findings"]) paths.push_back(f["location"]["file"]);
  return paths;
}
std::vector<std::string> sarif_paths(const nlohmann::json& sarif) {
  std::vector<std::string> paths;
  for (const auto& result : sarif["runs"][0]["results"]) {
    std::vector<nlohmann::json> places = {result["locations"][0]};
    if (result.contains("relatedLocations"))
      for (const auto& r : result["relatedLocations"]) places.push_back(r);
    for (const auto& place : places) {
      std::string uri = place["physicalLocation"]["artifactLocation"]["uri"];
      if (uri.rfind("file://", 0) == 0) uri = uri.substr(7);
      paths.push_back(uri);
    }
  }
  return paths;
}

void expect_all_open_from(const fs::path& base, const std::vector<std::string>& paths,
                          const std::string& what) {
  EXPECT_FALSE(paths.empty()) << what;
  for (const auto& p : paths) {
    EXPECT_TRUE(fs::exists(base / p)) << what << ": " << p << " does not open from " << base;
    EXPECT_EQ(p.find("lunar/lunar"), std::string::npos) << what << ": " << p;
  }
}

TEST(Diagnostics, AnUplinkOutsideTheMissionIsNamedAsItOpens) {
  // ws/lunar (the mission), ws/uplink_ridge2 (the package, beside it: a requirement that does
  // not parse, and a symlinked alternative that does not read), uabt runs in ws/third.
  Workspace ws;
  const fs::path mission = ws.copy("msl_curiosity", "lunar");
  fs::copy(mission / "uplinks/on_mud", ws.root() / "uplink_ridge2", fs::copy_options::recursive);
  const fs::path package = ws.root() / "uplink_ridge2";
  write(package / "requirements.fret",
        read(package / "requirements.fret") +
            "Ridge: In navigation if OnMud Mission shal satisfy selected_alt = on_mud\n");
  const fs::path alternative = package / "alternatives/navigation/on_mud.xml";
  write(ws.root() / "shared/on_mud.xml",
        "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"on_mud\">\n");
  fs::remove(alternative);
  fs::create_symlink("../../../shared/on_mud.xml", alternative);
  // The mission's own alternative, symlinked from elsewhere, is named by its link.
  const fs::path rocks = mission / "alternatives/navigation/on_rocks.xml";
  write(ws.root() / "shared/on_rocks.xml", read(rocks) + "<oops");
  fs::remove(rocks);
  fs::create_symlink(ws.root() / "shared/on_rocks.xml", rocks);
  const fs::path third = ws.root() / "third";
  fs::create_directories(third);

  const UabtRun gate = uabt_in(third, "gate ../lunar --uplink ../uplink_ridge2 --out out");
  EXPECT_EQ(gate.exit_code, 1) << gate.out;
  EXPECT_NE(gate.out.find("../uplink_ridge2/requirements.fret:"), std::string::npos) << gate.out;
  EXPECT_NE(gate.out.find("../uplink_ridge2/alternatives/navigation/on_mud.xml:"),
            std::string::npos)
      << gate.out;
  EXPECT_NE(gate.out.find("../lunar/alternatives/navigation/on_rocks.xml:"), std::string::npos)
      << gate.out;
  expect_all_open_from(third, printed_paths(gate.out), "gate text");
  expect_all_open_from(third, printed_paths(read(third / "out/findings.txt")), "findings.txt");
  expect_all_open_from(mission,
                       json_paths(nlohmann::json::parse(read(third / "out/findings.json"))),
                       "findings.json (relative to the mission)");
  expect_all_open_from(third,
                       sarif_paths(nlohmann::json::parse(read(third / "out/findings.sarif"))),
                       "findings.sarif (relative to the source root)");
  const UabtRun json = uabt_in(
      third, "gate ../lunar --uplink ../uplink_ridge2 --out out --format json", "2>/dev/null");
  expect_all_open_from(mission, json_paths(nlohmann::json::parse(json.out)), "--format json");
  const UabtRun sarif = uabt_in(
      third, "gate ../lunar --uplink ../uplink_ridge2 --out out --format sarif", "2>/dev/null");
  expect_all_open_from(third, sarif_paths(nlohmann::json::parse(sarif.out)), "--format sarif");

  // A package further up than the mission is named by its absolute path, not ../../…
  const uabt::testing::TempMission elsewhere({});
  fs::copy(package, elsewhere.dir() / "ridge", fs::copy_options::recursive);
  const UabtRun far = uabt_in(
      ws.root(), "gate lunar --uplink '" + (elsewhere.dir() / "ridge").string() + "' --out out");
  EXPECT_NE(far.out.find("\n" + (elsewhere.dir() / "ridge/requirements.fret:6:").string()),
            std::string::npos)
      << far.out;
  expect_all_open_from(ws.root(), printed_paths(far.out), "gate, package elsewhere");

  // `run`: the mission itself must pass its gate, so its own alternative is whole again.
  fs::remove(rocks);
  fs::copy_file(
      uabt::testing::mission_dir("msl_curiosity") / "alternatives/navigation/on_rocks.xml", rocks);
  const UabtRun run = uabt_in(
      third,
      "run ../lunar --scenario ../lunar/scenarios/dusty_start.json --uplink 2:../uplink_ridge2");
  EXPECT_NE(run.out.find("uplink ../uplink_ridge2 rejected"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("    ../uplink_ridge2/requirements.fret:6:"), std::string::npos)
      << run.out;
  expect_all_open_from(third, printed_paths(run.out), "run");
}

TEST(Diagnostics, NonAsciiCharacterNamesItselfAndItsAsciiForm) {
  Workspace ws;
  const fs::path m = ws.copy("exploration", "explore_utf8");
  replace_in(m / "requirements.fret", "battery >= 40", "battery \xE2\x89\xA5 40");
  const UabtRun run = uabt_in(ws.root(), "verify explore_utf8");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.out.find("found '\xE2\x89\xA5' (U+2265, not ASCII): write '>='"), std::string::npos)
      << run.out;
}

TEST(Diagnostics, ARunRefusedByTheGatesChecksNamesTheFindingsAsTheyOpen) {
  // From the repository's root, as a person types it: every finding's file opens from here.
  const UabtRun run = uabt_in(UABT_SOURCE_DIR,
                              "run missions/msl_curiosity_paper --scenario "
                              "missions/msl_curiosity/scenarios/dusty_start.json");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.out.find("uabt: the mission does not pass the gate's checks; only a verified "
                         "version runs:\nmissions/msl_curiosity_paper/requirements.fret:4:7: "
                         "error: no requirement of navigation holds in some states"),
            std::string::npos)
      << run.out;
}

}  // namespace
