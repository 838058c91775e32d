// Numbers as people write them, in every output: integers as integers, reals in the fewest
// digits that read back the same, negative and large values, JSON numbers as JSON numbers.
// One mission, every command that prints values, compared with tests/cli/golden/numbers.txt.
// To accept a deliberate change: UABT_UPDATE_GOLDEN=1 build/tests/test_cli
// --gtest_filter='Numbers.*'.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

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
