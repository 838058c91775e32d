// `uabt prove` and `uabt gate` from the command line: exit codes, formats, counterexample files.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "prove_support.hpp"

namespace uabt::testing {
namespace {

struct CliRun {
  int code;
  std::string out;
};

CliRun run(const std::string& args) {
  const std::string cmd = std::string(UABT_BINARY) + " " + args + " 2>&1";
  CliRun r{0, ""};
  FILE* p = popen(cmd.c_str(), "r");
  char buffer[4096];
  while (std::size_t n = fread(buffer, 1, sizeof buffer, p)) r.out.append(buffer, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(ProveCli, ViolationExitsOneWithTheTable) {
  const CliRun r = run("prove " + mission_dir("sample_drilling").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("requirements.fret:5:10: error: guarantee 'CoolBit' is violated at tick 1"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("note: 1     RUNNING  true           false      Drill started"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 proved, 1 violated, 0 bounded"), std::string::npos) << r.out;
}

TEST(ProveCli, JsonAndCounterexampleFiles) {
  TempMission scratch({});
  const auto dir = scratch.dir() / "cex";
  const CliRun r = run("prove " + mission_dir("sample_drilling").string() +
                       " --format json --counterexamples " + dir.string());
  EXPECT_EQ(r.code, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["verdict"], "fail");
  EXPECT_EQ(j["complete"], true);
  EXPECT_EQ(j["properties"][0]["id"], "CoolBit");
  EXPECT_EQ(j["properties"][0]["verdict"], "violated");
  EXPECT_EQ(j["properties"][0]["counterexample"]["tick"], 1);
  EXPECT_EQ(j["properties"][1]["verdict"], "proved");
  const auto file = nlohmann::json::parse(read_all(dir / "CoolBit.json"));
  EXPECT_EQ(file, j["properties"][0]["counterexample"]["scenario"]);
  // The scenario is one `uabt run` accepts: it plays to the violating tick.
  const CliRun replay = run("run " + mission_dir("sample_drilling").string() + " --scenario " +
                            (dir / "CoolBit.json").string());
  EXPECT_NE(replay.out.find("tick 1: drilling selects rotary (Soft)"), std::string::npos)
      << replay.out;
  // `uabt run` monitors the mission's properties: it reports the same violation at the same tick.
  EXPECT_EQ(replay.code, 1) << replay.out;
  EXPECT_NE(replay.out.find("tick 1: guarantee CoolBit violated (Drill.running=true, "
                            "IsBitCool=false)"),
            std::string::npos)
      << replay.out;
  EXPECT_NE(replay.out.find("property CoolBit: violated from tick 1"), std::string::npos)
      << replay.out;
}

TEST(ProveCli, SarifPointsAtTheRequirement) {
  const CliRun r = run("prove " + mission_dir("sample_drilling").string() + " --format sarif");
  EXPECT_EQ(r.code, 1);
  const auto j = nlohmann::json::parse(r.out);
  const auto& result = j["runs"][0]["results"][0];
  EXPECT_EQ(result["ruleId"], "prove-violated");
  const auto& region = result["locations"][0]["physicalLocation"]["region"];
  EXPECT_EQ(region["startLine"], 5);
}

TEST(ProveCli, GateFailsOnAViolatedGuaranteeAndKeepsTheRejectedTree) {
  TempMission scratch({});
  const CliRun broken =
      run("gate " + mission_dir("sample_drilling").string() + " --out " + scratch.dir().string());
  EXPECT_EQ(broken.code, 1);
  EXPECT_NE(broken.out.find("[prove-violated]"), std::string::npos) << broken.out;
  EXPECT_TRUE(std::filesystem::exists(scratch.dir() / "compiled.rejected.xml"));
  EXPECT_FALSE(std::filesystem::exists(scratch.dir() / "compiled.xml"));
}

// msl_curiosity's ArmClosed is violated in every selection style: with one-tick actions the
// drive and the opening of the arm succeed in the same tick. HoldOnUnknown holds only with the
// reactive selection. The gate says so instead of passing.
// msl_curiosity declares a reactive selection: the gate proves its four guarantees. The paper's
// sequence style lets a running drive run on over an unknown terrain: HoldOnUnknown is violated
// (3 ticks) and the gate fails, keeping the tree as compiled.rejected.xml.
TEST(ProveCli, CuriosityGateProvesItsGuaranteesAndRejectsTheSequenceStyle) {
  TempMission scratch({});
  const CliRun msl =
      run("gate " + mission_dir("msl_curiosity").string() + " --out " + scratch.dir().string());
  EXPECT_EQ(msl.code, 0) << msl.out;
  std::ifstream summary(scratch.dir() / "summary.md");
  const std::string summary_text((std::istreambuf_iterator<char>(summary)),
                                 std::istreambuf_iterator<char>());
  EXPECT_NE(summary_text.find("stages: load, verify, compile, conform, prove"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(scratch.dir() / "compiled.xml"));

  const auto sequence_out = scratch.dir() / "sequence";
  const CliRun sequence = run("gate " + mission_dir("msl_curiosity").string() +
                              " --selection sequence --out " + sequence_out.string());
  EXPECT_EQ(sequence.code, 1) << sequence.out;
  EXPECT_NE(sequence.out.find("guarantee 'HoldOnUnknown' is violated at tick 3"), std::string::npos)
      << sequence.out;
  EXPECT_TRUE(std::filesystem::exists(sequence_out / "compiled.rejected.xml"));
  EXPECT_FALSE(std::filesystem::exists(sequence_out / "compiled.xml"));

  const CliRun proved = run("prove " + mission_dir("msl_curiosity").string());
  EXPECT_EQ(proved.code, 0) << proved.out;
  EXPECT_NE(proved.out.find("4 guarantees: 4 proved, 0 violated"), std::string::npos) << proved.out;
  const CliRun violated =
      run("prove " + mission_dir("msl_curiosity").string() + " --selection sequence");
  EXPECT_EQ(violated.code, 1) << violated.out;
  EXPECT_NE(violated.out.find("4 guarantees: 3 proved, 1 violated"), std::string::npos)
      << violated.out;
}

TEST(ProveCli, BadWorldFileIsAUsageError) {
  auto files = mission_files("sample_drilling");
  files["world.json"] = "{\"actions\": {\"Drill\": {\"ticks\": [3, 1]}}}";
  TempMission m(files);
  const CliRun r = run("prove " + m.dir().string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("world.json:1:24: error: ticks [3, 1]: min is above max"), std::string::npos)
      << r.out;
}

TEST(ProveCli, ExplainKnowsTheChecks) {
  EXPECT_EQ(run("explain prove-violated").code, 0);
  EXPECT_EQ(run("explain prove-bounded").code, 0);
}

}  // namespace
}  // namespace uabt::testing
