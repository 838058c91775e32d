// What a tick shows (ARCHITECTURE §10, §14): `uabt run`'s monitor, `uabt monitor` on the trace it
// records and both `uabt prove` engines read the same observation of every tick, so they give
// the same verdict.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

CliRun uabt_in(const std::filesystem::path& dir, const std::string& args) {
  return run_shell("cd '" + dir.string() + "' && '" + std::string(UABT_BINARY) + "' " + args +
                   " 2>&1");
}

// The verdict `uabt prove --format json` gives guarantee `id`.
std::string proof_verdict(const std::string& json, const std::string& id) {
  const auto doc = nlohmann::json::parse(json, nullptr, false);
  if (doc.is_discarded() || !doc.contains("properties")) return "no answer: " + json;
  for (const auto& p : doc["properties"])
    if (p.value("id", "") == id) return p.value("verdict", "");
  return "not proved: " + json;
}

// The state a `--monitor-trace` line gives at `tick`.
nlohmann::json traced_state(const std::filesystem::path& trace, std::uint64_t tick) {
  std::ifstream in(trace);
  for (std::string line; std::getline(in, line);) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_discarded() && j.contains("tick") && j["tick"] == tick) return j["state"];
  }
  return nullptr;
}

// A descent: the adaptable `flight` (the mode `flight`) cruises for 4 ticks; the landing
// starts in tick 4 and is all tick 5 ticks, SpinDown included. The mode is true only in the
// ticks that tick `flight`, so the guarantee holds, although the Sequence resets `flight`
// when the root completes in tick 5.
std::map<std::string, std::string> descent() {
  return {{"mission.xml", mission_with("    <Sequence name=\"descent\">\n"
                                       "      <Adaptable ID=\"flight\"/>\n"
                                       "      <Sequence name=\"landing\">\n"
                                       "        <Touchdown/>\n"
                                       "        <SpinDown/>\n"
                                       "      </Sequence>\n"
                                       "    </Sequence>")},
          {"alternatives/flight/cruise.xml", alternative_tree("cruise", "<Cruise/>")},
          {"requirements.fret",
           "Cruising: In flight Mission shall satisfy selected_alt = cruise\n"
           "NoSpinInFlight: In flight the robot shall always satisfy !SpinDown.success\n"},
          {"world.json",
           "{\"actions\": {\"Cruise\": {\"ticks\": 4, \"results\": [\"success\"]},\n"
           "             \"Touchdown\": {\"ticks\": 2, \"results\": [\"success\"]},\n"
           "             \"SpinDown\": {\"ticks\": 1, \"results\": [\"success\"]}}}\n"},
          {"scenarios/nominal.json",
           "{\"max_ticks\": 20, \"actions\": {\"Cruise\": {\"ticks\": 4}, "
           "\"Touchdown\": {\"ticks\": 2}, \"SpinDown\": {\"ticks\": 1}}}\n"}};
}

TEST(TickObservation, TheModeIsFalseOnceItsNodeIsNoLongerTicked) {
  TempMission m(descent(), "descent");
  const std::filesystem::path dir = m.dir().parent_path();
  const CliRun run =
      uabt_in(dir, "run descent --scenario descent/scenarios/nominal.json --monitor-trace t.jsonl");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("property NoSpinInFlight: held\n"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("violation"), std::string::npos) << run.out;
  // What the ticks showed: `flight` in ticks 1-4, SpinDown's success in tick 5 only.
  const nlohmann::json fourth = traced_state(dir / "t.jsonl", 4);
  const nlohmann::json fifth = traced_state(dir / "t.jsonl", 5);
  ASSERT_TRUE(fourth.is_object()) << run.out;
  ASSERT_TRUE(fifth.is_object()) << run.out;
  EXPECT_EQ(fourth["flight"], true);
  EXPECT_EQ(fourth["SpinDown.success"], false);
  EXPECT_EQ(fifth["flight"], false);
  EXPECT_EQ(fifth["SpinDown.success"], true);

  const CliRun monitor = uabt_in(dir, "monitor descent/requirements.fret t.jsonl");
  EXPECT_EQ(monitor.exit_code, 0) << monitor.out;
  EXPECT_NE(monitor.out.find("NoSpinInFlight: held\n"), std::string::npos) << monitor.out;

  const CliRun explicit_engine = uabt_in(dir, "prove descent --format json");
  EXPECT_EQ(explicit_engine.exit_code, 0) << explicit_engine.out;
  EXPECT_EQ(proof_verdict(explicit_engine.out, "NoSpinInFlight"), "proved");
  const CliRun symbolic = uabt_in(dir, "prove descent --engine symbolic --format json");
  EXPECT_EQ(symbolic.exit_code, 0) << symbolic.out;
  EXPECT_EQ(proof_verdict(symbolic.out, "NoSpinInFlight"), "proved");
}

}  // namespace
}  // namespace uabt::testing
