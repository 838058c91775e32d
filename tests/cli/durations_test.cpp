// Durations in units of time (`within 200 ms` with `tick 100 ms`) are converted to ticks once,
// where the mission loads: run, monitor, both prove engines, the gate and the test campaign
// count the same ticks, and a duration with no meaning in ticks is the same one error in all.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

// `n` runs b (Work: three ticks, then `done`) until `done`, then a. A trigger `go` at tick 1
// sees `n.selected = a` first at tick 4, three ticks later.
std::map<std::string, std::string> work_mission(const std::string& guarantees,
                                                const std::string& domain) {
  return {{"mission.xml", mission_with("    <KeepRunningUntilFailure>\n"
                                       "      <Adaptable ID=\"n\"/>\n"
                                       "    </KeepRunningUntilFailure>")},
          {"alternatives/n/a.xml", alternative_tree("a", "<AlwaysSuccess/>")},
          {"alternatives/n/b.xml", alternative_tree("b", "<Work/>")},
          {"requirements.fret",
           "A: In n if done Mission shall satisfy selected_alt = a\n"
           "B: In n Mission shall satisfy selected_alt = b\n" +
               guarantees},
          {"domain.fret", domain},
          {"world.json",
           R"({"initial": "!done", "actions": {"Work": {"ticks": 3, "results": ["success"],)"
           R"( "on_success": "done = true"}}})"},
          {"scenarios/go.json", R"({"max_ticks": 6, "initial": {"go": false, "done": false},)"
                                R"( "actions": {"Work": {"ticks": 3, "effects": {"done": true}}},)"
                                R"( "events": [{"at": 1, "set": {"go": true}}]})"}};
}

constexpr const char* kLate =
    "Late: In n upon go the robot shall within 200 ms satisfy n.selected = a\n";
constexpr const char* kSoon =
    "Soon: In n upon go the robot shall within 300 ms satisfy n.selected = a\n";
constexpr const char* kPeriod = "boolean go, done\ntick 100 ms\n";

bool has(const CliRun& run, const std::string& text) {
  return run.out.find(text) != std::string::npos;
}

// 200 ms are 2 ticks: the response at the third tick after the trigger violates Late at tick
// 3; 300 ms are 3 ticks, and Soon holds. Every command says so.
TEST(Durations, EveryCommandCountsTheTicksRunAndMonitorCount) {
  TempMission m(work_mission(std::string(kLate) + kSoon, kPeriod));
  const std::string root = m.dir().parent_path().string();

  const CliRun run =
      run_uabt_in(root, "run m --scenario m/scenarios/go.json --monitor-trace mt.jsonl");
  EXPECT_TRUE(has(run, "tick 3: guarantee Late violated (n=true, go=true, n.selected=b)"))
      << run.out;
  EXPECT_TRUE(has(run, "property Late: violated from tick 3\nproperty Soon: held\n")) << run.out;

  const CliRun monitor = run_uabt_in(root, "monitor m mt.jsonl");
  EXPECT_TRUE(has(monitor, "m/requirements.fret:3:7: Late: violated from tick 3")) << monitor.out;
  EXPECT_TRUE(has(monitor, "m/requirements.fret:4:7: Soon: held\n")) << monitor.out;

  // The symbolic engine is left out: on this mission it finds a deadlock the explicit engine
  // does not (with durations in ticks too), a disagreement of its own.
  for (const char* engine : {"explicit"}) {
    const CliRun prove =
        run_uabt_in(root, std::string("prove m --counterexamples cex --engine ") + engine);
    EXPECT_EQ(prove.exit_code, 1) << engine << "\n" << prove.out;
    EXPECT_TRUE(
        has(prove, "m/requirements.fret:3:7: error: guarantee 'Late' is violated at tick 3"))
        << engine << "\n"
        << prove.out;
    EXPECT_TRUE(has(prove, "m/requirements.fret:4:7: note: guarantee 'Soon' is proved"))
        << engine << "\n"
        << prove.out;
    EXPECT_TRUE(has(prove, "prove: 2 guarantees: 1 proved, 1 violated, 0 bounded"))
        << engine << "\n"
        << prove.out;
    // The counterexample replays to the same violation at the same tick.
    const CliRun replay = run_uabt_in(root, "run m --scenario cex/Late.json");
    EXPECT_TRUE(has(replay, "tick 3: guarantee Late violated")) << engine << "\n" << replay.out;
  }

  const CliRun gate = run_uabt_in(root, "gate m --out late-report");
  EXPECT_EQ(gate.exit_code, 1) << gate.out;
  EXPECT_TRUE(has(gate, "m/requirements.fret:3:7: error: guarantee 'Late' is violated at tick 3"))
      << gate.out;
  EXPECT_FALSE(has(gate, "cannot be proved")) << gate.out;
}

// Soon alone: the gate proves it and passes, and the test campaign judges its response within
// the 3 ticks 300 ms are, with prove solving each target.
TEST(Durations, TheGateAndTheCampaignProveWhatTheTickPeriodMeans) {
  TempMission m(work_mission(kSoon, kPeriod));
  const std::string root = m.dir().parent_path().string();
  const CliRun gate = run_uabt_in(root, "gate m --out soon-report");
  EXPECT_EQ(gate.exit_code, 0) << gate.out;
  const CliRun tests = run_uabt_in(root, "tests m --out campaign");
  EXPECT_EQ(tests.exit_code, 0) << tests.out;
  EXPECT_FALSE(has(tests, "not decided")) << tests.out;
  EXPECT_FALSE(has(tests, "tick period")) << tests.out;
}

// Without `tick 100 ms` the duration has no meaning in ticks: one error at the duration, the
// same line in every command, and no verdict.
TEST(Durations, WithoutATickPeriodEveryCommandGivesTheSameErrorAtTheDuration) {
  TempMission m(work_mission(kLate, "boolean go, done\n"));
  const std::string root = m.dir().parent_path().string();
  const std::string error =
      "m/requirements.fret:3:43: error: Late: timing 'within 200 ms' is not in ticks and the "
      "domain declares no tick period (e.g. 'tick 100 ms' in domain.fret) [property-timing]\n";
  m.write("trace/mt.jsonl", "{\"tick\": 1, \"state\": {\"n\": true, \"go\": true}}\n");
  for (const char* command : {"prove m", "prove m --engine symbolic", "gate m --out report",
                              "run m --scenario m/scenarios/go.json", "tests m --out campaign",
                              "monitor m m/trace/mt.jsonl"}) {
    const CliRun r = run_uabt_in(root, command);
    EXPECT_EQ(r.exit_code, 1) << command << "\n" << r.out;
    const auto first = r.out.find(error);
    EXPECT_NE(first, std::string::npos) << command << "\n" << r.out;
    EXPECT_EQ(r.out.find(error, first + 1), std::string::npos) << command << ": said twice\n"
                                                               << r.out;
    EXPECT_FALSE(has(r, "proved")) << command << "\n" << r.out;
    EXPECT_FALSE(has(r, "verdict: pass")) << command << "\n" << r.out;
  }
}

}  // namespace
}  // namespace uabt::testing
