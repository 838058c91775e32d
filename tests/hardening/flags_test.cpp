// Every numeric option has a documented range (README, "Numeric options"); a value outside it,
// a sign or a number too long for any type is a command-line error in uabt's words, exit 2,
// before any work starts.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

struct Refusal {
  std::vector<std::string> args;  // after the mission directory
  std::string message;            // the whole output
};

// The good mission with a scenario: every other argument of a case is valid.
std::map<std::string, std::string> mission_and_scenario() {
  auto files = good_mission_files();
  files["s.json"] = "{}\n";
  return files;
}

TEST(Flags, NumbersOutsideTheirRangeAreRefusedInUabtsWords) {
  const TempMission m(mission_and_scenario());
  const std::string scenario = (m.dir() / "s.json").string();
  const std::string tree = (m.dir() / "mission.xml").string();
  const std::string huge = "99999999999999999999";
  const std::string three_hundred(300, '9');
  const std::vector<std::pair<std::string, Refusal>> cases = {
      {"prove", {{"--depth", "-1"}, "--depth must be a whole number from 1 to 10000, not '-1'"}},
      {"prove", {{"--depth", "0"}, "--depth must be a whole number from 1 to 10000, not '0'"}},
      {"prove",
       {{"--depth", huge}, "--depth must be a whole number from 1 to 10000, not '" + huge + "'"}},
      {"run",
       {{"--scenario", scenario, "--max-ticks", "0"},
        "--max-ticks must be a whole number from 1 to 1000000, not '0'"}},
      {"run",
       {{"--scenario", scenario, "--max-ticks", huge},
        "--max-ticks must be a whole number from 1 to 1000000, not '" + huge + "'"}},
      {"run",
       {{"--scenario", scenario, "--max-ticks", three_hundred},
        "--max-ticks must be a whole number from 1 to 1000000, not '99999999999999999999…'"}},
      {"tests",
       {{"--out", "o", "--max-ticks", "1.5"},
        "--max-ticks must be a whole number from 1 to 1000000, not '1.5'"}},
      {"verify",
       {{"--timeout-ms", "0"}, "--timeout-ms must be a whole number from 1 to 3600000, not '0'"}},
      {"conform",
       {{tree, "--timeout-ms", "3600001"},
        "--timeout-ms must be a whole number from 1 to 3600000, not '3600001'"}},
      {"diff",
       {{"--uplink", m.dir().string(), "--timeout-ms", "-5"},
        "--timeout-ms must be a whole number from 1 to 3600000, not '-5'"}},
      {"gate",
       {{"--timeout-ms", "ten"},
        "--timeout-ms must be a whole number from 1 to 3600000, not 'ten'"}},
      {"compile", {{"--bt-format", "5"}, "--bt-format must be 3 or 4, not '5'"}},
  };
  for (const auto& [command, refusal] : cases) {
    std::vector<std::string> args{command, m.dir().string()};
    args.insert(args.end(), refusal.args.begin(), refusal.args.end());
    SCOPED_TRACE(command + " " + refusal.args.back());
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.output, "uabt: " + refusal.message + "\n");
  }
}

TEST(Flags, AnUplinkTickOutsideItsRangeIsRefused) {
  const TempMission m(mission_and_scenario());
  const CliRun run = run_cli({"run", m.dir().string(), "--scenario", (m.dir() / "s.json").string(),
                              "--uplink", "99999999999999999999:" + m.dir().string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.output, "uabt: --uplink 99999999999999999999:" + m.dir().string() +
                            ": its TICK must be a whole number from 0 to 1000000, not "
                            "'99999999999999999999' (TICK:DIR: a tick number, then the package "
                            "directory)\n");
}

TEST(Flags, TheEndsOfEachRangeAreAccepted) {
  const TempMission m(good_mission_files());
  EXPECT_EQ(run_cli({"verify", m.dir().string(), "--timeout-ms", "3600000"}).exit_code, 0);
  EXPECT_EQ(run_cli({"verify", m.dir().string(), "--timeout-ms", "1"}).exit_code != 2, true);
  EXPECT_EQ(run_cli({"compile", m.dir().string(), "--bt-format", "3"}).exit_code, 0);
  EXPECT_NE(run_cli({"prove", m.dir().string(), "--depth", "1"}).exit_code, 2);
}

}  // namespace
}  // namespace uabt::testing
