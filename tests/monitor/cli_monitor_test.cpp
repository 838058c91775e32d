// `uabt monitor REQUIREMENTS TRACE`: verdicts, first violation with the values read,
// not-monitored with its reason, exit codes, and errors that name file and line.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "cli/cli_support.hpp"
#include "monitor_test_support.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

using Files = std::map<std::string, std::string>;

CliRun uabt_in(const std::filesystem::path& dir, const std::string& args) {
  return run_shell("cd '" + dir.string() + "' && '" + std::string(UABT_BINARY) + "' " + args +
                   " 2>&1");
}

const char* kRequirements =
    "# the rover stops within 2 ticks of mud, and never drives with the arm open\n"
    "Stop: upon OnMud the rover shall within 2 ticks satisfy stopped\n"
    "Arm: the rover shall never satisfy arm_open & driving\n"
    "Home: the rover shall eventually satisfy at_target\n"
    "Env: the Environment shall always satisfy !(OnMud & OnDust)\n";

TEST(MonitorCli, ReportsTheFirstViolationWithTheValuesRead) {
  TempMission files(
      Files{{"r.fret", kRequirements},
            {"run.jsonl",
             "{\"tick\": 0, \"state\": {\"OnMud\": false, \"OnDust\": true, \"stopped\": "
             "false, \"arm_open\": false, \"driving\": true, \"at_target\": false}}\n"
             "{\"tick\": 1, \"state\": {\"OnMud\": true, \"OnDust\": false}}\n"
             "{\"tick\": 2, \"state\": {}}\n"
             "{\"tick\": 3, \"state\": {}}\n"
             "{\"tick\": 4, \"state\": {\"stopped\": true, \"at_target\": true}}\n"}});
  const CliRun text = uabt_in(files.dir(), "monitor r.fret run.jsonl");
  EXPECT_EQ(text.exit_code, 1) << text.out;
  EXPECT_EQ(text.out,
            "r.fret:2:7: Stop: violated from tick 3 (OnMud=true, stopped=false)\n"
            "r.fret:3:6: Arm: held\n"
            "r.fret:4:7: Home: held\n"
            "r.fret:5:6: Env (assumption): held\n"
            "verdict: fail (5 ticks; 3 held, 1 violated, 0 not monitored)\n");
  const CliRun json = uabt_in(files.dir(), "monitor r.fret run.jsonl --format json");
  EXPECT_EQ(json.exit_code, 1);
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["verdict"], "fail");
  EXPECT_EQ(doc["requirements"][0]["id"], "Stop");
  EXPECT_EQ(doc["requirements"][0]["verdict"], "violated");
  EXPECT_EQ(doc["requirements"][0]["first_violation"], 3);
  EXPECT_TRUE(doc["requirements"][0]["reason"].is_null());
  EXPECT_EQ(doc["requirements"][0]["values"]["stopped"], false);
  EXPECT_EQ(doc["requirements"][1]["verdict"], "held");
  EXPECT_TRUE(doc["requirements"][1]["first_violation"].is_null());
  EXPECT_EQ(doc["requirements"][3]["role"], "assumption");
}

TEST(MonitorCli, PassesWhenEveryGuaranteeHolds) {
  TempMission files(
      Files{{"r.fret", kRequirements},
            {"run.jsonl",
             "{\"tick\": 10, \"state\": {\"OnMud\": false, \"OnDust\": true, "
             "\"stopped\": false, \"arm_open\": true, \"driving\": false, "
             "\"at_target\": false}}\n"
             "{\"tick\": 11, \"state\": {\"OnMud\": true, \"OnDust\": false}}\n"
             "{\"tick\": 12, \"state\": {\"stopped\": true, \"at_target\": true}}\n"}});
  const CliRun run = uabt_in(files.dir(), "monitor r.fret run.jsonl");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("verdict: pass (3 ticks; 4 held"), std::string::npos) << run.out;
}

TEST(MonitorCli, MissingVariablesAreNotMonitoredWithTheReason) {
  TempMission files(Files{{"r.fret", "Arm: the rover shall never satisfy arm_open & driving\n"},
                          {"run.jsonl", "{\"tick\": 0, \"state\": {\"driving\": true}}\n"}});
  const CliRun run = uabt_in(files.dir(), "monitor r.fret run.jsonl --format json");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  const auto doc = nlohmann::json::parse(run.out);
  EXPECT_EQ(doc["requirements"][0]["verdict"], "not-monitored");
  EXPECT_EQ(doc["requirements"][0]["reason"], "response: the trace has no variable 'arm_open'");
  EXPECT_EQ(doc["verdict"], "inconclusive");  // nothing violated, nothing to pass on
}

// A division by zero matters only where the result depends on it (ARCHITECTURE §14): a true
// disjunct decides, whichever side it is written on; where none decides, the requirement is
// not monitored with the reason.
TEST(MonitorCli, ADivisionByZeroThatDoesNotDecideTheResultIsNoReasonToGiveUp) {
  TempMission files(Files{{"r.fret",
                           "Safe: the rover shall always satisfy 10 / x > 1 | x = 0\n"
                           "Other: the rover shall always satisfy 10 / x > 1 | x = 1\n"},
                          {"run.jsonl",
                           "{\"tick\": 0, \"state\": {\"x\": 5}}\n"
                           "{\"tick\": 1, \"state\": {\"x\": 0}}\n"}});
  const CliRun run = uabt_in(files.dir(), "monitor r.fret run.jsonl --format json");
  const auto doc = nlohmann::json::parse(run.out);
  EXPECT_EQ(doc["requirements"][0]["verdict"], "held") << run.out;
  EXPECT_EQ(doc["requirements"][1]["verdict"], "not-monitored") << run.out;
  EXPECT_EQ(doc["requirements"][1]["reason"], "at tick 1, the response: division by zero")
      << run.out;
}

// FRET formalizes nextOcc only in future time; the monitor says so in FRET's terms, and a
// persisted(n, p) whose n is not a number is refused as FRET leaves it unexpanded.
TEST(MonitorCli, TemporalFunctionsFretCannotMonitorAreNamedWithFretsReason) {
  TempMission files(Files{{"r.fret",
                           "N: the sw shall always satisfy at the next occurrence of hot, fan\n"
                           "P: the sw shall always satisfy persisted(k, hot)\n"
                           "W: the sw shall always satisfy occurred(1, 3, hot)\n"},
                          {"run.jsonl",
                           "{\"tick\": 0, \"state\": {\"hot\": true, \"fan\": true, \"k\": 2}}\n"
                           "{\"tick\": 1, \"state\": {}}\n"}});
  const CliRun run = uabt_in(files.dir(), "monitor r.fret run.jsonl");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_EQ(run.out,
            "r.fret:1:4: N: not-monitored: response: FRET's 'nextOcc' looks ahead to the next "
            "occurrence: FRET expands it only into future-time LTL, ($Right$ | (X (((!p & "
            "!$Right$) U p) => ((!p & !$Right$) U (p & q))))), and its past-time formula, the "
            "one a monitor evaluates, keeps it unexpanded\n"
            "r.fret:2:4: P: not-monitored: response: the first argument of 'persisted' is 'k': "
            "FRET expands persisted(n, p) only for a whole number of ticks n\n"
            "r.fret:3:4: W: not-monitored: response: FRET's 'occurred(m, n, p)' needs p at each "
            "of the last n ticks (S[m,n]); only occurred(n, p) is monitored\n"
            "verdict: inconclusive (2 ticks; 0 held, 0 violated, 3 not monitored)\n");
}

TEST(MonitorCli, BadTracesAreErrorsWithFileAndLine) {
  TempMission files(
      Files{{"r.fret", "Arm: the rover shall never satisfy arm_open\n"},
            {"gap.jsonl",
             "{\"tick\": 0, \"state\": {\"arm_open\": false}}\n"
             "{\"tick\": 2, \"state\": {\"arm_open\": true}}\n"},
            {"junk.jsonl", "{\"tick\": 0, \"state\": {\"arm_open\": false}}\nnope\n"},
            {"domain.fret", "integer speed in [0, 10]\n"},
            {"typed.jsonl", "{\"tick\": 0, \"state\": {\"speed\": true, \"arm_open\": false}}\n"}});
  const CliRun gap = uabt_in(files.dir(), "monitor r.fret gap.jsonl");
  EXPECT_EQ(gap.exit_code, 1);
  EXPECT_EQ(gap.out,
            "gap.jsonl:2:1: error: tick 2 follows tick 0: a trace has one line per tick, in "
            "order [trace-invalid]\n");
  const CliRun junk = uabt_in(files.dir(), "monitor r.fret junk.jsonl");
  EXPECT_EQ(junk.exit_code, 1);
  EXPECT_NE(junk.out.find("junk.jsonl:2:2: error: not a trace line: invalid JSON"),
            std::string::npos)
      << junk.out;
  const CliRun typed = uabt_in(files.dir(), "monitor r.fret typed.jsonl --domain domain.fret");
  EXPECT_EQ(typed.exit_code, 1);
  EXPECT_NE(typed.out.find("typed.jsonl:1:1: error: 'speed' at tick 0 does not fit its type: "
                           "the domain declares it integer [trace-invalid]"),
            std::string::npos)
      << typed.out;
  EXPECT_EQ(uabt_in(files.dir(), "monitor r.fret no_such.jsonl").exit_code, 2);
}

// A requirements file with no requirement (only comments, or nothing) checks nothing: that is
// no pass but an input error naming the file.
TEST(MonitorCli, NothingToMonitorIsAnInputError) {
  TempMission files(Files{{"empty.fret", "# nothing stated yet\n"},
                          {"run.jsonl", "{\"tick\": 0, \"state\": {\"arm_open\": false}}\n"}});
  for (const std::string format : {"text", "json"}) {
    const CliRun run = uabt_in(files.dir(), "monitor empty.fret run.jsonl --format " + format);
    EXPECT_EQ(run.exit_code, 2) << run.out;
    EXPECT_EQ(run.out, "empty.fret: error: nothing to monitor: the file states no requirement\n");
  }
}

// An obligation still open when the trace ends holds (FRET's finite-trace meaning), and the
// report says it is pending: what is due and the tick that triggered it.
TEST(MonitorCli, AnObligationOpenAtTheEndIsHeldButPending) {
  TempMission files(Files{
      {"r.fret",
       "Stop: upon OnMud the rover shall within 5 ticks satisfy stopped\n"
       "Arm: the rover shall never satisfy arm_open\n"},
      {"run.jsonl",
       "{\"tick\": 0, \"state\": {\"OnMud\": false, \"stopped\": false, \"arm_open\": false}}\n"
       "{\"tick\": 1, \"state\": {\"OnMud\": true}}\n"
       "{\"tick\": 2, \"state\": {\"stopped\": true, \"OnMud\": false}}\n"
       "{\"tick\": 3, \"state\": {\"stopped\": false, \"OnMud\": true}}\n"}});
  const CliRun text = uabt_in(files.dir(), "monitor r.fret run.jsonl");
  EXPECT_EQ(text.exit_code, 0) << text.out;
  EXPECT_EQ(text.out,
            "r.fret:1:7: Stop: held (pending at end: stopped within 5 ticks, triggered at tick 3)\n"
            "r.fret:2:6: Arm: held\n"
            "verdict: pass (4 ticks; 2 held, 0 violated, 0 not monitored)\n");
  const CliRun json = uabt_in(files.dir(), "monitor r.fret run.jsonl --format json");
  EXPECT_EQ(json.exit_code, 0) << json.out;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["requirements"][0]["verdict"], "held");
  EXPECT_EQ(doc["requirements"][0]["pending"]["obligation"], "stopped within 5 ticks");
  EXPECT_EQ(doc["requirements"][0]["pending"]["since"], 3);
  EXPECT_TRUE(doc["requirements"][1]["pending"].is_null());
  // Discharged before the end: nothing pending.
  files.write(
      "done.jsonl",
      "{\"tick\": 0, \"state\": {\"OnMud\": true, \"stopped\": false, \"arm_open\": false}}\n"
      "{\"tick\": 1, \"state\": {\"stopped\": true}}\n");
  EXPECT_EQ(uabt_in(files.dir(), "monitor r.fret done.jsonl").out,
            "r.fret:1:7: Stop: held\nr.fret:2:6: Arm: held\n"
            "verdict: pass (2 ticks; 2 held, 0 violated, 0 not monitored)\n");
  // Every timing with a deadline, in a mode scope and without a condition; a mode that ended
  // closes its obligations.
  files.write("timed.fret",
              "Nx: upon OnMud the rover shall at the next timepoint satisfy stopped\n"
              "Af: upon OnMud the rover shall after 2 ticks satisfy stopped\n"
              "InM: In driving upon OnMud the rover shall within 4 ticks satisfy stopped\n"
              "NoC: the rover shall within 9 ticks satisfy stopped\n");
  const std::string start =
      "{\"tick\": 0, \"state\": {\"OnMud\": false, \"stopped\": false, \"driving\": true}}\n";
  files.write("late.jsonl", start + "{\"tick\": 1, \"state\": {}}\n" +
                                "{\"tick\": 2, \"state\": {\"OnMud\": true}}\n");
  EXPECT_EQ(
      uabt_in(files.dir(), "monitor timed.fret late.jsonl").out,
      "timed.fret:1:5: Nx: held (pending at end: stopped at the next tick, triggered at tick "
      "2)\n"
      "timed.fret:2:5: Af: held (pending at end: stopped after 2 ticks, triggered at tick 2)\n"
      "timed.fret:3:6: InM: held (pending at end: stopped within 4 ticks, triggered at tick "
      "2)\n"
      "timed.fret:4:6: NoC: held (pending at end: stopped within 9 ticks, triggered at tick "
      "0)\n"
      "verdict: pass (3 ticks; 4 held, 0 violated, 0 not monitored)\n");
  files.write("parked.jsonl", start + "{\"tick\": 1, \"state\": {\"OnMud\": true}}\n" +
                                  "{\"tick\": 2, \"state\": {\"driving\": false}}\n");
  EXPECT_NE(uabt_in(files.dir(), "monitor timed.fret parked.jsonl").out.find("InM: held\n"),
            std::string::npos);
}

TEST(MonitorCli, TickPeriodTurnsTimeUnitsIntoTicks) {
  TempMission files(
      Files{{"r.fret", "Stop: upon OnMud the rover shall within 200 millisecs satisfy stopped\n"},
            {"domain.fret", "boolean OnMud, stopped\ntick 100 ms\n"},
            {"run.jsonl",
             "{\"tick\": 0, \"state\": {\"OnMud\": true, \"stopped\": false}}\n"
             "{\"tick\": 1, \"state\": {}}\n"
             "{\"tick\": 2, \"state\": {\"stopped\": true}}\n"}});
  EXPECT_EQ(uabt_in(files.dir(), "monitor r.fret run.jsonl --domain domain.fret").exit_code, 0);
  // Without a tick period the duration has no meaning in ticks: an error at the duration, and
  // no verdict.
  const CliRun no_period = uabt_in(files.dir(), "monitor r.fret run.jsonl");
  EXPECT_EQ(no_period.exit_code, 1);
  EXPECT_EQ(no_period.out,
            "r.fret:1:41: error: Stop: timing 'within 200 millisecs' is not in ticks and the "
            "domain declares no tick period (e.g. 'tick 100 ms' in domain.fret) "
            "[property-timing]\n");
}

// FRET's own export, as it ships: FSM-007 ("within 5 ticks") violated by a trace where the
// response fails for five ticks.
TEST(MonitorCli, FretExportAsItShips) {
  const auto path = fret_reference("fsm_reqts_and_vars.json");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no FRET data";
  std::string trace;
  for (int t = 0; t < 6; ++t)
    trace += "{\"tick\": " + std::to_string(t) +
             ", \"state\": {\"state\": 1, \"ap_maneuver_state\": 1, \"supported\": true, "
             "\"good\": true, \"STATE\": 0, \"ap_transition_state\": 2, \"standby\": false, "
             "\"ap_standby_state\": 3, \"ap_nominal_state\": 4, \"apfail\": false, \"limits\": "
             "false, \"pullup\": false, \"senstate\": 0, \"request\": false, "
             "\"SENSTATE\": 0, \"sen_nominal_state\": 5, \"sen_fault_state\": 6, "
             "\"sen_transition_state\": 7}}\n";
  TempMission files(Files{{"run.jsonl", trace}});
  const CliRun run =
      uabt_in(files.dir(), "monitor '" + path.string() + "' run.jsonl --format json");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  const auto doc = nlohmann::json::parse(run.out);
  ASSERT_EQ(doc["requirements"].size(), 13u);
  for (const auto& r : doc["requirements"]) {
    EXPECT_NE(r["verdict"], "not-monitored") << r.dump();
    if (r["id"] == "FSM-007") {
      EXPECT_EQ(r["verdict"], "violated");
      EXPECT_EQ(r["first_violation"], 5);
    }
  }
}

// The classes where uabt once disagreed with FRET's formalizer. Each case carries FRET's
// formula for the sentence: semantics.json's ptExpanded for its key, filled with the fields as
// FRET's SemanticsAnalyzer rewrites them (`if A then B` -> `A => B`); the oracle evaluates it on
// the same trace and `uabt monitor` must give the same verdict.
TEST(MonitorCli, ExpressionsMeanWhatFretFormalizes) {
  struct Case {
    const char* sentence;
    const char* fret_formula;
    const char* domain;  // declarations, or "" for types as JSON writes them
    std::vector<std::map<std::string, std::string>> trace;  // JSON values a tick
    const char* verdict;
  };
  const std::vector<Case> cases = {
      // null,null,always: (H $post_condition$), post_condition "(q & p => r)".
      {"the sw shall always satisfy q & if p then r",
       "(H ((q & p) => r))",
       "",
       {{{"p", "false"}, {"q", "false"}, {"r", "false"}}},
       "held"},
      {"the sw shall always satisfy q & if p then r",
       "(H ((q & p) => r))",
       "",
       {{{"p", "true"}, {"q", "true"}, {"r", "false"}}},
       "violated from tick 0 (q=true, p=true, r=false)"},
      // FRET's NUMBER carries its sign: -1 ^ 2 is 1.
      {"the sw shall always satisfy x > -1 ^ 2",
       "(H (x > -1 ^ 2))",
       "",
       {{{"x", "0"}}},
       "violated from tick 0 (x=0)"},
      {"the sw shall always satisfy x > -1 ^ 2", "(H (x > -1 ^ 2))", "", {{{"x", "2"}}}, "held"},
      // Integers divide as integers: 1 / 2 is 0.
      {"the sw shall always satisfy n / 2 > x",
       "(H (n / 2 > x))",
       "integer n, x\n",
       {{{"n", "1"}, {"x", "0"}}},
       "violated from tick 0 (n=1, x=0)"},
      {"the sw shall always satisfy n mod 4 = -3 & n / -4 = -1",
       "(H (n mod 4 = -3 & n / -4 = -1))",
       "integer n\n",
       {{{"n", "-7"}}},
       "violated from tick 0 (n=-7)"},
      {"the sw shall always satisfy n mod 4 = -3 & n / -4 = 1",
       "(H (n mod 4 = -3 & n / -4 = 1))",
       "integer n\n",
       {{{"n", "-7"}}},
       "held"},
      // FRET's predefined FTP, as in its Lift+Cruise case study: FTP is (Z FALSE).
      {"the sw shall always satisfy FTP | absReal(preReal(0.0, kias) - kias) <= 10.0",
       "(H ((Z FALSE) | (absReal(preReal(0.0, kias) - kias) <= 10.0)))",
       "",
       {{{"kias", "50"}}, {{"kias", "55"}}, {{"kias", "70"}}},
       "violated from tick 2 (kias=70)"},
      {"the sw shall always satisfy FTP | absReal(preReal(0.0, kias) - kias) <= 10.0",
       "(H ((Z FALSE) | (absReal(preReal(0.0, kias) - kias) <= 10.0)))",
       "",
       {{{"kias", "50"}}, {{"kias", "55"}}, {{"kias", "60"}}},
       "held"},
      // FRET's temporal functions, expanded as its xform.js does, from the scope's first
      // point ($Left$: FTP here, the first point of m for "in m").
      {"upon persisted(2, hot) the sw shall immediately satisfy fan",
       "(H ((((H[<=2] hot) & (H[<2] ! (!(Y TRUE)))) & (Z (! ((H[<=2] hot) & (H[<2] ! (!(Y "
       "TRUE))))))) -> fan))",
       "",
       {{{"hot", "true"}, {"fan", "false"}},
        {{"hot", "true"}, {"fan", "false"}},
        {{"hot", "true"}, {"fan", "false"}}},
       "violated from tick 2 (hot=true, fan=false)"},
      {"upon persisted(2, hot) the sw shall immediately satisfy fan",
       "(H ((((H[<=2] hot) & (H[<2] ! (!(Y TRUE)))) & (Z (! ((H[<=2] hot) & (H[<2] ! (!(Y "
       "TRUE))))))) -> fan))",
       "",
       {{{"hot", "true"}, {"fan", "false"}},
        {{"hot", "true"}, {"fan", "false"}},
        {{"hot", "true"}, {"fan", "true"}}},
       "held"},
      {"in m the sw shall always satisfy occurred(1, hot)",
       "(H (m -> (((! (m & ((!(Y TRUE)) | (Y (!m))))) S hot) & (O[<=1] hot))))",
       "",
       {{{"m", "false"}, {"hot", "true"}},
        {{"m", "true"}, {"hot", "false"}},
        {{"m", "true"}, {"hot", "false"}}},
       "violated from tick 1 (m=true, hot=false)"},
      {"the sw shall always satisfy prevOcc(hot, fan)",
       "(H ((!(Y TRUE)) | (Y (((! (!(Y TRUE)) & !hot) S hot) => ((! (!(Y TRUE)) & !hot) S (hot "
       "& fan))))))",
       "",
       {{{"hot", "true"}, {"fan", "true"}},
        {{"hot", "false"}, {"fan", "false"}},
        {{"hot", "true"}, {"fan", "false"}},
        {{"hot", "false"}, {"fan", "false"}}},
       "violated from tick 3 (hot=false, fan=false)"},
      // Reals stay real.
      {"the sw shall always satisfy y / 2 > x",
       "(H (y / 2 > x))",
       "real y\ninteger x\n",
       {{{"y", "1"}, {"x", "0"}}},
       "held"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.sentence);
    std::string jsonl;
    std::vector<OracleState> oracle_trace;
    const std::string domain = c.domain;
    for (std::size_t t = 0; t < c.trace.size(); ++t) {
      jsonl += "{\"tick\": " + std::to_string(t) + ", \"state\": {";
      OracleState state;
      bool first = true;
      for (const auto& [name, value] : c.trace[t]) {
        jsonl += std::string(first ? "" : ", ") + "\"" + name + "\": " + value;
        first = false;
        if (value == "true" || value == "false") {
          state[name] = OracleValue{false, value == "true", 0, false};
        } else {
          const bool declared_real = domain.find("real " + name) != std::string::npos;
          state[name] = OracleValue{true, false, std::stod(value), !declared_real};
        }
      }
      jsonl += "}}\n";
      oracle_trace.push_back(state);
    }
    const std::vector<bool> fret = PtFormula::parse(c.fret_formula).evaluate(oracle_trace);
    Files files{{"r.fret", std::string("R: ") + c.sentence + "\n"}, {"run.jsonl", jsonl}};
    std::string args = "monitor r.fret run.jsonl";
    if (!domain.empty()) {
      files["domain.fret"] = domain;
      args += " --domain domain.fret";
    }
    TempMission dir(files);
    const CliRun run = uabt_in(dir.dir(), args);
    EXPECT_EQ(run.out.substr(0, run.out.find('\n')), std::string("r.fret:1:4: R: ") + c.verdict)
        << run.out;
    EXPECT_EQ(std::string(c.verdict) == "held", static_cast<bool>(fret.back())) << c.fret_formula;
  }
}

// Nothing violated but a requirement the trace cannot monitor: the verdict says so
// (inconclusive, exit 1), not `fail` with 0 violated; a violation is still `fail`.
TEST(MonitorCli, NotMonitoredWithoutViolationIsInconclusive) {
  TempMission files(Files{{"r.fret",
                           "Arm: the rover shall never satisfy arm_open\n"
                           "Cam: the rover shall always satisfy camera_on\n"},
                          {"run.jsonl",
                           "{\"tick\": 1, \"state\": {\"arm_open\": false}}\n"
                           "{\"tick\": 2, \"state\": {\"arm_open\": false}}\n"},
                          {"open.jsonl",
                           "{\"tick\": 1, \"state\": {\"arm_open\": false}}\n"
                           "{\"tick\": 2, \"state\": {\"arm_open\": true}}\n"}});
  const CliRun text = uabt_in(files.dir(), "monitor r.fret run.jsonl");
  EXPECT_EQ(text.exit_code, 1) << text.out;
  EXPECT_EQ(text.out,
            "r.fret:1:6: Arm: held\n"
            "r.fret:2:6: Cam: not-monitored: response: the trace has no variable 'camera_on'\n"
            "verdict: inconclusive (2 ticks; 1 held, 0 violated, 1 not monitored)\n");
  const CliRun json = uabt_in(files.dir(), "monitor r.fret run.jsonl --format json");
  EXPECT_EQ(json.exit_code, 1) << json.out;
  EXPECT_EQ(nlohmann::json::parse(json.out)["verdict"], "inconclusive");
  const CliRun open = uabt_in(files.dir(), "monitor r.fret open.jsonl");
  EXPECT_EQ(open.exit_code, 1) << open.out;
  EXPECT_NE(open.out.find("verdict: fail (2 ticks; 0 held, 1 violated, 1 not monitored)"),
            std::string::npos)
      << open.out;
}

// "selection|property|assumption ID: VERDICT[ from tick N]" lines of `uabt run`, and the same
// from `uabt monitor --format json`.
std::map<std::string, std::string> run_verdicts(const std::string& out) {
  std::map<std::string, std::string> verdicts;
  static const std::regex line(
      R"(^(?:selection|property|assumption) (\S+): (\S+( from tick \d+)?))");
  std::istringstream in(out);
  for (std::string text; std::getline(in, text);)
    if (std::smatch m; std::regex_search(text, m, line)) verdicts[m[1]] = m[2];
  return verdicts;
}

std::map<std::string, std::string> monitor_verdicts(const std::string& out) {
  std::map<std::string, std::string> verdicts;
  const auto doc = nlohmann::json::parse(out);
  for (const auto& r : doc["requirements"]) {
    std::string verdict = r["verdict"];
    if (!r["first_violation"].is_null())
      verdict += " from tick " + std::to_string(r["first_violation"].get<int>());
    verdicts[r["id"]] = verdict;
  }
  return verdicts;
}

// `uabt run --monitor-trace` records each selection with the values its guards read and the
// adaptable nodes' alternatives and priority orders, so that `uabt monitor` judges the
// selection requirements (and properties that name an alternative never selected, such as
// HoldOnUnknown's hold_position) as the run does, instead of "not monitored".
TEST(MonitorCli, RunThenMonitorJudgeSelectionRequirementsAlike) {
  TempMission m(mission_files("msl_curiosity"), "msl");
  const std::string dir = m.dir().parent_path().string();
  for (const char* scenario :
       {"dusty_start", "rejected_uplink", "rocks_mid_drive", "short_drive"}) {
    SCOPED_TRACE(scenario);
    const CliRun run = uabt_in(dir, std::string("run msl --scenario msl/scenarios/") + scenario +
                                        ".json --monitor-trace t.jsonl");
    const CliRun monitor = uabt_in(
        dir, "monitor msl/requirements.fret t.jsonl --domain msl/domain.fret --format json");
    const auto ran = run_verdicts(run.out);
    EXPECT_EQ(ran.size(), 8u) << run.out;
    EXPECT_EQ(monitor_verdicts(monitor.out), ran) << run.out << monitor.out;
    for (const char* id : {"Req1", "Req2", "Safe", "HoldOnUnknown"})
      EXPECT_EQ(ran.at(id), "held") << id;
    EXPECT_EQ(monitor.exit_code, run.exit_code) << run.out << monitor.out;
  }
}

// An accepted uplink adds Req3, which the mission's own requirements do not state: the trace's
// selection lines carry each requirement as the run stated it, so that monitor, given the
// mission, judges every selection requirement as the run did, Req3 too (at the uplink's line).
// A trace without those sentences (written before they were recorded) still reads, and
// monitor says which requirement it lacks.
TEST(MonitorCli, RunThenMonitorJudgeAnUplinksSelectionRequirements) {
  TempMission m(mission_files("msl_curiosity"), "msl");
  const std::string dir = m.dir().parent_path().string();
  const CliRun run =
      uabt_in(dir, "run msl --scenario msl/scenarios/mud_uplink.json --monitor-trace t.jsonl");
  ASSERT_NE(run.out.find("tick 30: navigation selects on_mud (Req3)"), std::string::npos)
      << run.out;
  const auto ran = run_verdicts(run.out);
  const CliRun monitor = uabt_in(dir, "monitor msl t.jsonl --format json");
  const auto judged = monitor_verdicts(monitor.out);
  for (const char* id : {"Req1", "Req2", "Req3", "Safe"}) {
    ASSERT_EQ(ran.count(id), 1u) << id << run.out;
    ASSERT_EQ(judged.count(id), 1u) << id << monitor.out;
    EXPECT_EQ(judged.at(id), ran.at(id)) << id << monitor.out;
  }
  EXPECT_EQ(monitor.exit_code, 0) << monitor.out;
  const CliRun text =
      uabt_in(dir, "monitor msl/requirements.fret t.jsonl --domain msl/domain.fret");
  EXPECT_NE(text.out.find("msl/requirements.fret:3:7: Req1 (selection): held\n"), std::string::npos)
      << text.out;
  // Named so that it opens from where the command ran, like the mission's own requirements.
  EXPECT_NE(text.out.find("\nmsl/uplinks/on_mud/requirements.fret:2:7: Req3 (selection): held\n"),
            std::string::npos)
      << text.out;
  std::error_code ec;
  EXPECT_TRUE(std::filesystem::is_regular_file(
      m.dir().parent_path() / "msl/uplinks/on_mud/requirements.fret", ec));

  // The same trace without the sentences.
  std::ifstream in(m.dir().parent_path() / "t.jsonl");
  std::string old_trace;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("{\"selection\"", 0) == 0) {
      auto header = nlohmann::json::parse(line);
      for (auto& [id, node] : header["selection"].items()) node.erase("sentences");
      line = header.dump();
    }
    old_trace += line + "\n";
  }
  std::ofstream(m.dir().parent_path() / "old.jsonl", std::ios::binary) << old_trace;
  const CliRun old = uabt_in(dir, "monitor msl old.jsonl");
  EXPECT_NE(old.out.find("Req1 (selection): not-monitored: the run selected by requirement "
                         "'Req3' of 'navigation', which these requirements do not state"),
            std::string::npos)
      << old.out;
  EXPECT_EQ(old.out.find("Req3 (selection)"), std::string::npos) << old.out;
}

// An uplink restates the selection requirement FlightAbort with a new guard: from the swap on,
// the run judges the selections by the merged requirements (the restated guard), and the old
// statement stops at the swap, as properties do. `uabt monitor` on the run's trace agrees.
TEST(MonitorCli, RunJudgesARestatedSelectionRequirementByItsNewGuard) {
  const auto flight = [](const std::string& alt) {
    return "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"" + alt + "\">\n    <Fly_" + alt +
           "/>\n  </BehaviorTree>\n</root>\n";
  };
  TempMission m(
      Files{{"mission.xml",
             "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
             "  <BehaviorTree ID=\"MainTree\">\n"
             "    <Sequence name=\"climb\">\n      <Ascend/>\n      <Adaptable ID=\"flight\"/>\n"
             "    </Sequence>\n  </BehaviorTree>\n</root>\n"},
            {"alternatives/flight/cruise.xml", flight("cruise")},
            {"alternatives/flight/abort.xml", flight("abort")},
            {"domain.fret", "boolean Abort, Override\n"},
            {"requirements.fret",
             "FlightAbort: In flight if Abort Mission shall satisfy selected_alt = abort\n"
             "Cruise: In flight Mission shall satisfy selected_alt = cruise\n"},
            {"uplinks/override/requirements.fret",
             "FlightAbort: In flight if Abort & !Override Mission shall satisfy selected_alt = "
             "abort\n"},
            // Override from the start, Abort from tick 4, when Ascend ends and `flight` selects.
            {"scenarios/abort.json",
             "{\"max_ticks\": 20, \"initial\": {\"Override\": true},\n"
             " \"actions\": {\"Ascend\": {\"ticks\": 4}},\n"
             " \"events\": [{\"at\": 4, \"set\": {\"Abort\": true}}]}\n"}},
      "flight");
  const std::string dir = m.dir().parent_path().string();
  const CliRun run = uabt_in(dir,
                             "run flight --scenario flight/scenarios/abort.json --uplink "
                             "2:flight/uplinks/override --monitor-trace t.jsonl");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("tick 4: flight selects cruise (Cruise)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("selection FlightAbort: held (monitored until tick 1, when an uplink "
                         "replaced or removed it)\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("selection FlightAbort: held (added by an uplink: monitored from tick "
                         "2)\n"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("violated"), std::string::npos) << run.out;

  const CliRun monitor = uabt_in(dir, "monitor flight t.jsonl --format json");
  EXPECT_EQ(monitor.exit_code, 0) << monitor.out;
  const auto doc = nlohmann::json::parse(monitor.out);
  int judged = 0;
  for (const auto& r : doc["requirements"])
    if (r["id"] == "FlightAbort") {
      ++judged;
      EXPECT_EQ(r["verdict"], "held") << monitor.out;
    }
  EXPECT_EQ(judged, 2) << "the statement before the swap and the restated one" << monitor.out;
}

// The judgement itself, on a hand-written trace: a selection must start the alternative of the
// first requirement, in priority order, whose guard held in the values it read; one that goes
// on after an earlier branch ("after") is judged from that branch on; a trace that records no
// selection (as every trace before) leaves selection requirements not monitored.
TEST(MonitorCli, SelectionsAreJudgedInPriorityOrder) {
  const std::string requirements =
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n"
      "Hold: Mission shall always satisfy navigation.selected != hold_position\n";
  const std::string header =
      "{\"selection\": {\"navigation\": {\"alternatives\": [\"on_dust\", \"on_rocks\", "
      "\"hold_position\"], \"requirements\": [\"Req1\", \"Req2\", \"Safe\"]}}}\n";
  const auto tick = [](int t, const std::string& alternative, const std::string& read,
                       const std::string& after = "") {
    return "{\"tick\": " + std::to_string(t) + ", \"state\": {\"navigation.selected\": \"" +
           alternative + "\"}, \"select\": {\"navigation\": [{\"alternative\": \"" + alternative +
           "\", \"read\": {" + read + "}" +
           (after.empty() ? "" : ", \"after\": \"" + after + "\"") + "}]}}\n";
  };
  const std::string dust = "\"OnDust\": true, \"OnRocks\": true";
  TempMission files(
      Files{{"r.fret", requirements},
            {"good.jsonl", header + tick(1, "on_dust", dust) + tick(2, "on_rocks", dust, "Req1")},
            {"bad.jsonl", header + tick(1, "on_dust", dust) + tick(2, "on_rocks", dust)},
            {"old.jsonl", "{\"tick\": 1, \"state\": {\"navigation.selected\": \"on_dust\"}}\n"}});
  const CliRun good = uabt_in(files.dir(), "monitor r.fret good.jsonl");
  EXPECT_EQ(good.exit_code, 0) << good.out;
  EXPECT_EQ(good.out,
            "r.fret:1:7: Req1 (selection): held\n"
            "r.fret:2:7: Req2 (selection): held\n"
            "r.fret:3:7: Safe (selection): held\n"
            "r.fret:4:7: Hold: held\n"
            "verdict: pass (2 ticks; 4 held, 0 violated, 0 not monitored)\n");
  const CliRun bad = uabt_in(files.dir(), "monitor r.fret bad.jsonl");
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  EXPECT_NE(bad.out.find("r.fret:1:7: Req1 (selection): violated from tick 2 (OnDust=true, "
                         "navigation.selected=on_rocks)\n"),
            std::string::npos)
      << bad.out;
  const CliRun old = uabt_in(files.dir(), "monitor r.fret old.jsonl");
  EXPECT_EQ(old.exit_code, 1) << old.out;
  EXPECT_NE(old.out.find("r.fret:1:7: Req1 (selection): not-monitored: the trace records no "
                         "selection of 'navigation'"),
            std::string::npos)
      << old.out;
  EXPECT_NE(old.out.find("r.fret:4:7: Hold: held"), std::string::npos) << old.out;
}

}  // namespace
}  // namespace uabt::testing
