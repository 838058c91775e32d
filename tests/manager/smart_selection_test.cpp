// Smart re-selection (--smart-selection) must select the same alternatives at the same ticks
// and end with the same verdict as BT.CPP's tick; only condition ticks may drop.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "manager/manager.hpp"
#include "selection_missions.hpp"
#include "test_support.hpp"

namespace uabt::manager {
namespace {

using namespace uabt::runtime;  // the scenarios and traces the manager runs on

using compile::SelectionStyle;

struct Outcome {
  std::vector<std::string> events;  // select/uplink/status/error/done, without timings
  std::string verdict;
  std::uint64_t conditions = 0;
};

Outcome run(const std::filesystem::path& dir, Scenario scenario, SelectionStyle style, bool smart) {
  ManagerOptions options;
  options.gate.compile.selection = style;
  options.gate.compile.selection_forced = true;
  options.smart_selection = smart;
  BehaviorTreeManager manager(dir, std::move(scenario), options);
  ManagerRun r = manager.run();
  Outcome out;
  for (const TraceEvent& e : r.trace)
    out.events.push_back(std::to_string(e.tick) + " " + e.event + " " + e.adaptable + " " +
                         e.requirement + " " + e.alternative + " " + e.uplink + " " + e.verdict +
                         " " + e.status + " " + e.message);
  out.verdict = r.verdict;
  out.conditions = r.condition_ticks;
  return out;
}

// Runs both ways; returns (plain, smart) condition ticks.
std::pair<std::uint64_t, std::uint64_t> compare(const std::filesystem::path& dir,
                                                const Scenario& scenario, SelectionStyle style,
                                                const std::string& label) {
  const Outcome plain = run(dir, scenario, style, false);
  const Outcome smart = run(dir, scenario, style, true);
  EXPECT_EQ(plain.events, smart.events) << label;
  EXPECT_EQ(plain.verdict, smart.verdict) << label;
  EXPECT_LE(smart.conditions, plain.conditions) << label;
  return {plain.conditions, smart.conditions};
}

// Events by tick, as load_scenario leaves them.
void order_events(Scenario& s) {
  std::stable_sort(s.events.begin(), s.events.end(),
                   [](const ScenarioEvent& a, const ScenarioEvent& b) { return a.at < b.at; });
  for (int i = 0; i < static_cast<int>(s.events.size()); ++i) s.events[i].index = i;
}

std::filesystem::path curiosity() {
  return uabt::testing::mission_dir("msl_curiosity");
}

TEST(SmartSelection, ShippedScenariosSelectTheSameWithFewerConditionTicks) {
  std::uint64_t plain = 0, smart = 0;
  for (const auto& entry : std::filesystem::directory_iterator(curiosity() / "scenarios")) {
    const Scenario scenario = load_scenario(entry.path());
    for (SelectionStyle style : {SelectionStyle::sequence, SelectionStyle::reactive}) {
      const auto [p, s] = compare(curiosity(), scenario, style, entry.path().filename().string());
      if (style == SelectionStyle::sequence) {
        EXPECT_EQ(p, s) << "nothing to skip without reactive";
      } else {
        plain += p;
        smart += s;
      }
    }
  }
  EXPECT_LT(smart, plain);
}

// Terrain changes at random ticks, actions of random length, with and without the uplink.
TEST(SmartSelection, RandomTerrainScenariosSelectTheSame) {
  const Scenario base = load_scenario(curiosity() / "scenarios" / "mud_uplink.json");
  std::mt19937 rng(18);
  std::uint64_t plain = 0, smart = 0;
  for (int round = 0; round < 30; ++round) {
    Scenario s = base;
    s.events.clear();
    const bool uplink = rng() % 2 == 0;  // OnMud is a name only the uplink brings
    auto terrain = [&](StateAssignment& set) {
      const int t = static_cast<int>(rng() % (uplink ? 4 : 3));
      set.emplace_back("OnDust", ScriptValue::of_bool(t == 0));
      set.emplace_back("OnRocks", ScriptValue::of_bool(t == 1));
      if (uplink) set.emplace_back("OnMud", ScriptValue::of_bool(t == 2));
    };
    s.initial.clear();
    terrain(s.initial);
    s.initial.emplace_back("IsInLocation", ScriptValue::of_bool(false));
    s.initial.emplace_back("IsTowardObject", ScriptValue::of_bool(rng() % 2 == 0));
    for (auto& [name, action] : s.actions)
      if (name != "WaitForGroundCommand") action.ticks = 1 + static_cast<std::int64_t>(rng() % 30);
    const int events = static_cast<int>(rng() % 6);
    for (int i = 0; i < events; ++i) {
      ScenarioEvent e;
      e.at = 1 + static_cast<std::int64_t>(rng() % 120);
      terrain(e.set);
      s.events.push_back(std::move(e));
    }
    if (uplink) {
      ScenarioEvent e;
      e.at = 1 + static_cast<std::int64_t>(rng() % 120);
      e.uplink = "uplinks/on_mud";
      s.events.push_back(std::move(e));
    }
    order_events(s);
    const auto [p, q] =
        compare(curiosity(), s, SelectionStyle::reactive, "round " + std::to_string(round));
    plain += p;
    smart += q;
  }
  EXPECT_LT(smart, plain);
}

// ScriptCondition guards (blackboard keys): eight battery bands, the reading changing at
// random ticks while a band's action runs.
TEST(SmartSelection, RandomBatteryScenariosSelectTheSame) {
  const uabt::testing::TempMission mission(uabt::testing::battery_ladder_files(8));
  std::mt19937 rng(42);
  std::uint64_t plain = 0, smart = 0;
  for (int round = 0; round < 20; ++round) {
    Scenario s;
    s.max_ticks = 200;
    s.initial.emplace_back("battery", ScriptValue::of_int(static_cast<std::int64_t>(rng() % 80)));
    s.actions["Stop"].ticks = 1 + static_cast<std::int64_t>(rng() % 40);
    for (int i = 0; i < 4; ++i) {
      ScenarioEvent e;
      e.at = 1 + static_cast<std::int64_t>(rng() % 40);
      e.set.emplace_back("battery", ScriptValue::of_int(static_cast<std::int64_t>(rng() % 80)));
      s.events.push_back(std::move(e));
    }
    order_events(s);
    const auto [p, q] =
        compare(mission.dir(), s, SelectionStyle::reactive, "round " + std::to_string(round));
    plain += p;
    smart += q;
  }
  EXPECT_LT(smart, plain);
}

}  // namespace
}  // namespace uabt::manager
