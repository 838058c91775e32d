// What `uabt prove` prints and writes is usable as it stands: its counterexample replays with the
// command it advises, its timeline names every action at every tick the action runs, and its
// messages name the files the user wrote, as `uabt verify` names them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

bool has(const CliRun& r, const std::string& text) {
  return r.out.find(text) != std::string::npos;
}

// sample_drilling with overlapping guards (a `guard-overlap` error of verify) and a cool bit at
// first: rotary drills the bit hot in tick 1 and again in tick 2, which violates CoolBit.
std::map<std::string, std::string> overlapping_drilling() {
  auto files = mission_files("sample_drilling");
  files["requirements.fret"] =
      "Hard: In drilling if HardRock Mission shall satisfy selected_alt = percussive\n"
      "Soft: In drilling if !HardRock | !IsBitCool Mission shall satisfy selected_alt = rotary\n"
      "CoolBit: Mission shall always satisfy Drill.running -> IsBitCool\n";
  auto& world = files["world.json"];
  world.replace(world.find("\"!IsBitCool\""), 12, "\"IsBitCool\"");
  return files;
}

TEST(ProveReplay, CounterexampleReplaysOnAMissionWithVerifyFindings) {
  TempMission m(overlapping_drilling());
  const std::string here = m.dir().parent_path().string();
  const CliRun proved = run_uabt_in(here, "prove m --counterexamples cex");
  EXPECT_EQ(proved.exit_code, 1) << proved.out;
  EXPECT_TRUE(has(proved,
                  "m/requirements.fret:3:10: error: guarantee 'CoolBit' is violated at "
                  "tick 2"))
      << proved.out;
  EXPECT_TRUE(has(proved, "(replay it with `uabt run m --scenario cex/CoolBit.json`)"))
      << proved.out;

  // The advice works: the run replays the violation at the same tick, exit 1 for it, and says
  // on one line that the mission it runs is not verified.
  const CliRun replay = run_uabt_in(here, "run m --scenario cex/CoolBit.json");
  EXPECT_EQ(replay.exit_code, 1) << replay.out;
  EXPECT_TRUE(has(replay,
                  "uabt: warning: the mission does not pass the gate's checks (1 error: "
                  "guard-overlap); it runs unverified, only to replay the counterexample of "
                  "'CoolBit' in cex/CoolBit.json\n"))
      << replay.out;
  EXPECT_TRUE(has(replay,
                  "tick 2: guarantee CoolBit violated (Drill.running=true, "
                  "IsBitCool=false)"))
      << replay.out;
  EXPECT_TRUE(has(replay, "property CoolBit: violated from tick 2")) << replay.out;
  EXPECT_FALSE(has(replay, "only a verified version runs")) << replay.out;

  // Any other scenario on that mission is refused as before.
  auto scenario =
      nlohmann::ordered_json::parse(read_all(m.dir().parent_path() / "cex/CoolBit.json"));
  scenario.erase("counterexample_of");
  m.write("plain.json", scenario.dump(2));
  const CliRun plain = run_uabt_in(here, "run m --scenario m/plain.json");
  EXPECT_EQ(plain.exit_code, 1) << plain.out;
  EXPECT_TRUE(has(plain,
                  "uabt: the mission does not pass the gate's checks; only a verified "
                  "version runs:\nm/requirements.fret:2:7: error: Hard (percussive) and "
                  "Soft (rotary) can both hold"))
      << plain.out;
  EXPECT_FALSE(has(plain, "guarantee CoolBit violated")) << plain.out;

  // The marker names a guarantee of the mission, or the scenario is refused where it says so.
  m.write("other.json", "{\"counterexample_of\": \"Hard\", \"max_ticks\": 2}\n");
  const CliRun other = run_uabt_in(here, "run m --scenario m/other.json");
  EXPECT_EQ(other.exit_code, 1) << other.out;
  EXPECT_TRUE(has(other,
                  "m/other.json:1:23: error: /counterexample_of: 'Hard' is not a "
                  "guarantee of the mission (its guarantees: CoolBit)"))
      << other.out;
}

TEST(ProveReplay, TimelineShowsARunningActionAtEveryTick) {
  TempMission m({{"mission.xml", mission_with("    <Sequence>\n      <Drive/>\n      <Park/>\n"
                                              "    </Sequence>")},
                 {"requirements.fret",
                  "Arrive: upon Drive.running Mission shall within 2 ticks satisfy "
                  "!Drive.running\n"}});
  const std::string here = m.dir().parent_path().string();
  const CliRun text = run_uabt_in(here, "prove m");
  EXPECT_EQ(text.exit_code, 1) << text.out;
  EXPECT_TRUE(has(text, "m/requirements.fret:1:9: error: guarantee 'Arrive' is violated at tick 3"))
      << text.out;
  EXPECT_TRUE(has(text, "note: 1     RUNNING  true           Drive started\n")) << text.out;
  EXPECT_TRUE(has(text, "note: 2     RUNNING  true           Drive running\n")) << text.out;
  EXPECT_TRUE(has(text, "note: 3     RUNNING  true           Drive running\n")) << text.out;
  EXPECT_TRUE(has(text,
                  "m/requirements.fret:1:9: note: action 'Drive' has no world.json entry, "
                  "so it may run any number of ticks\n"))
      << text.out;

  const CliRun html = run_uabt_in(here, "prove m --format html");
  EXPECT_TRUE(has(html,
                  "<tr class=\"action\"><th><code>Drive</code></th><td class=\"run\">started"
                  "</td><td class=\"run\">running</td><td class=\"run viol\">running</td>"
                  "</tr>"))
      << html.out;
  EXPECT_TRUE(has(html,
                  "action &#39;Drive&#39; has no world.json entry, so it may run any "
                  "number of ticks"))
      << html.out;

  const auto json = nlohmann::json::parse(run_uabt_in(here, "prove m --format json").out);
  const auto& cex = json["properties"][0]["counterexample"];
  EXPECT_EQ(cex["trace"][2]["actions"], nlohmann::json::array({"Drive running"}));
  EXPECT_EQ(cex["notes"][0],
            "action 'Drive' has no world.json entry, so it may run any number "
            "of ticks");
}

// An alternative whose script reads a key nothing wrote: the run stops there, in the
// alternative's file, not in a compiled.xml prove never writes.
std::map<std::string, std::string> failing_script() {
  return {{"mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"nav\"/>\n"
                                       "      <Drive/>\n    </Sequence>")},
          {"alternatives/nav/slow.xml",
           alternative_tree("slow",
                            "<Sequence>\n      <Script code=\"speed := limit + 1\"/>\n"
                            "    </Sequence>")},
          {"alternatives/nav/fast.xml", alternative_tree("fast", "<Drive/>")},
          {"domain.fret", "boolean Dusty\n"},
          {"requirements.fret",
           "Slow: In nav if Dusty Mission shall satisfy selected_alt = slow\n"
           "Fast: In nav Mission shall satisfy selected_alt = fast\n"
           "Never: Mission shall always satisfy !Drive.failure\n"}};
}

TEST(ProveReplay, DiagnosticsNameTheMissionFolderAndTheSourceOfANode) {
  TempMission m(failing_script());
  const std::string here = m.dir().parent_path().string();
  const CliRun verify = run_uabt_in(here, "verify m");
  EXPECT_TRUE(has(verify, "m/alternatives/nav/slow.xml:4:7: error: blackboard entry 'limit'"))
      << verify.out;
  const CliRun prove = run_uabt_in(here, "prove m");
  EXPECT_TRUE(has(prove,
                  "note: a reachable tick stops with an error: tick 1 of a run: "
                  "m/alternatives/nav/slow.xml:4:7: Script: undefined blackboard key "
                  "'limit'"))
      << prove.out;
  EXPECT_FALSE(has(prove, "compiled.xml")) << prove.out;

  // A mission the explicit engine cannot cut: the requirement is named from here.
  TempMission windy({{"mission.xml", mission_with("    <Drive/>")},
                     {"domain.fret", "real wind\n"},
                     {"requirements.fret",
                      "Calm: Mission shall always satisfy Drive.running -> wind * wind < 10\n"}});
  const CliRun refused =
      run_uabt_in(windy.dir().parent_path().string(), "prove m --engine explicit");
  EXPECT_EQ(refused.exit_code, 1) << refused.out;
  EXPECT_TRUE(has(refused,
                  "uabt: prove: the explicit-state engine cannot cut real 'wind' into "
                  "cells: the atom `wind * wind < 10` (m/requirements.fret:1:7)"))
      << refused.out;
}

}  // namespace
}  // namespace uabt::testing
