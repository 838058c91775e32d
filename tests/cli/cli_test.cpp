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
  CliRun run = uabt("compile missions/msl_curiosity");
  EXPECT_EQ(run.exit_code, 0);
  // The tree on stdout, then (stderr) the one line that says compile does not verify.
  EXPECT_EQ(run.out, read(uabt::testing::source_dir() / "tests/compile/golden/msl_curiosity.xml") +
                         "uabt: msl_curiosity: compiled, not verified: `uabt gate` proves the "
                         "guards and the tree\n");
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
  EXPECT_NE(run.out.find("uplink uplinks/on_mud accepted"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("navigation selects on_mud (Req3)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("mission success"), std::string::npos);
}

}  // namespace
