// One gate everywhere (ARCHITECTURE §12): a package that `uabt gate --uplink` rejects is rejected
// by every entry point that could admit it, for the same reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using uabt::testing::CliRun;

CliRun uabt_in(const fs::path& dir, const std::string& args) {
  return uabt::testing::run_shell("cd '" + dir.string() + "' && '" + UABT_BINARY + "' " + args +
                                  " 2>&1");
}

// missions/msl_curiosity copied, with `uplinks/mud_bare`: the on_mud package whose
// requirements keep only Req3. Without the restated HoldOnUnknown, the mission's own
// HoldOnUnknown (hold on any terrain but dust and rocks) now fails on mud, where on_mud runs.
class BarePackage : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::copy(uabt::testing::mission_dir("msl_curiosity"), mission(), fs::copy_options::recursive);
    fs::copy(mission() / "uplinks" / "on_mud", mission() / "uplinks" / "mud_bare",
             fs::copy_options::recursive);
    write("msl/uplinks/mud_bare/requirements.fret",
          "Req3: In navigation if OnMud Mission shall satisfy selected_alt = on_mud\n");
    std::ifstream in(mission() / "scenarios" / "mud_uplink.json");
    std::string scenario((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "\"uplinks/on_mud\"";
    scenario.replace(scenario.find(from), from.size(), "\"uplinks/mud_bare\"");
    write("msl/scenarios/mud_bare.json", scenario);
  }
  void write(const std::string& path, const std::string& text) const { scratch_.write(path, text); }
  fs::path root() const { return scratch_.dir(); }
  fs::path mission() const { return scratch_.dir() / "msl"; }

 private:
  uabt::testing::TempMission scratch_{{}, "work"};
};

constexpr const char* kViolation =
    "guarantee 'HoldOnUnknown' is violated at tick 2: In navigation upon !OnDust & !OnRocks the "
    "rover shall within 1 tick satisfy navigation.selected = hold_position [prove-violated]";

TEST_F(BarePackage, GateUplinkRejectsItWithTheProof) {
  const CliRun r = uabt_in(root(), "gate msl --uplink msl/uplinks/mud_bare --out out");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find(kViolation), std::string::npos) << r.out;
  // The merged mission it wrote is rejected by the plain gate for the same reason.
  const CliRun merged = uabt_in(root(), "gate out/merged --out out2");
  EXPECT_EQ(merged.exit_code, 1) << merged.out;
  EXPECT_NE(merged.out.find(kViolation), std::string::npos) << merged.out;
}

TEST_F(BarePackage, AScenarioUplinkEventIsRejectedWithTheProof) {
  const CliRun r = uabt_in(root(), "run msl --scenario msl/scenarios/mud_bare.json");
  EXPECT_NE(r.out.find("uplink msl/uplinks/mud_bare rejected"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(kViolation), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("accepted"), std::string::npos) << r.out;
  EXPECT_NE(r.exit_code, 0) << "mud is unknown to the running version: it holds, then times out";
}

TEST_F(BarePackage, RunUplinkIsRejectedWithTheProof) {
  // dusty_start has no uplink event of its own.
  const CliRun r = uabt_in(
      root(), "run msl --scenario msl/scenarios/dusty_start.json --uplink 3:msl/uplinks/mud_bare");
  EXPECT_NE(r.out.find("uplink msl/uplinks/mud_bare rejected"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(kViolation), std::string::npos) << r.out;
  // The shipped package restates HoldOnUnknown for mud and is accepted the same way.
  const CliRun ok = uabt_in(
      root(), "run msl --scenario msl/scenarios/dusty_start.json --uplink 3:msl/uplinks/on_mud");
  EXPECT_NE(ok.out.find("uplink msl/uplinks/on_mud accepted"), std::string::npos) << ok.out;
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
}

TEST_F(BarePackage, AScenarioUplinkToNoFolderFailsBeforeTickOne) {
  write("msl/scenarios/typo.json",
        R"({"initial": {"OnDust": true}, "events": [{"at": 5, "uplink": "uplinks/on_mudd"}]})");
  const CliRun r = uabt_in(root(), "run msl --scenario msl/scenarios/typo.json");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("msl/scenarios/typo.json:1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("uplink package 'uplinks/on_mudd' is not a directory"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("tick "), std::string::npos) << "the run must not start: " << r.out;
}

}  // namespace

namespace {

// The contract check is part of the one gate: without its uplink.json consent, on_mud's weaker
// HoldOnUnknown is refused by the running manager as by `gate --uplink`.
TEST_F(BarePackage, AWeakenedGuaranteeWithoutConsentIsRejectedByTheRunToo) {
  fs::remove(mission() / "uplinks" / "on_mud" / "uplink.json");
  const CliRun gate = uabt_in(root(), "gate msl --uplink msl/uplinks/on_mud --out out");
  EXPECT_EQ(gate.exit_code, 1) << gate.out;
  EXPECT_NE(gate.out.find("[uplink-guarantee-weakened]"), std::string::npos) << gate.out;
  const CliRun run = uabt_in(root(), "run msl --scenario msl/scenarios/mud_uplink.json");
  EXPECT_NE(run.out.find("uplink msl/uplinks/on_mud rejected"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("guarantee 'HoldOnUnknown' is restated in a weaker form"),
            std::string::npos)
      << run.out;
}

}  // namespace
