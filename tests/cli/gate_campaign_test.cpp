// The gate writes the test campaign of the mission it gates beside its reports (OUT/tests/),
// with one scenario per behaviour change of an uplink.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/files.hpp"
#include "cli/cli_support.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace {

using uabt::testing::CliRun;

CliRun uabt(const std::string& args) {
  return uabt::testing::run_uabt_in(uabt::testing::source_dir().string(), args);
}

std::string read(const std::filesystem::path& p) {
  std::string error;
  return uabt::read_text_file(p, error).value_or("");
}

TEST(GateCampaign, UplinkGateWritesTheCampaignWithTheBehaviourChangeScenario) {
  uabt::testing::TempMission scratch({});
  const auto out = scratch.dir() / "mud";
  const CliRun gate = uabt(
      "gate missions/msl_curiosity --uplink "
      "missions/msl_curiosity/uplinks/on_mud --out '" +
      out.string() + "'");
  ASSERT_EQ(gate.exit_code, 0) << gate.out;
  // The campaign adds no finding: the terminal says nothing about it.
  EXPECT_EQ(gate.out.find("campaign"), std::string::npos) << gate.out;
  EXPECT_NE(read(out / "tests/junit.xml").find("<testsuite name=\"msl_curiosity.tests\""),
            std::string::npos);
  EXPECT_NE(read(out / "tests/campaign.json").find("\"behaviour_change_scenarios\": 1"),
            std::string::npos);

  // The uplink moves the all-unknown-but-mud state from hold_position to on_mud.
  const auto change = out / "tests/navigation-change-01.json";
  EXPECT_NE(read(change).find("\"description\": \"Test campaign: behaviour change: node "
                              "navigation moves from hold_position to on_mud\""),
            std::string::npos)
      << read(change);
  const CliRun run =
      uabt("run '" + (out / "merged").string() + "' --scenario '" + change.string() + "'");
  EXPECT_EQ(run.out.find("tick 1: navigation selects "),
            run.out.find("tick 1: navigation selects on_mud (Req3)"))
      << run.out;
  EXPECT_NE(run.out.find("tick 1: navigation selects on_mud (Req3)"), std::string::npos) << run.out;

  const std::string summary = read(out / "summary.md");
  EXPECT_NE(summary.find("### Test campaign\n\ntests/: 9 scenarios (1 for a behaviour change) "
                         "cover 25 of 25 reachable targets; 27 targets, 2 unreachable\n"),
            std::string::npos)
      << summary;
  EXPECT_NE(read(out / "report.html")
                .find("<h2>Test campaign</h2>\n<p>tests/: 9 scenarios (1 for a behaviour change) "
                      "cover 25 of 25 reachable targets"),
            std::string::npos);
}

TEST(GateCampaign, PlainGateWritesTheCampaignAndAFailingGateNone) {
  uabt::testing::TempMission scratch({});
  const auto out = scratch.dir() / "landing";
  ASSERT_EQ(uabt("gate missions/planetary_landing --out '" + out.string() + "'").exit_code, 0);
  EXPECT_TRUE(std::filesystem::exists(out / "tests/junit.xml"));
  EXPECT_NE(read(out / "summary.md")
                .find("tests/: 9 scenarios cover 26 of 26 reachable targets; 26 targets, 0 "
                      "unreachable\n"),
            std::string::npos)
      << read(out / "summary.md");

  // A mission the gate rejects gets no campaign, and the one an earlier run wrote goes.
  const auto stale = out / "tests/landing-99.json";
  uabt::write_file_atomically(stale, "{}\n");
  const CliRun fail = uabt("gate missions/planetary_landing_unsafe --out '" + out.string() + "'");
  EXPECT_EQ(fail.exit_code, 1) << fail.out;
  EXPECT_FALSE(std::filesystem::exists(out / "tests"));
  EXPECT_NE(read(out / "summary.md").find("no test campaign: the gate failed"), std::string::npos);
}

TEST(GateCampaign, UnreachableTargetsAreListedWithTheirReasonAndTheVerdictStays) {
  // b never changes R1's guard (a | a & b): its MC/DC target is unreachable. The gate warns
  // about the atom (guard-vacuous-atom) and still passes; the campaign says why b is not tested.
  using uabt::testing::alternative_tree;
  uabt::testing::TempMission m(
      {{"mission.xml",
        uabt::testing::mission_with("    <Sequence>\n      <Adaptable ID=\"node\"/>\n    "
                                    "</Sequence>")},
       {"alternatives/node/go.xml", alternative_tree("go")},
       {"alternatives/node/hold.xml", alternative_tree("hold")},
       {"domain.fret", "boolean a, b\n"},
       {"requirements.fret",
        "R1: In node if a | (a & b) Mission shall satisfy selected_alt = go\n"
        "Safe: In node Mission shall satisfy selected_alt = hold\n"}});
  const auto out = m.dir().parent_path() / "out";
  const CliRun gate =
      uabt::testing::run_uabt_in(m.dir().parent_path().string(), "gate m --out out");
  EXPECT_EQ(gate.exit_code, 0) << gate.out;
  EXPECT_NE(gate.out.find("m: pass\n"), std::string::npos) << gate.out;
  const std::string summary = read(out / "summary.md");
  EXPECT_NE(summary.find("tests/: 2 scenarios cover 5 of 5 reachable targets; 6 targets, 1 "
                         "unreachable\n\n- unreachable: MC/DC of b in R1: changing it alone "
                         "changes the guard and the selected alternative: not independently "
                         "testable: changing b alone never changes the guard of R1 (the other "
                         "atoms mask it)\n"),
            std::string::npos)
      << summary;
  // No finding of its own: the findings are the gate's.
  EXPECT_EQ(read(out / "findings.txt").find("campaign"), std::string::npos);
}

}  // namespace
