// `uabt prove` and `uabt gate` from the command line: exit codes, formats, counterexample files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>

#include "bench/prove_families.hpp"
#include "cli/cli_support.hpp"
#include "prove_support.hpp"

namespace uabt::testing {
namespace {

CliRun run(const std::string& args) {
  return run_shell(std::string(UABT_BINARY) + " " + args + " 2>&1");
}

TEST(ProveCli, ViolationExitsOneWithTheTable) {
  const CliRun r = run("prove " + mission_dir("sample_drilling").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("requirements.fret:5:10: error: guarantee 'CoolBit' is violated at tick 1"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("note: 1     RUNNING  true           false      Drill started"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 proved, 1 violated, 0 bounded"), std::string::npos) << r.out;
}

TEST(ProveCli, SymbolicEngineNamesItsFigures) {
  const std::string mission = mission_dir("sample_drilling").string();
  const CliRun text = run("prove " + mission + " --engine symbolic");
  EXPECT_EQ(text.exit_code, 1);
  EXPECT_NE(
      text.out.find("requirements.fret:5:10: error: guarantee 'CoolBit' is violated at tick 1"),
      std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("1 proved, 1 violated, 0 bounded (symbolic engine: BMC to depth 2, "
                          "k-induction up to k = 2)"),
            std::string::npos)
      << text.out;
  const CliRun json = run("prove " + mission + " --engine symbolic --format json");
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["engine"], "symbolic");
  EXPECT_EQ(j["bmc_depth"], 2);
  EXPECT_EQ(j["induction_k"], 2);
  EXPECT_FALSE(j.contains("states"));
  EXPECT_EQ(j["properties"][0]["verdict"], "violated");
  EXPECT_EQ(j["properties"][0]["counterexample"]["tick"], 1);
  EXPECT_EQ(j["properties"][1]["verdict"], "proved");
}

// A guarantee IC3/PDR proved says so, not "k-induction with k = 0".
TEST(ProveCli, SymbolicProofsNameHowEachGuaranteeWasProved) {
  const std::string mission = mission_dir("msl_curiosity").string();
  const CliRun text = run("prove " + mission + " --engine symbolic");
  EXPECT_EQ(text.exit_code, 0) << text.out;
  EXPECT_EQ(text.out.find("k = 0"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("guarantee 'NoDrillAway' is proved: the rover shall never satisfy "
                          "Drill.running & !IsInLocation (IC3/PDR, Z3's Spacer)"),
            std::string::npos)
      << text.out;
  // And, as the explicit engine's do, when the guarantee's trigger first holds.
  EXPECT_NE(text.out.find("within 1 tick satisfy navigation.selected = hold_position "
                          "(k-induction with k = 2; its trigger first holds at tick 1)"),
            std::string::npos)
      << text.out;
  const auto j =
      nlohmann::json::parse(run("prove " + mission + " --engine symbolic --format json").out);
  std::map<std::string, std::string> method;
  for (const auto& p : j["properties"]) method[p["id"]] = p.value("method", "");
  EXPECT_EQ(method, (std::map<std::string, std::string>{{"ArmClosed", "IC3/PDR"},
                                                        {"HoldOnUnknown", "k-induction"},
                                                        {"NoDrillAway", "IC3/PDR"},
                                                        {"PictureOfSample", "IC3/PDR"}}));
  // The explicit engine's proofs name their states and transitions instead.
  const auto e = nlohmann::json::parse(run("prove " + mission + " --format json").out);
  for (const auto& p : e["properties"]) EXPECT_FALSE(p.contains("method")) << p;
}

TEST(ProveCli, JsonAndCounterexampleFiles) {
  TempMission scratch({});
  const auto dir = scratch.dir() / "cex";
  const CliRun r = run("prove " + mission_dir("sample_drilling").string() +
                       " --format json --counterexamples " + dir.string());
  EXPECT_EQ(r.exit_code, 1);
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
  EXPECT_EQ(replay.exit_code, 1) << replay.out;
  EXPECT_NE(replay.out.find("tick 1: guarantee CoolBit violated (Drill.running=true, "
                            "IsBitCool=false)"),
            std::string::npos)
      << replay.out;
  EXPECT_NE(replay.out.find("property CoolBit: violated from tick 1"), std::string::npos)
      << replay.out;
}

TEST(ProveCli, SarifPointsAtTheRequirement) {
  const CliRun r = run("prove " + mission_dir("sample_drilling").string() + " --format sarif");
  EXPECT_EQ(r.exit_code, 1);
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
  EXPECT_EQ(broken.exit_code, 1);
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
  EXPECT_EQ(msl.exit_code, 0) << msl.out;
  std::ifstream summary(scratch.dir() / "summary.md");
  const std::string summary_text((std::istreambuf_iterator<char>(summary)),
                                 std::istreambuf_iterator<char>());
  EXPECT_NE(summary_text.find("stages: load, verify, compile, conform, prove"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(scratch.dir() / "compiled.xml"));

  const auto sequence_out = scratch.dir() / "sequence";
  const CliRun sequence = run("gate " + mission_dir("msl_curiosity").string() +
                              " --selection sequence --out " + sequence_out.string());
  EXPECT_EQ(sequence.exit_code, 1) << sequence.out;
  EXPECT_NE(sequence.out.find("guarantee 'HoldOnUnknown' is violated at tick 3"), std::string::npos)
      << sequence.out;
  EXPECT_TRUE(std::filesystem::exists(sequence_out / "compiled.rejected.xml"));
  EXPECT_FALSE(std::filesystem::exists(sequence_out / "compiled.xml"));

  const CliRun proved = run("prove " + mission_dir("msl_curiosity").string());
  EXPECT_EQ(proved.exit_code, 0) << proved.out;
  EXPECT_NE(proved.out.find("4 guarantees: 4 proved, 0 violated"), std::string::npos) << proved.out;
  const CliRun violated =
      run("prove " + mission_dir("msl_curiosity").string() + " --selection sequence");
  EXPECT_EQ(violated.exit_code, 1) << violated.out;
  EXPECT_NE(violated.out.find("4 guarantees: 3 proved, 1 violated"), std::string::npos)
      << violated.out;
}

// FRET's temporal functions and FTP, proved by both engines as `uabt run` monitors them: x
// counts the ticks up to 3 while Work runs (5 ticks). Each function has a guarantee that holds
// and one violated at its shortest tick, whose counterexample replays in `uabt run` to the
// same violation.
TEST(ProveCli, TemporalFunctionsAndFtpAreProvedAndTheirCounterexamplesReplay) {
  TempMission m({{"mission.xml", R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <ReactiveSequence>
      <Script code="x = x &lt; 3 ? x + 1 : 3"/>
      <Work/>
    </ReactiveSequence>
  </BehaviorTree>
</root>
)"},
                 {"domain.fret", "integer x in [0, 3]\n"},
                 {"world.json", R"({"initial": "x = 0", "actions": {
                    "Work": {"ticks": 5, "results": ["success"]}}})"},
                 {"requirements.fret",
                  "PersistedHolds: Mission shall always satisfy x >= 3 -> persisted(1, x >= 2)\n"
                  "PersistedFails: Mission shall always satisfy x >= 2 -> persisted(1, x >= 2)\n"
                  "OccurredHolds: Mission shall always satisfy x = 2 -> occurred(1, x = 1)\n"
                  "OccurredFails: Mission shall always satisfy x = 3 -> occurred(2, x = 1)\n"
                  "PrevOccHolds: Mission shall always satisfy prevOcc(x = 2, x >= 1)\n"
                  "PrevOccFails: Mission shall always satisfy prevOcc(x >= 1, x >= 2)\n"
                  "FtpHolds: Mission shall always satisfy FTP -> x = 1\n"
                  "FtpFails: Mission shall always satisfy FTP | x = 1\n"}});
  const std::map<std::string, int> violated = {
      {"PersistedFails", 2}, {"OccurredFails", 4}, {"PrevOccFails", 2}, {"FtpFails", 2}};
  for (const std::string engine : {"explicit", "symbolic"}) {
    const auto cex = m.dir() / ("cex-" + engine);
    const CliRun r = run("prove " + m.dir().string() + " --engine " + engine +
                         " --format json --counterexamples " + cex.string());
    EXPECT_EQ(r.exit_code, 1) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["properties"].size(), 8u) << r.out;
    for (const auto& p : j["properties"]) {
      const std::string id = p["id"];
      const auto it = violated.find(id);
      if (it == violated.end()) {
        EXPECT_EQ(p["verdict"], "proved") << engine << " " << id;
        continue;
      }
      ASSERT_EQ(p["verdict"], "violated") << engine << " " << id;
      EXPECT_EQ(p["counterexample"]["tick"], it->second) << engine << " " << id;
      const CliRun replay =
          run("run " + m.dir().string() + " --scenario " + (cex / (id + ".json")).string());
      EXPECT_EQ(replay.exit_code, 1) << replay.out;
      EXPECT_NE(
          replay.out.find("property " + id + ": violated from tick " + std::to_string(it->second)),
          std::string::npos)
          << engine << " " << id << "\n"
          << replay.out;
    }
  }
}

// Twelve flags the environment sets and only the guarantee reads after tick 2: the explicit
// engine chooses them as the guarantee's conjunction reaches them (2 N^2 + 5 N + 2 transitions,
// where every flag's two values took tens of thousands), and the counterexample it writes makes
// the same choices: `uabt run` replays it to the same violation at the same tick.
TEST(ProveCli, FlagsOnlyAGuaranteeReadsAreChosenAsItReadsThemAndTheCounterexampleReplays) {
  TempMission scratch({});
  const auto dir = scratch.dir() / "recheck";
  bench::generate_recheck(dir, 12);
  const auto cex = scratch.dir() / "cex";
  const CliRun r = run("prove " + dir.string() + " --counterexamples " + cex.string());
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("error: guarantee 'Ready' is violated at tick 2"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("(explicit-state engine: 17 states, 350 transitions, runs explored up to "
                       "tick 2)"),
            std::string::npos)
      << r.out;
  const CliRun replay = run("run " + dir.string() + " --scenario " + (cex / "Ready.json").string());
  EXPECT_EQ(replay.exit_code, 1) << replay.out;
  EXPECT_NE(replay.out.find("tick 2: guarantee Ready violated"), std::string::npos) << replay.out;
  EXPECT_NE(replay.out.find("property Ready: violated from tick 2"), std::string::npos)
      << replay.out;
}

// What prove's finite state cannot keep, the value of an earlier tick (preBool, preInt,
// preReal), is named, not proved and not silently dropped.
TEST(ProveCli, PreviousValuesAreNamedAsNotProved) {
  auto files = mission_files("sample_drilling");
  files["requirements.fret"] +=
      "Cool: Mission shall always satisfy !Drill.running | preBool(false, IsBitCool)\n";
  TempMission m(files);
  const CliRun r = run("prove " + m.dir().string());
  EXPECT_NE(r.out.find("requirements.fret:7:7: error: guarantee 'Cool' cannot be proved: "
                       "preBool/preInt/preReal read the value of an earlier tick, which prove's "
                       "finite state does not keep: not supported by prove [fretish-unsupported]"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 not checked"), std::string::npos) << r.out;
}

TEST(ProveCli, BadWorldFileIsAUsageError) {
  auto files = mission_files("sample_drilling");
  files["world.json"] = "{\"actions\": {\"Drill\": {\"ticks\": [3, 1]}}}";
  TempMission m(files);
  const CliRun r = run("prove " + m.dir().string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("world.json:1:24: error: ticks [3, 1]: min is above max"), std::string::npos)
      << r.out;
}

// world.json follows the rules scenarios follow (ARCHITECTURE §8): every input error is exit 2 from
// `prove` and a finding at its place in the gate, with "did you mean" for a likely typo.
TEST(ProveCli, WorldFileIsCheckedAgainstTheMission) {
  struct Case {
    std::string world, at, message, check;
  };
  const std::vector<Case> cases = {
      {R"({"actions": {"Drill": {"ticks": 2, "on_success": "IsBitCool = false; wind = 1000"}}})",
       "1000",
       "on_success of 'Drill': wind = 1000 is out of its range [0, 15] (declared integer at "
       "domain.fret:",
       "load-file"},
      {R"({"actions": {"Drill": {"ticks": 2, "on_success": "IsBitCol = true"}}})", "IsBitCol =",
       "on_success of 'Drill' writes 'IsBitCol', which is neither a variable of the domain nor a "
       "condition of the mission (did you mean 'IsBitCool'?)",
       "load-file"},
      {R"({"actions": {"Drill": {"ticks": 2, "on_failure": "wind = 30 / wind"}}})", "/ wind",
       "on_failure of 'Drill' divides by wind, which is zero in a state the domain allows (",
       "guard-division-by-zero"},
      // BehaviorTree.CPP's ~ turns a boolean into an integer: the effect leaves the domain.
      {R"({"actions": {"Drill": {"ticks": 2, "results": ["failure"], )"
       R"("on_failure": "IsBitCool = false; HardRock = ~HardRock"}}})",
       "\"Drill\"", "action 'Drill' on_failure: HardRock = -", "load-file"},
  };
  for (const Case& c : cases) {
    auto files = mission_files("sample_drilling");
    files["domain.fret"] += "integer wind in [0, 15]\n";
    files["world.json"] = c.world;
    TempMission m(files);
    const std::string column = std::to_string(c.world.find(c.at) + 1);
    const CliRun prove = run("prove " + m.dir().string());
    EXPECT_EQ(prove.exit_code, 2) << c.world << "\n" << prove.out;
    EXPECT_NE(prove.out.find("world.json:1:" + column + ": error: " + c.message), std::string::npos)
        << c.world << "\n"
        << prove.out;
    const CliRun gate = run("gate " + m.dir().string() + " --format json");
    EXPECT_EQ(gate.exit_code, 1) << gate.out;
    const auto j = nlohmann::json::parse(gate.out.substr(gate.out.find('{')));
    bool found = false;
    for (const auto& f : j["findings"])
      found = found || (f["check"] == c.check && f["location"]["file"] == "world.json" &&
                        f["location"]["column"] == std::stoi(column));
    EXPECT_TRUE(found) << gate.out;
  }
  // A directory where the file should be is an input error too, not an absent world model.
  auto files = mission_files("sample_drilling");
  files.erase("world.json");
  files["world.json/keep"] = "";
  TempMission m(files);
  const CliRun prove = run("prove " + m.dir().string());
  EXPECT_EQ(prove.exit_code, 2) << prove.out;
  EXPECT_NE(prove.out.find("world.json: error: is a directory, not a file"), std::string::npos)
      << prove.out;
}

// An entry for an action that only an uplink adds is kept, with a warning at the entry: it
// describes nothing on board.
TEST(ProveCli, AWorldEntryNoTreeRunsIsAWarning) {
  auto files = mission_files("sample_drilling");
  std::string& world = files["world.json"];
  const std::string entry = R"("TurnLeft": {"ticks": 1}, )";
  world.insert(world.find("\"actions\"") + std::string("\"actions\": {").size(), entry);
  TempMission m(files);
  const CliRun prove = run("prove " + m.dir().string());
  EXPECT_EQ(prove.exit_code, 1) << "CoolBit is violated as without the entry\n" << prove.out;
  EXPECT_NE(prove.out.find(": warning: no tree of the mission runs 'TurnLeft': its entry takes "
                           "effect only once an uplink adds it [world-unknown-action]"),
            std::string::npos)
      << prove.out;
  const CliRun gate = run("gate " + m.dir().string() + " --format json");
  const auto j = nlohmann::json::parse(gate.out.substr(gate.out.find('{')));
  int warnings = 0;
  for (const auto& f : j["findings"])
    warnings += f["check"] == "world-unknown-action" && f["severity"] == "warning" &&
                f["location"]["file"] == "world.json";
  EXPECT_EQ(warnings, 1) << gate.out;
}

// A misspelt entry leaves the real action undescribed: the warning names it.
TEST(ProveCli, AMisspeltWorldEntryNamesTheActionLeftUndescribed) {
  auto files = mission_files("sample_drilling");
  std::string& world = files["world.json"];
  world.replace(world.find("\"Drill\""), 7, "\"Dril\"");
  TempMission m(files);
  const CliRun prove = run("prove " + m.dir().string());
  EXPECT_NE(prove.out.find("world.json:5:5: warning: no tree of the mission runs 'Dril'"),
            std::string::npos)
      << prove.out;
  EXPECT_NE(prove.out.find("note: did you mean 'Drill'? That leaf has no entry: as written, it "
                           "may do anything and writes nothing in the proof"),
            std::string::npos)
      << prove.out;
}

// BT.CPP ignores a misspelt main_tree_to_execute: with one tree that passed unnoticed, with
// two it surfaced as prove-bounded. Either way it is one error at the attribute.
TEST(ProveCli, MisspeltMainTreeIsOneErrorAtTheAttribute) {
  for (const bool two_trees : {false, true}) {
    auto files = mission_files("sample_drilling");
    std::string& xml = files["mission.xml"];
    xml.replace(xml.find("main_tree_to_execute"), 20, "main_tree_to_exectue");
    if (two_trees)
      xml.replace(
          xml.find("</root>"), 7,
          "  <BehaviorTree ID=\"Spare\">\n    <AlwaysSuccess/>\n  </BehaviorTree>\n</root>");
    TempMission m(files);
    const CliRun gate = run("gate " + m.dir().string() + " --out " + m.dir().string() + "/out");
    EXPECT_EQ(gate.exit_code, 1) << gate.out;
    EXPECT_NE(gate.out.find("mission.xml:5:24: error: unknown attribute 'main_tree_to_exectue' on "
                            "<root>: BehaviorTree.CPP ignores it; did you mean "
                            "'main_tree_to_execute'? [bt-structure]\n"),
              std::string::npos)
        << gate.out;
    EXPECT_EQ(gate.out.find("prove-bounded"), std::string::npos) << gate.out;
    EXPECT_EQ(std::count(gate.out.begin(), gate.out.end(), '\n'), 2)
        << "one finding and the verdict\n"
        << gate.out;
  }
}

// A mission that states no guarantee: nothing to prove, said in one line, exit 0.
TEST(ProveCli, NoGuaranteesIsSaid) {
  const CliRun text = run("prove " + mission_dir("planetary_landing").string());
  EXPECT_EQ(text.exit_code, 0) << text.out;
  EXPECT_EQ(text.out,
            "prove: planetary_landing states no guarantees (requirements that choose no "
            "alternative and are not about the Environment): nothing to prove\n");
  const CliRun json = run("prove " + mission_dir("planetary_landing").string() + " --format json");
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["engine"], "none");
  EXPECT_EQ(j["verdict"], "pass");
  EXPECT_TRUE(j["properties"].empty());
}

TEST(ProveCli, ExplainKnowsTheChecks) {
  EXPECT_EQ(run("explain prove-violated").exit_code, 0);
  EXPECT_EQ(run("explain prove-bounded").exit_code, 0);
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

// The gate's report directory: the Proofs section, the scenario under counterexamples/ that
// `uabt run` replays, the SARIF message with the table, JUnit's failure; a later passing run
// leaves no stale scenario behind.
TEST(ProveCli, GateReportsShowTheProofs) {
  TempMission scratch({});
  const auto out = scratch.dir() / "report";
  const std::string mission = mission_dir("sample_drilling").string();
  EXPECT_EQ(run("gate " + mission + " --out " + out.string()).exit_code, 1);
  const std::string html = read_all(out / "report.html");
  EXPECT_NE(html.find("<section id=\"proofs\">"), std::string::npos);
  EXPECT_NE(html.find("<table class=\"timeline\">"), std::string::npos);
  const std::string scenario = (out / "counterexamples/CoolBit.json").string();
  EXPECT_NE(html.find("uabt run " + mission + " --scenario " + scenario), std::string::npos);
  EXPECT_NE(read_all(out / "summary.md").find("### Proofs"), std::string::npos);
  const auto json = nlohmann::json::parse(read_all(out / "findings.json"));
  EXPECT_EQ(json["proofs"]["properties"][0]["counterexample"]["scenario_file"], scenario);
  EXPECT_EQ(json["proofs"]["properties"][1]["verdict"], "proved");
  const auto sarif = nlohmann::json::parse(read_all(out / "findings.sarif"));
  const auto& result = sarif["runs"][0]["results"][0];
  EXPECT_EQ(result["ruleId"], "prove-violated");
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["region"]["startLine"], 5);
  EXPECT_NE(result["message"]["text"].get<std::string>().find(
                "\n1     RUNNING  true           false      Drill started"),
            std::string::npos)
      << result["message"]["text"];
  const std::string junit = read_all(out / "junit.xml");
  EXPECT_NE(junit.find("prove-violated"), std::string::npos);
  EXPECT_NE(junit.find("<failure"), std::string::npos);
  const CliRun replay = run("run " + mission + " --scenario " + scenario);
  EXPECT_NE(replay.out.find("property CoolBit: violated from tick 1"), std::string::npos)
      << replay.out;

  auto files = mission_files("sample_drilling");
  // Both alternatives now cool the bit: CoolDown is no longer a unique id, OneTool goes.
  files["requirements.fret"] =
      "Hard: In drilling if HardRock Mission shall satisfy selected_alt = percussive\n"
      "Soft: In drilling Mission shall satisfy selected_alt = rotary\n"
      "CoolBit: Mission shall always satisfy Drill.running -> IsBitCool\n";
  files["alternatives/drilling/rotary.xml"] = kFixedRotary;
  TempMission fixed(files);
  const CliRun pass = run("gate " + fixed.dir().string() + " --out " + out.string());
  EXPECT_EQ(pass.exit_code, 0) << pass.out;
  EXPECT_FALSE(std::filesystem::exists(out / "counterexamples"));
  EXPECT_EQ(read_all(out / "report.html").find("<table class=\"timeline\">"), std::string::npos);
}

TEST(ProveCli, HtmlFormatIsAPageWithTheTimeline) {
  const CliRun r = run("prove " + mission_dir("sample_drilling").string() + " --format html");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out.rfind("<!DOCTYPE html>", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("<table class=\"timeline\">"), std::string::npos);
  EXPECT_EQ(r.out.find("<script"), std::string::npos);
  EXPECT_EQ(r.out.find("http"), std::string::npos);
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

// msl_curiosity declares a reactive selection; gated in the paper's sequence style it violates
// HoldOnUnknown, and the replay command the report gives runs in that same style.
TEST(ProveCli, SequenceGateReplaysInItsStyle) {
  TempMission scratch({});
  const auto out = scratch.dir() / "report";
  const std::string mission = mission_dir("msl_curiosity").string();
  EXPECT_EQ(run("gate " + mission + " --selection sequence --out " + out.string()).exit_code, 1);
  const auto json = nlohmann::json::parse(read_all(out / "findings.json"));
  std::string replay;
  std::uint64_t tick = 0;
  ASSERT_TRUE(json.contains("proofs")) << json.dump(2);
  for (const auto& p : json["proofs"]["properties"])
    if (p["id"] == "HoldOnUnknown") {
      replay = p["counterexample"]["replay"];
      tick = p["counterexample"]["tick"];
    }
  EXPECT_EQ(tick, 3u);
  const std::string scenario = (out / "counterexamples/HoldOnUnknown.json").string();
  EXPECT_EQ(replay, "uabt run " + mission + " --selection sequence --scenario " + scenario);
  const CliRun r = run(replay.substr(std::string("uabt ").size()));
  EXPECT_NE(r.out.find("property HoldOnUnknown: violated from tick " + std::to_string(tick)),
            std::string::npos)
      << r.out;
  // Without the style, the mission's own (reactive) runs the same scenario without violation.
  const CliRun declared = run("run " + mission + " --scenario " + scenario);
  EXPECT_EQ(declared.out.find("property HoldOnUnknown: violated"), std::string::npos)
      << declared.out;
}

}  // namespace
}  // namespace uabt::testing
