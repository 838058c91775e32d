#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace {

using uabt::testing::CliRun;

// Runs the real binary from the source directory, as a user or CI would.
CliRun uabt(const std::string& args) {
  return uabt::testing::run_shell("cd '" + uabt::testing::source_dir().string() + "' && '" +
                                  UABT_BINARY + "' " + args + " 2>&1");
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Cli, GatePassesOnCuriosityAndFailsOnThePapersRequirements) {
  uabt::testing::TempMission out({});
  CliRun pass = uabt("gate missions/msl_curiosity --out '" + (out.dir() / "a").string() + "'");
  EXPECT_EQ(pass.exit_code, 0) << pass.out;
  CliRun fail =
      uabt("gate missions/msl_curiosity_paper --out '" + (out.dir() / "b").string() + "'");
  EXPECT_EQ(fail.exit_code, 1) << fail.out;
  EXPECT_NE(fail.out.find("requirements.fret:5:7: error:"), std::string::npos) << fail.out;
  EXPECT_NE(fail.out.find("[guard-overlap]"), std::string::npos);
  EXPECT_NE(fail.out.find("[guard-gap]"), std::string::npos);
  const std::string sarif = read(out.dir() / "b" / "findings.sarif");
  EXPECT_NE(sarif.find("\"uri\": \"missions/msl_curiosity_paper/requirements.fret\""),
            std::string::npos)
      << "SARIF locations are repository-relative so code scanning finds the file";
}

TEST(Cli, MissingPathAndBadOptionsExitTwo) {
  EXPECT_EQ(uabt("verify missions/no_such_mission").exit_code, 2);
  EXPECT_EQ(uabt("compile missions/msl_curiosity --bt-format 5").exit_code, 2);
  EXPECT_EQ(uabt("frobnicate").exit_code, 2);
  EXPECT_EQ(uabt("explain no-such-check").exit_code, 2);
}

TEST(Cli, VerifyJsonFollowsTheContract) {
  CliRun run = uabt("verify missions/msl_curiosity_paper --format json");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.out.find("\"verdict\": \"fail\""), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"check\": \"guard-overlap\""), std::string::npos);
  EXPECT_EQ(uabt("verify missions/msl_curiosity --allow-overlap").exit_code, 0);
}

TEST(Cli, AllowOverlapTurnsOverlapIntoAWarning) {
  CliRun run = uabt("verify missions/msl_curiosity_paper --allow-overlap");
  EXPECT_EQ(run.exit_code, 1) << "the gap is still an error";
  EXPECT_NE(run.out.find("warning:"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("error: Req1 (on_dust) and Req2"), std::string::npos) << run.out;
}

TEST(Cli, CompileToStdoutIsTheGoldenTree) {
  const std::string note =
      "uabt: msl_curiosity: compiled, not verified: `uabt gate` proves the guards and the tree\n";
  // The tree on stdout, then (stderr) the one line that says compile does not verify. Without
  // --selection the mission's own style (navigation declares selection="reactive").
  CliRun run = uabt("compile missions/msl_curiosity");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(
      run.out,
      read(uabt::testing::source_dir() / "tests/compile/golden/msl_curiosity_reactive.xml") + note);
  // An explicit style overrides it: the paper's Fig. 4.
  run = uabt("compile missions/msl_curiosity --selection sequence");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out,
            read(uabt::testing::source_dir() / "tests/compile/golden/msl_curiosity.xml") + note);
}

TEST(Cli, ConformAcceptsTheCompiledTreeAndThePapersGeneratedTree) {
  uabt::testing::TempMission out({});
  const std::string compiled = (out.dir() / "c.xml").string();
  ASSERT_EQ(uabt("compile missions/exploration -o '" + compiled + "'").exit_code, 0);
  EXPECT_EQ(uabt("conform missions/exploration '" + compiled + "'").exit_code, 0);
  const auto replication = uabt::testing::replication_dir();
  if (!std::filesystem::exists(replication)) GTEST_SKIP();
  CliRun paper = uabt("conform '" + replication.string() + "' '" +
                      (replication / "output/concrete_mission.xml").string() + "'");
  EXPECT_EQ(paper.exit_code, 0) << paper.out;
}

TEST(Cli, ExplainPrintsTheCheckDocumentation) {
  CliRun run = uabt("explain guard-overlap");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("## Why this matters"), std::string::npos);
  EXPECT_NE(run.out.find("## How to fix it"), std::string::npos);
  CliRun list = uabt("explain");
  EXPECT_NE(list.out.find("guard-gap (error, verify)"), std::string::npos) << list.out;
}

TEST(Cli, DiffShowsTheMudUplinkImpact) {
  // A copy of the mission with the uplink merged in by hand is the uplinked version.
  CliRun run = uabt("diff missions/msl_curiosity missions/msl_curiosity");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("navigation: unchanged"), std::string::npos) << run.out;
}

TEST(Cli, RunTheCuriosityStory) {
  CliRun run = uabt(
      "run missions/msl_curiosity --selection reactive --scenario "
      "missions/msl_curiosity/scenarios/mud_uplink.json");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("uplink missions/msl_curiosity/uplinks/on_mud accepted"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("navigation selects on_mud (Req3)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("mission success"), std::string::npos);
}

// --- the uplink workflow (ARCHITECTURE §11)
// ---------------------------------------------------------

TEST(CliUplink, GateUplinkExitCodes) {
  uabt::testing::TempMission out({});
  const std::string o = " --out '" + out.dir().string() + "/";
  CliRun mud = uabt("gate missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/on_mud" +
                    o + "mud'");
  EXPECT_EQ(mud.exit_code, 0) << mud.out;
  EXPECT_NE(mud.out.find("uplinks/on_mud/requirements.fret:2:7: note: Req3: new requirement"),
            std::string::npos)
      << mud.out;
  EXPECT_NE(mud.out.find("navigation: 1 of 4 states (1/4) change their alternative"),
            std::string::npos)
      << mud.out;
  CliRun sand = uabt(
      "gate missions/msl_curiosity --uplink "
      "missions/msl_curiosity/uplinks/on_sand_ambiguous" +
      o + "sand'");
  EXPECT_EQ(sand.exit_code, 1) << sand.out;
  EXPECT_NE(sand.out.find("[guard-overlap]"), std::string::npos) << sand.out;
  EXPECT_EQ(
      uabt("gate missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/nope" + o + "x'")
          .exit_code,
      2);
}

TEST(CliUplink, APackageGivenAsTheMissionGetsTheRightCommand) {
  CliRun run = uabt("gate missions/msl_curiosity/uplinks/on_mud");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.out.find("`uabt gate missions/msl_curiosity --uplink "
                         "missions/msl_curiosity/uplinks/on_mud`"),
            std::string::npos)
      << run.out;
}

TEST(CliUplink, GateUplinkWritesTheMergedMissionThatGatesToTheSameTree) {
  uabt::testing::TempMission out({});
  const auto dir = out.dir() / "storm";
  ASSERT_EQ(uabt("gate missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/dust_storm "
                 "--out '" +
                 dir.string() + "'")
                .exit_code,
            0);
  const std::string requirements = read(dir / "merged" / "requirements.fret");
  EXPECT_LT(requirements.find("Storm: In navigation"), requirements.find("Req1: In navigation"))
      << requirements;
  EXPECT_TRUE(std::filesystem::exists(dir / "merged/alternatives/navigation/wait_out_storm.xml"));
  const auto again = out.dir() / "again";
  ASSERT_EQ(
      uabt("gate '" + (dir / "merged").string() + "' --out '" + again.string() + "'").exit_code, 0);
  EXPECT_EQ(read(again / "compiled.xml"), read(dir / "compiled.xml"));
  EXPECT_NE(read(dir / "summary.md").find("placed before Req1 (uplink.json)"), std::string::npos);
}

TEST(CliUplink, DiffExitCodeAndUplink) {
  EXPECT_EQ(uabt("diff missions/msl_curiosity missions/msl_curiosity --exit-code").exit_code, 0);
  CliRun changed =
      uabt("diff missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/on_mud");
  EXPECT_EQ(changed.exit_code, 0) << changed.out;
  EXPECT_NE(changed.out.find("navigation: changed (1 of 4 states, 1/4, change their alternative)"),
            std::string::npos)
      << changed.out;
  EXPECT_EQ(uabt("diff missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/on_mud "
                 "--exit-code")
                .exit_code,
            1);
  EXPECT_EQ(uabt("diff missions/msl_curiosity missions/msl_curiosity_paper --exit-code").exit_code,
            1);
  EXPECT_EQ(uabt("diff missions/msl_curiosity").exit_code, 2) << "NEW or --uplink";
  EXPECT_EQ(uabt("diff missions/msl_curiosity missions/exploration --uplink "
                 "missions/msl_curiosity/uplinks/on_mud")
                .exit_code,
            2);
  CliRun json = uabt(
      "diff missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/on_mud "
      "--format json");
  EXPECT_NE(json.out.find("\"changed_states\": 1,"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"OnMud\": true"), std::string::npos) << json.out;
}

// A discrete mission's behaviour change is counted in states, to the byte as it always was.
TEST(CliUplink, DiffOfADiscreteMissionKeepsItsCountsToTheByte) {
  EXPECT_EQ(
      uabt("diff missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/retire_rocks").out,
      "navigation: changed (1 of 3 states, 1/3, change their alternative)\n"
      "  on_rocks (Req2) -> hold_position (Safe): 1 state (1/3)\n"
      "    e.g. OnDust=false, OnRocks=true\n");
  const std::string json =
      uabt(
          "diff missions/msl_curiosity --uplink missions/msl_curiosity/uplinks/retire_rocks "
          "--format json")
          .out;
  const std::string node = json.substr(0, json.find("      \"changes\""));
  EXPECT_EQ(node,
            "{\n"
            "  \"tool\": \"uabt\",\n"
            "  \"changed\": true,\n"
            "  \"nodes\": [\n"
            "    {\n"
            "      \"adaptable\": \"navigation\",\n"
            "      \"status\": \"changed\",\n"
            "      \"counted\": true,\n"
            "      \"states\": 3,\n"
            "      \"changed_states\": 1,\n"
            "      \"changed_share\": 0.3333333333333333,\n"
            "      \"changed_share_exact\": \"1/3\",\n"
            "      \"not_counted_reason\": null,\n");
  EXPECT_NE(json.find("          \"states\": 1,\n"
                      "          \"share\": 0.3333333333333333,\n"
                      "          \"share_exact\": \"1/3\",\n"),
            std::string::npos)
      << json;
}

// A real guard boundary that moves changes a measured share of the space, not "not counted".
TEST(CliUplink, DiffMeasuresTheShareOfARealSpaceThatChanges) {
  auto requirements = [](const std::string& threshold) {
    return "Windy: In nav if wind > " + threshold +
           " Mission shall satisfy selected_alt = slow\n"
           "Calm: In nav Mission shall satisfy selected_alt = fast\n";
  };
  const uabt::testing::TwoVersions v("nav", "real wind in [0, 10]\n", requirements("6"),
                                     requirements("4"), {"fast", "slow"});
  const std::string versions =
      "'" + v.old_version.dir().string() + "' '" + v.new_version.dir().string() + "'";
  const CliRun text = uabt("diff " + versions + " --exit-code");
  EXPECT_EQ(text.exit_code, 1) << text.out;
  EXPECT_EQ(text.out.rfind("nav: changed (20.0% of the space changes its alternative)\n"
                           "  fast (Calm) -> slow (Windy): 20.0% of the space\n"
                           "    e.g. wind=",
                           0),
            0u)
      << text.out;
  const std::string json = uabt("diff " + versions + " --format json").out;
  EXPECT_NE(json.find("      \"states\": null,\n"
                      "      \"changed_states\": null,\n"
                      "      \"changed_share\": 0.2,\n"
                      "      \"changed_share_exact\": \"1/5\",\n"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("          \"states\": null,\n"
                      "          \"share\": 0.2,\n"
                      "          \"share_exact\": \"1/5\",\n"),
            std::string::npos)
      << json;
}

TEST(CliUplink, RunRefusesAMissingUplinkBeforeTheRunStarts) {
  CliRun run = uabt(
      "run missions/msl_curiosity --scenario "
      "missions/msl_curiosity/scenarios/dusty_start.json --uplink 3:uplinks/on_mud");
  EXPECT_EQ(run.exit_code, 2) << "relative to the current directory, where there is no uplinks/";
  EXPECT_NE(run.out.find("no such directory"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("tick "), std::string::npos) << "the run must not start: " << run.out;
  EXPECT_EQ(uabt("run missions/msl_curiosity --scenario "
                 "missions/msl_curiosity/scenarios/dusty_start.json --uplink x:uplinks/on_mud")
                .exit_code,
            2);
  CliRun ok = uabt(
      "run missions/msl_curiosity --scenario "
      "missions/msl_curiosity/scenarios/dusty_start.json --uplink "
      "3:missions/msl_curiosity/uplinks/on_mud");
  EXPECT_NE(ok.out.find("uplink missions/msl_curiosity/uplinks/on_mud accepted"), std::string::npos)
      << ok.out;
}

}  // namespace

namespace {

TEST(Cli, RunStopsOnAScriptErrorAndOnMaxTicks) {
  const std::map<std::string, std::string> files = {
      {"no_battery.json", R"({"initial": {"terrain": "sand"}})"},
      {"forever.json",
       R"({"initial": {"OnDust": true}, "actions": {"MoveForward": {"ticks": 1000000}}})"}};
  uabt::testing::TempMission dir(files);
  CliRun error = uabt("run missions/exploration --scenario '" +
                      (dir.dir() / "no_battery.json").string() + "'");
  EXPECT_EQ(error.exit_code, 1) << error.out;
  EXPECT_NE(error.out.find("undefined blackboard key 'battery'"), std::string::npos);
  // Where, as the file opens from the directory uabt ran in.
  EXPECT_NE(error.out.find("\nmissions/exploration/mission.xml:8:9: error: ScriptCondition"),
            std::string::npos)
      << error.out;
  EXPECT_NE(error.out.find("tick 1: error: missions/exploration/mission.xml:8:9:"),
            std::string::npos)
      << error.out;
  EXPECT_NE(error.out.find("mission error"), std::string::npos) << error.out;
  EXPECT_EQ(error.out.find("mission success"), std::string::npos) << error.out;
  CliRun timeout = uabt("run missions/msl_curiosity --max-ticks 50 --scenario '" +
                        (dir.dir() / "forever.json").string() + "'");
  EXPECT_EQ(timeout.exit_code, 1) << timeout.out;
  EXPECT_NE(timeout.out.find("tick 50: mission timeout"), std::string::npos) << timeout.out;
}

}  // namespace
