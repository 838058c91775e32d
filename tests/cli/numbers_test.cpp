// Numbers as people write them, in every output: integers as integers, reals in the fewest
// digits that read back the same, negative and large values, JSON numbers as JSON numbers.
// One mission, every command that prints values, compared with tests/cli/golden/numbers.txt.
// To accept a deliberate change: UABT_UPDATE_GOLDEN=1 build/tests/test_cli
// --gtest_filter='Numbers.*'.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"

namespace {

namespace fs = std::filesystem;
using uabt::testing::TempMission;

const std::map<std::string, std::string> kMission = {
    {"mission.xml",
     "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
     "  <BehaviorTree ID=\"MainTree\">\n"
     "    <Repeat num_cycles=\"3\"><Adaptable ID=\"move\"/></Repeat>\n"
     "  </BehaviorTree>\n</root>\n"},
    {"alternatives/move/fast.xml",
     "<root BTCPP_format=\"4\"><BehaviorTree ID=\"fast\"><Drive/></BehaviorTree></root>\n"},
    {"alternatives/move/slow.xml",
     "<root BTCPP_format=\"4\"><BehaviorTree ID=\"slow\"><Creep/></BehaviorTree></root>\n"},
    {"domain.fret",
     "integer battery in [-100, 100]\n"
     "real wind in [-40.5, 40.5]\n"
     "integer dist in [10000000000, 20000000000]\n"
     "real big in [1e21, 1e22]\n"
     "real ratio in [0.1, 0.9]\n"},
    {"requirements.fret",
     "Calm: In move if wind < 9.5 Mission shall satisfy selected_alt = fast\n"
     "Other: In move Mission shall satisfy selected_alt = slow\n"
     "NoDrive: Mission shall always satisfy Drive.running -> (battery > 50 & wind < -3 & "
     "dist < 10000000000 & big < 1e21 & ratio > 0.5)\n"},
    {"scenarios/numbers.json",
     "{\"max_ticks\": 2, \"initial\": {\"battery\": 50, \"wind\": -3.5, \"dist\": 10000000000, "
     "\"big\": 1e21, \"ratio\": 0.1}, \"actions\": {\"Drive\": {\"ticks\": 3}}}\n"}};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The lines of `text` from the first that contains `from` through the next that contains `to`.
std::string excerpt(const std::string& text, const std::string& from, const std::string& to) {
  const auto begin = text.rfind('\n', text.find(from)) + 1;
  const auto end = text.find('\n', text.find(to, begin));
  if (text.find(from) == std::string::npos || end == std::string::npos) return "(missing)\n";
  return text.substr(begin, end + 1 - begin);
}

// Every output that prints the mission's values, as one text. Runs in the mission's parent.
std::string every_output(const TempMission& m) {
  const std::string dir = m.dir().parent_path().string();
  const auto uabt = [&](const std::string& args) {
    return "$ uabt " + args + "\n" + uabt::testing::run_uabt_in(dir, args).out;
  };
  std::string out;
  out += uabt("prove numbers");
  out += uabt("prove numbers --format json");
  uabt::testing::run_uabt_in(dir, "prove numbers --format html -o prove.html");
  out +=
      "$ uabt prove numbers --format html: the timeline\n" +
      excerpt(read(m.dir().parent_path() / "prove.html"), "<table class=\"timeline\">", "</table>");
  uabt::testing::run_uabt_in(dir, "gate numbers --out report");
  out += "$ uabt gate numbers: summary.md, the counterexample\n" +
         excerpt(read(m.dir().parent_path() / "report/summary.md"), "| tick |", "| root |");
  const std::string summary = read(m.dir().parent_path() / "report/summary.md");
  out += excerpt(summary, "| `battery` |", "| `ratio` |");
  out += uabt(
      "run numbers --scenario numbers/scenarios/numbers.json --trace run.jsonl "
      "--monitor-trace monitor.jsonl");
  out += "$ cat run.jsonl\n" + read(m.dir().parent_path() / "run.jsonl");
  out += "$ cat monitor.jsonl\n" + read(m.dir().parent_path() / "monitor.jsonl");
  out += uabt("monitor numbers/requirements.fret monitor.jsonl --domain numbers/domain.fret");
  out += uabt(
      "monitor numbers/requirements.fret monitor.jsonl --domain numbers/domain.fret --format "
      "json");
  return out;
}

TEST(Numbers, EveryOutputWritesNumbersAsPeopleDo) {
  TempMission m(kMission, "numbers");
  const std::string out = every_output(m);
  const fs::path golden = fs::path(UABT_SOURCE_DIR) / "tests/cli/golden/numbers.txt";
  if (std::getenv("UABT_UPDATE_GOLDEN") != nullptr) std::ofstream(golden, std::ios::binary) << out;
  EXPECT_EQ(out, read(golden));
  // The same input gives the same bytes.
  TempMission again(kMission, "numbers");
  EXPECT_EQ(every_output(again), out);
}

// JSON numbers are JSON numbers: what a violated property read, in prove, run and monitor.
TEST(Numbers, JsonCarriesNumbersAsNumbers) {
  TempMission m(kMission, "numbers");
  const std::string dir = m.dir().parent_path().string();
  const auto prove =
      nlohmann::json::parse(uabt::testing::run_shell("cd '" + dir + "' && '" + UABT_BINARY +
                                                     "' prove numbers --format json 2>/dev/null")
                                .out);
  const auto& values = prove["properties"][0]["counterexample"]["trace"][0]["values"];
  EXPECT_TRUE(values["battery"].is_number_integer()) << values;
  EXPECT_TRUE(values["wind"].is_number_float()) << values;
  EXPECT_TRUE(values["Drive.running"].is_boolean()) << values;

  uabt::testing::run_uabt_in(
      dir, "run numbers --scenario numbers/scenarios/numbers.json --trace run.jsonl");
  std::istringstream lines(read(m.dir().parent_path() / "run.jsonl"));
  std::string line;
  bool seen = false;
  while (std::getline(lines, line)) {
    const auto event = nlohmann::json::parse(line);
    if (event["event"] != "violation") continue;
    seen = true;
    EXPECT_EQ(event["values"]["battery"], 50) << line;
    EXPECT_EQ(event["values"]["dist"], 10000000000LL) << line;
    EXPECT_EQ(event["values"]["wind"], -3.5) << line;
    EXPECT_EQ(event["values"]["ratio"], 0.1) << line;
    EXPECT_EQ(event["values"]["big"], 1e21) << line;
  }
  EXPECT_TRUE(seen);
}

// `uabt run --monitor-trace` writes the trace `uabt monitor` reads, and both give every
// mission property the same verdict, on a run that violates a guarantee and one that does not.
TEST(Numbers, RunThenMonitorAgree) {
  for (const char* wind : {"-3.5", "20"}) {  // fast: Drive runs and breaks NoDrive; slow: not
    auto files = kMission;
    std::string& scenario = files["scenarios/numbers.json"];
    const std::string written = "\"wind\": -3.5";
    scenario.replace(scenario.find(written), written.size(), std::string("\"wind\": ") + wind);
    files["requirements.fret"] +=
        "Eventually: Mission shall eventually satisfy Drive.success\n"
        "Soon: upon Drive.running Mission shall within 1 tick satisfy ratio > 0.5\n";
    TempMission m(files, "numbers");
    const std::string dir = m.dir().parent_path().string();
    const auto run = uabt::testing::run_shell(
        "cd '" + dir + "' && '" + UABT_BINARY +
        "' run numbers --scenario numbers/scenarios/numbers.json --monitor-trace t.jsonl "
        "2>/dev/null");
    const auto monitor = uabt::testing::run_shell(
        "cd '" + dir + "' && '" + UABT_BINARY +
        "' monitor numbers/requirements.fret t.jsonl --domain numbers/domain.fret --format json "
        "2>/dev/null");
    const auto report = nlohmann::json::parse(monitor.out);
    std::map<std::string, std::string> monitored;
    for (const auto& r : report["requirements"]) {
      std::string verdict = r["verdict"];
      if (!r["first_violation"].is_null())
        verdict += " from tick " + std::to_string(r["first_violation"].get<int>());
      monitored[r["id"]] = verdict;
    }
    for (const char* id : {"NoDrive", "Eventually", "Soon"}) {
      const std::string property = std::string("property ") + id + ": ";
      const auto at = run.out.find(property);
      ASSERT_NE(at, std::string::npos) << run.out;
      const std::string said =
          run.out.substr(at + property.size(), run.out.find('\n', at) - at - property.size());
      EXPECT_EQ(said, monitored[id]) << "wind " << wind << ", " << id << "\n" << run.out;
    }
    EXPECT_EQ(monitored["NoDrive"], std::string(wind) == "20" ? "held" : "violated from tick 1");
  }
}

}  // namespace

namespace {

// Durations in the abbreviations `tick 100 ms` uses: `within 300 ms` is `within 3 ticks` once
// the domain declares the period, and a property-timing error that says how without one.
TEST(Units, MillisecondsInARequirementCountTicksOfTheDeclaredPeriod) {
  const std::string trace =
      "{\"tick\": 1, \"state\": {\"go\": true, \"done\": false}}\n"
      "{\"tick\": 2, \"state\": {\"go\": false}}\n"
      "{\"tick\": 3, \"state\": {}}\n"
      "{\"tick\": 4, \"state\": {}}\n"
      "{\"tick\": 5, \"state\": {\"done\": true}}\n";
  const auto monitor = [&](const std::string& timing, const std::string& domain) {
    TempMission m({{"r.fret", "R: upon go Mission shall " + timing + " satisfy done\n"},
                   {"domain.fret", domain},
                   {"t.jsonl", trace}});
    return uabt::testing::run_uabt_in(m.dir().string(),
                                      "monitor r.fret t.jsonl --domain domain.fret");
  };
  const std::string period = "boolean go, done\ntick 100 ms\n";
  const auto ticks = monitor("within 3 ticks", period);
  EXPECT_EQ(ticks.out,
            "r.fret:1:4: R: violated from tick 4 (go=false, done=false)\nverdict: fail (5 ticks; 0 "
            "held, 1 "
            "violated, 0 not monitored)\n");
  for (const char* written : {"within 300 ms", "within 0.3 s", "within 300 milliseconds"}) {
    const auto run = monitor(written, period);
    EXPECT_EQ(run.out, ticks.out) << written;
    EXPECT_EQ(run.exit_code, ticks.exit_code) << written;
  }
  EXPECT_EQ(monitor("within 400 ms", period).exit_code, 0);
  const auto no_period = monitor("within 300 ms", "boolean go, done\n");
  EXPECT_NE(no_period.out.find("timing 'within 300 ms' is not in ticks and the domain declares "
                               "no tick period (e.g. 'tick 100 ms' in domain.fret)"),
            std::string::npos)
      << no_period.out;
  EXPECT_NE(no_period.exit_code, 0);
}

}  // namespace

namespace {

using uabt::testing::CliRun;

// A real variable whose values are whole (speed 12, doubled to 24) and that the tree changes by
// a fraction: `speed = speed - 0.5` only runs when the blackboard holds speed as a real, as
// BehaviorTree.CPP refuses a real assigned into an integer entry. An integer variable beside it.
const std::map<std::string, std::string> kWhole = {
    {"mission.xml",
     "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
     "  <BehaviorTree ID=\"MainTree\">\n"
     "    <Repeat num_cycles=\"3\"><Sequence><Adaptable ID=\"move\"/>"
     "<Script code=\"speed = speed - 0.5\"/></Sequence></Repeat>\n"
     "  </BehaviorTree>\n</root>\n"},
    {"alternatives/move/fast.xml",
     "<root BTCPP_format=\"4\"><BehaviorTree ID=\"fast\"><Drive/></BehaviorTree></root>\n"},
    {"alternatives/move/slow.xml",
     "<root BTCPP_format=\"4\"><BehaviorTree ID=\"slow\"><Creep/></BehaviorTree></root>\n"},
    {"domain.fret", "real speed in [0, 100]\ninteger battery in [0, 100]\n"},
    {"requirements.fret",
     "Calm: In move if speed < 30 & battery > 20 Mission shall satisfy selected_alt = fast\n"
     "Other: In move Mission shall satisfy selected_alt = slow\n"
     "Bounded: Mission shall always satisfy speed < 40\n"},
    {"world.json",
     "{\"initial\": \"speed = 12 & battery = 50\", \"actions\": {\"Drive\": {\"ticks\": 2, "
     "\"on_success\": \"speed = speed * 2\"}, \"Creep\": {\"ticks\": 1}}}\n"}};

// A whole number written with a fraction part (`12.0`): what a real is written as when its
// writer does not know that its reader types it by the declaration.
bool has_whole_real(const std::string& text) {
  for (std::size_t at = text.find(".0"); at != std::string::npos; at = text.find(".0", at + 1)) {
    std::size_t end = at + 2;
    while (end < text.size() && text[end] == '0') ++end;
    if (at > 0 && std::isdigit(static_cast<unsigned char>(text[at - 1])) &&
        (end == text.size() || !std::isdigit(static_cast<unsigned char>(text[end]))))
      return true;
  }
  return false;
}

// prove's counterexample writes the whole real speed as 12, 24 and 47; `uabt run` replays it to
// the same violation at the same tick (speed is a real on the blackboard, so the script's
// fraction fits it), its monitor trace writes 12 too, and `uabt monitor` reads that trace back to
// the run's verdicts.
TEST(Numbers, WholeRealsOfACounterexampleAreIntegersAndReplay) {
  TempMission m(kWhole, "whole");
  const std::string dir = m.dir().parent_path().string();
  const CliRun prove = uabt::testing::run_uabt_in(dir, "prove whole --counterexamples cex");
  EXPECT_NE(prove.out.find("guarantee 'Bounded' is violated at tick 3"), std::string::npos)
      << prove.out;
  const std::string scenario = read(m.dir().parent_path() / "cex/Bounded.json");
  EXPECT_NE(scenario.find("\"initial\": {\n    \"speed\": 12,\n    \"battery\": 50\n  }"),
            std::string::npos)
      << scenario;
  EXPECT_NE(scenario.find("\"effects\": {\n            \"speed\": 24\n"), std::string::npos)
      << scenario;
  EXPECT_NE(scenario.find("\"effects\": {\n            \"speed\": 47\n"), std::string::npos)
      << scenario;
  EXPECT_FALSE(has_whole_real(scenario)) << scenario;

  const CliRun run = uabt::testing::run_uabt_in(
      dir, "run whole --scenario cex/Bounded.json --monitor-trace monitor.jsonl");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_NE(run.out.find("tick 3: guarantee Bounded violated (speed=46)\ntick 3: mission success\n"
                         "selection Calm: held\nselection Other: held\n"
                         "property Bounded: violated from tick 3\n"),
            std::string::npos)
      << run.out;
  const std::string trace = read(m.dir().parent_path() / "monitor.jsonl");
  EXPECT_NE(trace.find("\n{\"tick\":1,\"state\":{\"speed\":12},\"select\":{\"move\":[{"
                       "\"alternative\":\"fast\",\"read\":{\"speed\":12,\"battery\":50}}]}}\n"),
            std::string::npos)
      << trace;
  EXPECT_NE(trace.find("{\"tick\":3,\"state\":{\"speed\":46}"), std::string::npos) << trace;
  EXPECT_FALSE(has_whole_real(trace)) << trace;
  const CliRun monitor = uabt::testing::run_uabt_in(dir, "monitor whole monitor.jsonl");
  EXPECT_EQ(monitor.out,
            "whole/requirements.fret:1:7: Calm (selection): held\n"
            "whole/requirements.fret:2:8: Other (selection): held\n"
            "whole/requirements.fret:3:10: Bounded: violated from tick 3 (speed=46)\n"
            "verdict: fail (3 ticks; 2 held, 1 violated, 0 not monitored)\n");
}

// Every scenario `uabt tests` writes gives speed and what Drive makes of it as whole numbers,
// and each replays with `uabt run` without an error.
TEST(Numbers, WholeRealsOfTheCampaignAreIntegersAndReplay) {
  TempMission m(kWhole, "whole");
  const std::string dir = m.dir().parent_path().string();
  const CliRun tests = uabt::testing::run_uabt_in(dir, "tests whole --out tests");
  EXPECT_EQ(tests.exit_code, 0) << tests.out;
  int scenarios = 0;
  for (const auto& e : fs::directory_iterator(m.dir().parent_path() / "tests")) {
    if (!e.path().filename().string().starts_with("move-")) continue;
    ++scenarios;
    const std::string name = e.path().filename().string();
    const std::string text = read(e.path());
    EXPECT_FALSE(has_whole_real(text)) << name << "\n" << text;
    const auto j = nlohmann::json::parse(text);
    EXPECT_TRUE(j["initial"]["speed"].is_number_integer()) << name << "\n" << text;
    EXPECT_TRUE(j["actions"]["Drive"]["effects"]["speed"].is_number_integer()) << name << "\n"
                                                                               << text;
    const CliRun run = uabt::testing::run_uabt_in(dir, "run whole --scenario tests/" + name);
    EXPECT_EQ(run.out.find("error"), std::string::npos) << name << "\n" << run.out;
    EXPECT_NE(run.out.find("mission success"), std::string::npos) << name << "\n" << run.out;
  }
  EXPECT_EQ(scenarios, 5) << tests.out;
}

// A number is what its variable's declaration makes it, however JSON writes it: 12 for the
// real speed is a real (the script's fraction fits it), 50.0 for the integer battery an integer;
// 12.5 for battery is refused where it is written, in a scenario and in a trace.
TEST(Numbers, ANumberIsWhatItsVariableIsDeclared) {
  auto files = kWhole;
  files["scenarios/typed.json"] =
      "{\"max_ticks\": 1, \"initial\": {\"speed\": 12, \"battery\": 50.0},\n"
      " \"actions\": {\"Drive\": {\"ticks\": 1}}}\n";
  files["scenarios/fraction.json"] =
      "{\"max_ticks\": 1, \"initial\": {\"speed\": 12,\n"
      "                             \"battery\": 12.5}}\n";
  files["typed.jsonl"] = "{\"tick\": 1, \"state\": {\"speed\": 12, \"battery\": 50.0}}\n";
  files["fraction.jsonl"] =
      "{\"tick\": 1, \"state\": {\"speed\": 12, \"battery\": 50}}\n"
      "{\"tick\": 2, \"state\": {\"battery\": 12.5}}\n";
  // 12 / 8 is 1 for integers, 1.5 for reals.
  files["eighth.fret"] = "Eighth: Mission shall always satisfy speed / 8 > 1.4 & battery = 50\n";
  TempMission m(files, "whole");
  const std::string dir = m.dir().parent_path().string();

  const CliRun typed =
      uabt::testing::run_uabt_in(dir, "run whole --scenario whole/scenarios/typed.json");
  EXPECT_EQ(typed.exit_code, 0) << typed.out;
  EXPECT_NE(typed.out.find("tick 1: mission success\n"), std::string::npos) << typed.out;
  const CliRun fraction =
      uabt::testing::run_uabt_in(dir, "run whole --scenario whole/scenarios/fraction.json");
  EXPECT_NE(fraction.exit_code, 0) << fraction.out;
  EXPECT_NE(fraction.out.find("whole/scenarios/fraction.json:2:41: error: battery = 12.5 is not "
                              "an integer (declared integer at "),
            std::string::npos)
      << fraction.out;

  const CliRun read_back = uabt::testing::run_uabt_in(
      dir, "monitor whole/eighth.fret whole/typed.jsonl --domain whole/domain.fret");
  EXPECT_EQ(read_back.out,
            "whole/eighth.fret:1:9: Eighth: held\n"
            "verdict: pass (1 ticks; 1 held, 0 violated, 0 not monitored)\n");
  const CliRun refused = uabt::testing::run_uabt_in(dir, "monitor whole whole/fraction.jsonl");
  EXPECT_EQ(refused.exit_code, 1) << refused.out;
  EXPECT_NE(refused.out.find("whole/fraction.jsonl:2:1: error: 'battery' at tick 2 does not fit "
                             "its type: the domain declares it integer [trace-invalid]"),
            std::string::npos)
      << refused.out;

  // `uabt coverage` reads the trace's battery as the integer 50: a state of the guard's space.
  const CliRun coverage = uabt::testing::run_uabt_in(dir, "coverage whole whole/typed.jsonl");
  EXPECT_NE(coverage.out.find("visited: speed in (0, 30), just below the boundary 30"),
            std::string::npos)
      << coverage.out;
}

// What `uabt gate` wrote into reports/ gives every whole number within 64 bits as a JSON
// integer: a witness's real wind of 40 is 40, not 40.0.
TEST(Numbers, ShippedReportsWriteWholeNumbersAsIntegers) {
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(UABT_SOURCE_DIR) / "reports")) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".json" && ext != ".sarif")) continue;
    ++files;
    std::vector<std::string> whole;
    std::function<void(const nlohmann::json&, const std::string&)> walk =
        [&](const nlohmann::json& j, const std::string& at) {
          if (j.is_number_float()) {
            const double x = j.get<double>();
            if (std::trunc(x) == x && std::fabs(x) < 0x1p63) whole.push_back(at + " = " + j.dump());
          } else if (j.is_object()) {
            for (const auto& [key, value] : j.items()) walk(value, at + "/" + key);
          } else if (j.is_array()) {
            for (std::size_t i = 0; i < j.size(); ++i) walk(j[i], at + "/" + std::to_string(i));
          }
        };
    walk(nlohmann::json::parse(read(e.path())), "");
    std::string list;
    for (const auto& w : whole) list += w + "\n";
    EXPECT_TRUE(whole.empty()) << e.path().string() << ":\n" << list;
  }
  EXPECT_GT(files, 20);
}

}  // namespace
