// Realizability (src/realize): the verdicts, minimal conflicts and defeating inputs of small sets
// whose answer is known, and a randomized cross-check against a game solver written here, with
// its own reading of the requirements, over a few hundred generated sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>
#include <set>

#include "base/diagnostics.hpp"
#include "cli/cli_support.hpp"
#include "realize/realize.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

using Conflicts = std::vector<std::vector<std::string>>;

const std::string kRover =
    mission_with("    <Sequence>\n      <Stow/>\n      <Drill/>\n    </Sequence>");

realize::Result realizability(const TempMission& t) {
  std::string error;
  auto mission = load::load_mission(t.dir(), {}, error);
  EXPECT_TRUE(mission) << error;
  if (!mission) return {};
  EXPECT_FALSE(has_errors(mission->findings)) << format_text(mission->findings);
  return realize::check_realizability(*mission, prove::mission_world(*mission));
}

// The example: consistent (a run without a sample request after an alarm satisfies all
// three), but the environment raises the alarm at tick 1 and asks for a sample at tick 2.
const char* const kDustAndSample =
    "G1: upon DustAlarm the rover shall at the next timepoint satisfy Stow.running\n"
    "G2: whenever SampleReq the rover shall immediately satisfy Drill.running\n"
    "G3: the rover shall always satisfy !(Drill.running & Stow.running)\n";

TEST(Realizability, AConsistentSetTheEnvironmentDefeatsIsUnrealizable) {
  const TempMission t({{"mission.xml", kRover},
                       {"domain.fret", "boolean DustAlarm, SampleReq\n"},
                       {"requirements.fret", kDustAndSample}});
  const realize::Result r = realizability(t);
  ASSERT_EQ(r.realizable, false);
  ASSERT_EQ(r.components.size(), 1u);
  const realize::Component& c = r.components.front();
  EXPECT_EQ(c.conflicts, (Conflicts{{"G1", "G2", "G3"}}));
  EXPECT_TRUE(c.conflicts_complete);
  // Tick 1: the alarm (Stow is due at tick 2); tick 2: a sample request (Drill is due now).
  ASSERT_EQ(c.defeating_inputs.size(), 2u);
  EXPECT_EQ(c.defeating_inputs[0].inputs,
            (State{{"DustAlarm", Value::of_bool(true)}, {"SampleReq", Value::of_bool(false)}}));
  EXPECT_EQ(c.defeating_inputs[1].inputs,
            (State{{"DustAlarm", Value::of_bool(false)}, {"SampleReq", Value::of_bool(true)}}));
  // Who decides what.
  std::map<std::string, realize::Role> roles;
  for (const auto& s : r.signals) roles[s.name] = s.role;
  // A status of the robot's node is made of the tree's choice (run it, let it end) and the
  // world's (how it ends), which `running` does not read.
  using realize::Role;
  EXPECT_EQ(roles, (std::map<std::string, Role>{{"DustAlarm", Role::input},
                                                {"Drill.running", Role::output},
                                                {"Drill.state", Role::output},
                                                {"SampleReq", Role::input},
                                                {"Stow.running", Role::output},
                                                {"Stow.state", Role::output}}));
}

TEST(Realizability, AnAssumptionAboutTheEnvironmentMakesItRealizable) {
  const TempMission t(
      {{"mission.xml", kRover},
       {"domain.fret", "boolean DustAlarm, SampleReq\n"},
       {"requirements.fret", std::string(kDustAndSample) +
                                 "A1: upon DustAlarm the Environment shall at the next timepoint "
                                 "satisfy !SampleReq\n"}});
  const realize::Result r = realizability(t);
  EXPECT_EQ(r.realizable, true);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components.front().requirements, (std::vector<std::string>{"G1", "G2", "G3", "A1"}));
  EXPECT_TRUE(r.components.front().conflicts.empty());
}

// The tree runs its nodes and lets them end; the world says how they end. A node the tree does
// not run neither succeeds nor fails, and the tree cannot make the world succeed.
TEST(Realizability, TheTreeRunsItsNodesAndTheWorldSaysHowTheyEnd) {
  const auto answer = [](const std::string& requirements) {
    const TempMission t({{"mission.xml", mission_with("    <Sequence>\n      <IsDug/>\n"
                                                      "      <TakePicture/>\n    </Sequence>")},
                         {"domain.fret", "boolean Go\n"},
                         {"requirements.fret", requirements}});
    return realizability(t).realizable;
  };
  EXPECT_EQ(answer("Picture: the rover shall always satisfy TakePicture.running | "
                   "TakePicture.success -> IsDug\n"),
            true);
  EXPECT_EQ(answer("Done: upon Go the rover shall within 2 ticks satisfy TakePicture.success\n"),
            false);
  EXPECT_EQ(answer("Ended: upon Go the rover shall within 2 ticks satisfy TakePicture.success | "
                   "TakePicture.failure\n"),
            true);
}

// world.json says how an action may end: a drill that never fails makes "it never fails"
// something every tree meets; without the entry the world may fail it whenever it ends.
TEST(Realizability, WorldJsonBoundsHowAnActionMayEnd) {
  const auto answer = [](const std::string& results) {
    std::map<std::string, std::string> files{
        {"mission.xml", mission_with("    <Sequence>\n      <Stow/>\n      <Drill/>\n"
                                     "    </Sequence>")},
        {"domain.fret", "boolean Go\n"},
        {"requirements.fret",
         "Drilled: upon Go the rover shall within 3 ticks satisfy Drill.success\n"
         "NeverFails: the rover shall never satisfy Drill.failure\n"}};
    if (!results.empty())
      files["world.json"] =
          "{\"actions\": {\"Drill\": {\"ticks\": [1, 2], \"results\": " + results +
          "}, \"Stow\": {\"ticks\": 1}}}";
    const TempMission t(files);
    return realizability(t);
  };
  const realize::Result free = answer("");
  EXPECT_EQ(free.realizable, false);
  ASSERT_EQ(free.components.size(), 1u);
  EXPECT_EQ(free.components[0].conflicts, (Conflicts{{"Drilled"}}));
  EXPECT_EQ(answer("[\"success\", \"failure\"]").realizable, false);
  const realize::Result sure = answer("[\"success\"]");
  EXPECT_EQ(sure.realizable, true);
  ASSERT_EQ(sure.notes.size(), 1u);
  EXPECT_NE(sure.notes[0].find("how long it runs does not"), std::string::npos) << sure.notes[0];
  // A drill that always fails: nothing meets "drilled within 3 ticks".
  const realize::Result never = answer("[\"failure\"]");
  EXPECT_EQ(never.realizable, false);
  EXPECT_EQ(never.components.at(0).conflicts, (Conflicts{{"Drilled"}}));
}

// A tree reacts within a tick to how its nodes ended (a Fallback ticks its second child when the
// first fails), and a condition ends as its value says.
TEST(Realizability, TheTreeReactsToHowItsNodesEnded) {
  const auto answer = [](const std::string& requirements) {
    const TempMission t(
        {{"mission.xml", mission_with("    <Fallback>\n      <IsClear/>\n      <Wait/>\n"
                                      "    </Fallback>")},
         {"nodes.xml",
          "<root BTCPP_format=\"4\"><TreeNodesModel><Condition ID=\"IsClear\"/>"
          "<Action ID=\"Wait\"/></TreeNodesModel></root>"},
         {"requirements.fret", requirements}});
    return realizability(t).realizable;
  };
  EXPECT_EQ(answer("Checked: the rover shall always satisfy IsClear.success | IsClear.failure\n"
                   "WaitWhenBlocked: whenever IsClear.failure the rover shall immediately "
                   "satisfy Wait.running\n"
                   "GoWhenClear: whenever IsClear.success the rover shall immediately satisfy "
                   "!Wait.running\n"),
            true);
  EXPECT_EQ(answer("Checked: the rover shall always satisfy IsClear.success | IsClear.failure\n"
                   "Agrees: the rover shall always satisfy IsClear.success -> IsClear\n"),
            true);
}

// One node's statuses are tied, so requirements on them are decided together.
TEST(Realizability, StatusesOfOneNodeAreOneComponent) {
  const TempMission t({{"mission.xml", mission_with("    <Sequence name=\"Leg\">\n      <Stow/>\n"
                                                    "    </Sequence>")},
                       {"requirements.fret",
                        "Runs: the rover shall always satisfy Leg.running\n"
                        "Done: the rover shall always satisfy Leg.success\n"}});
  const realize::Result r = realizability(t);
  EXPECT_EQ(r.realizable, false);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components.front().conflicts, (Conflicts{{"Runs", "Done"}}));
}

// An assumption the tree's outputs could break would let the tree win by breaking it: not
// decided.
TEST(Realizability, AnAssumptionOverTheTreesOutputsIsNotDecided) {
  const TempMission t({{"mission.xml", kRover},
                       {"domain.fret", "boolean Go\n"},
                       {"requirements.fret",
                        "Drills: whenever Go the rover shall immediately satisfy Drill.running\n"
                        "Cheat: the Environment shall always satisfy !Drill.running\n"}});
  const realize::Result r = realizability(t);
  EXPECT_EQ(r.realizable, std::nullopt);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_NE(r.components.front().reason.find("Cheat reads 'Drill.running'"), std::string::npos)
      << r.components.front().reason;
}

// A real-valued input is played by the cells its atoms draw: slope in (30, 45] asks for both.
TEST(Realizability, ARealInputIsPlayedByItsCells) {
  const std::string requirements =
      "Brake: whenever slope > 20 the rover shall immediately satisfy Stow.running\n"
      "Climb: whenever slope > 30 the rover shall immediately satisfy Drill.running\n"
      "OneAtATime: the rover shall always satisfy !(Stow.running & Drill.running)\n";
  const TempMission steep({{"mission.xml", kRover},
                           {"domain.fret", "real slope in [0, 45]\n"},
                           {"requirements.fret", requirements}});
  const realize::Result r = realizability(steep);
  ASSERT_EQ(r.realizable, false);
  EXPECT_EQ(r.components.front().conflicts, (Conflicts{{"Brake", "Climb", "OneAtATime"}}));
  ASSERT_EQ(r.components.front().defeating_inputs.size(), 1u);
  const Value slope = r.components.front().defeating_inputs[0].inputs.at(0).second;
  EXPECT_GT(slope.kind == Value::Kind::real ? slope.real : static_cast<double>(slope.integer), 30.0)
      << slope.to_string();
  const TempMission gentle({{"mission.xml", kRover},
                            {"domain.fret", "real slope in [0, 45]\nassume gentle: slope <= 30\n"},
                            {"requirements.fret", requirements}});
  EXPECT_EQ(realizability(gentle).realizable, true);
}

// Every minimal conflict, and a component apart for guarantees that share no output.
TEST(Realizability, EveryMinimalConflictOfEachComponent) {
  const TempMission t(
      {{"mission.xml", kRover},
       {"domain.fret", "boolean Go, Wind\n"},
       {"requirements.fret",
        "Do: whenever Go the rover shall immediately satisfy Drill.running\n"
        "Dont: whenever Go the rover shall immediately satisfy !Drill.running\n"
        "Never: the rover shall never satisfy Drill.running\n"
        "Stowed: whenever Wind the rover shall immediately satisfy Stow.running\n"}});
  const realize::Result r = realizability(t);
  ASSERT_EQ(r.realizable, false);
  ASSERT_EQ(r.components.size(), 2u);
  EXPECT_EQ(r.components[0].requirements, (std::vector<std::string>{"Do", "Dont", "Never"}));
  EXPECT_EQ(r.components[0].realizable, false);
  EXPECT_EQ(r.components[0].conflicts, (Conflicts{{"Do", "Dont"}, {"Do", "Never"}}));
  EXPECT_EQ(r.components[1].requirements, (std::vector<std::string>{"Stowed"}));
  EXPECT_EQ(r.components[1].realizable, true);
}

// Fail closed: a requirement realizability does not decide leaves the answer open.
TEST(Realizability, WhatIsNotASafetyRequirementIsNotDecided) {
  const TempMission t(
      {{"mission.xml", kRover},
       {"domain.fret", "boolean Go\n"},
       {"requirements.fret", "Later: upon Go the rover shall eventually satisfy Drill.running\n"}});
  const realize::Result r = realizability(t);
  EXPECT_EQ(r.realizable, std::nullopt);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_NE(r.components.front().reason.find("not a safety requirement"), std::string::npos)
      << r.components.front().reason;
}

// A name the mission does not have is said as such, with the closest name it has.
TEST(Realizability, ANameTheMissionDoesNotHaveIsNamedWithTheClosestOne) {
  const TempMission t(
      {{"mission.xml", kRover},
       {"requirements.fret", "Apart: the rover shall never satisfy Dril.running\n"}});
  const realize::Result r = realizability(t);
  EXPECT_EQ(r.realizable, std::nullopt);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components.front().reason,
            "Apart: 'Dril.running' is no domain variable, condition, node status "
            "(<node>.running/.success/.failure), adaptable node or <adaptable>.selected of the "
            "mission (did you mean 'Drill.running'?)");
}

TEST(Realizability, TheCommandAnswersInTextAndJsonWithItsExitCode) {
  const TempMission bad({{"mission.xml", kRover},
                         {"domain.fret", "boolean DustAlarm, SampleReq\n"},
                         {"requirements.fret", kDustAndSample}});
  const std::string dir = bad.dir().parent_path().string();
  const CliRun text = run_uabt_in(dir, "realizable m");
  EXPECT_EQ(text.exit_code, 1);
  EXPECT_EQ(text.out,
            "m/requirements.fret:1:5: error: no behavior tree meets G1, G2 and G3 together: the "
            "environment can always bring about a state in which one of them fails "
            "[requirements-unrealizable]\n"
            "m/requirements.fret:1:5: note: inputs that defeat every tree of this component: "
            "tick 1: DustAlarm = true, SampleReq = false; tick 2: DustAlarm = false, SampleReq = "
            "true\n"
            "realizable: no (1 component, 1 unrealizable with 1 minimal conflict)\n");
  const CliRun json = run_uabt_in(dir, "realizable m --format json");
  EXPECT_EQ(json.exit_code, 1);
  EXPECT_NE(json.out.find("\"realizable\": false"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"conflicts\": [\n    [\n      \"G1\",\n      \"G2\",\n      \"G3\""),
            std::string::npos)
      << json.out;
  // For code scanning and CI: the same finding as SARIF and JUnit.
  const CliRun sarif = run_uabt_in(dir, "realizable m --format sarif");
  EXPECT_EQ(sarif.exit_code, 1);
  EXPECT_NE(sarif.out.find("\"ruleId\": \"requirements-unrealizable\""), std::string::npos)
      << sarif.out;
  const CliRun junit = run_uabt_in(dir, "realizable m --format junit");
  EXPECT_EQ(junit.exit_code, 1);
  EXPECT_NE(junit.out.find("type=\"requirements-unrealizable\""), std::string::npos) << junit.out;
  const CliRun html = run_uabt_in(dir, "realizable m --format html");
  EXPECT_EQ(html.exit_code, 1);
  EXPECT_NE(html.out.find("<section id=\"realizability\">"), std::string::npos) << html.out;
  bad.write("requirements.fret", std::string(kDustAndSample) +
                                     "A1: upon DustAlarm the Environment shall at the next "
                                     "timepoint satisfy !SampleReq\n");
  const CliRun good = run_uabt_in(dir, "realizable m");
  EXPECT_EQ(good.exit_code, 0) << good.out;
  EXPECT_EQ(good.out, "realizable: yes (1 component)\n");
  bad.write("requirements.fret", "G1: the rover shall always satisfy\n");
  EXPECT_EQ(run_uabt_in(dir, "realizable m").exit_code, 2);
}

// ---- The cross-check: a second solver, written here from the requirements' meaning ----
//
// Inputs a, b (domain variables no tree writes), outputs Stow.running, Drill.running. Forms,
// E and C boolean formulas of one tick:
//   always E                      violated at t when E(t) fails
//   whenever C immediately E      violated at t when C(t) and not E(t)
//   upon C at the next timepoint E  violated at t when C rose at t-1 (C(t-1), and t-1 is the
//                                   first tick or C(t-2) failed) and not E(t)
// and optionally an assumption `the Environment shall always satisfy A` over the inputs.

struct Formula {
  // A small boolean formula over variables 0..3 (a, b, Stow.running, Drill.running).
  enum Kind { var, negation, conjunction, disjunction } kind = var;
  int variable = 0;
  std::vector<Formula> args;
  bool eval(unsigned valuation) const {
    switch (kind) {
      case var: return (valuation >> variable) & 1;
      case negation: return !args[0].eval(valuation);
      case conjunction: return args[0].eval(valuation) && args[1].eval(valuation);
      case disjunction: return args[0].eval(valuation) || args[1].eval(valuation);
    }
    return false;
  }
  std::string text() const {
    static const char* const kNames[] = {"a", "b", "Stow.running", "Drill.running"};
    switch (kind) {
      case var: return kNames[variable];
      case negation: return "!" + args[0].text();
      case conjunction: return "(" + args[0].text() + " & " + args[1].text() + ")";
      case disjunction: return "(" + args[0].text() + " | " + args[1].text() + ")";
    }
    return "";
  }
};

Formula random_formula(std::mt19937& random, int depth, int variables) {
  Formula f;
  const int pick = std::uniform_int_distribution<int>(0, depth == 0 ? 1 : 3)(random);
  if (pick <= 1) {
    f.kind = Formula::var;
    f.variable = std::uniform_int_distribution<int>(0, variables - 1)(random);
    if (pick == 1) {
      Formula n;
      n.kind = Formula::negation;
      n.args.push_back(f);
      return n;
    }
    return f;
  }
  f.kind = pick == 2 ? Formula::conjunction : Formula::disjunction;
  f.args.push_back(random_formula(random, depth - 1, variables));
  f.args.push_back(random_formula(random, depth - 1, variables));
  return f;
}

struct Guarantee {
  int form = 0;  // 0 always, 1 whenever-immediately, 2 upon-next
  Formula condition, response;
};

// The game written out: a state is the valuations of the last two ticks and how many ticks
// there were (0, 1, 2 or more); the tree wins from a state when every input has an output that
// keeps every guarantee (or breaks the assumption) and leads to a state it wins from.
bool independent_realizable(const std::vector<Guarantee>& guarantees,
                            const std::optional<Formula>& assumption) {
  struct State {
    unsigned before = 0, last = 0;  // valuations: bit 0 a, 1 b, 2 Stow.running, 3 Drill.running
    int ticks = 0;                  // 0, 1 or 2 (two or more)
    int index() const {
      return ticks == 0 ? 0 : 1 + static_cast<int>(last + 16 * before) + 256 * (ticks - 1);
    }
  };
  const auto violated = [&](const State& s, unsigned now) {
    for (const Guarantee& g : guarantees) {
      if (g.form == 0 && !g.response.eval(now)) return true;
      if (g.form == 1 && g.condition.eval(now) && !g.response.eval(now)) return true;
      if (g.form == 2 && s.ticks >= 1 && g.condition.eval(s.last) &&
          (s.ticks == 1 || !g.condition.eval(s.before)) && !g.response.eval(now))
        return true;
    }
    return false;
  };
  const auto next = [](const State& s, unsigned now) {
    return State{s.last, now, std::min(s.ticks + 1, 2)};
  };
  std::vector<State> states{State{}};
  for (unsigned last = 0; last < 16; ++last) states.push_back(State{0, last, 1});
  for (unsigned before = 0; before < 16; ++before)
    for (unsigned last = 0; last < 16; ++last) states.push_back(State{before, last, 2});
  std::vector<char> winning(1 + 16 + 256 * 2, 1);
  for (bool changed = true; changed;) {
    changed = false;
    for (const State& s : states) {
      if (!winning[static_cast<std::size_t>(s.index())]) continue;
      for (unsigned input = 0; input < 4; ++input) {
        bool answered = false;
        for (unsigned output = 0; output < 4 && !answered; ++output) {
          const unsigned now = input | (output << 2);
          if (assumption && !assumption->eval(now))
            answered = true;
          else if (!violated(s, now) && winning[static_cast<std::size_t>(next(s, now).index())])
            answered = true;
        }
        if (!answered) {
          winning[static_cast<std::size_t>(s.index())] = 0;
          changed = true;
          break;
        }
      }
    }
  }
  return winning[0] != 0;
}

// The defeating inputs as a scenario: replayed with `uabt run` on a mission's tree that keeps
// running, they make it violate the conflict's requirements at the tick the game says; an
// action the inputs always end the same way is a scenario action with that result.
TEST(Realizability, TheDefeatingInputsReplayAsAScenarioThatViolatesTheConflict) {
  const TempMission t(
      {{"mission.xml", mission_with("    <KeepRunningUntilFailure>\n      <Sequence>\n"
                                    "        <Stow/>\n        <Drill/>\n      </Sequence>\n"
                                    "    </KeepRunningUntilFailure>")},
       {"domain.fret", "boolean DustAlarm, SampleReq\n"},
       {"requirements.fret", kDustAndSample}});
  const std::string dir = t.dir().parent_path().string();
  const CliRun realizable = run_uabt_in(dir, "realizable m --scenarios defeats");
  EXPECT_EQ(realizable.exit_code, 1);
  EXPECT_NE(realizable.out.find("note: the inputs that defeat every tree meeting G1's conflict: "
                                "defeats/G1.json (replay them with `uabt run m --scenario "
                                "defeats/G1.json`)"),
            std::string::npos)
      << realizable.out;
  const CliRun run = run_uabt_in(dir, "run m --scenario defeats/G1.json");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_NE(run.out.find("tick 2: guarantee G1 violated"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("tick 2: guarantee G2 violated"), std::string::npos) << run.out;

  // A drill the world fails whenever it ends: the scenario's Drill fails.
  const TempMission drill({{"mission.xml", kRover},
                           {"domain.fret", "boolean Go\n"},
                           {"requirements.fret",
                            "Drilled: upon Go the rover shall within 2 ticks satisfy "
                            "Drill.success\n"}});
  const realize::Result r = realizability(drill);
  ASSERT_EQ(r.components.size(), 1u);
  const std::optional<std::string> scenario = realize::defeat_scenario(r, r.components[0]);
  ASSERT_TRUE(scenario.has_value());
  EXPECT_NE(scenario->find("\"Drill\": {\n      \"ticks\": 1,\n      \"result\": \"failure\""),
            std::string::npos)
      << *scenario;
  // A node the requirement names by its name: the scenario gives the result to its action ID
  // (the tree keeps running however the drill ends).
  const TempMission bore(
      {{"mission.xml", mission_with("    <KeepRunningUntilFailure>\n      <Inverter>\n"
                                    "        <Drill name=\"bore\"/>\n      </Inverter>\n"
                                    "    </KeepRunningUntilFailure>")},
       {"domain.fret", "boolean Go\n"},
       {"requirements.fret",
        "Drilled: upon Go the rover shall within 2 ticks satisfy "
        "bore.success\n"}});
  const std::string bore_dir = bore.dir().parent_path().string();
  const CliRun named = run_uabt_in(bore_dir, "realizable m --scenarios defeats");
  EXPECT_NE(named.out.find("no behavior tree meets Drilled: the environment can always bring "
                           "about a state in which it fails"),
            std::string::npos)
      << named.out;
  const CliRun bored = run_uabt_in(bore_dir, "run m --scenario defeats/Drilled.json");
  EXPECT_EQ(bored.exit_code, 1) << bored.out;
  EXPECT_NE(bored.out.find("property Drilled: violated from tick 3"), std::string::npos)
      << bored.out;
  // Nothing to write for a realizable set.
  realize::Component met;
  met.realizable = true;
  EXPECT_FALSE(realize::defeat_scenario(r, met).has_value());
}

TEST(Realizability, AgreesWithAGameSolverWrittenFromTheRequirementsMeaning) {
  std::mt19937 random(40);
  int unrealizable = 0, realizable = 0;
  const TempMission t({{"mission.xml", kRover}, {"domain.fret", "boolean a, b\n"}});
  for (int round = 0; round < 300; ++round) {
    std::vector<Guarantee> guarantees(
        static_cast<std::size_t>(std::uniform_int_distribution<int>(1, 3)(random)));
    std::string text;
    for (std::size_t k = 0; k < guarantees.size(); ++k) {
      Guarantee& g = guarantees[k];
      g.form = std::uniform_int_distribution<int>(0, 2)(random);
      g.condition = random_formula(random, 1, 2);  // over the inputs
      g.response = random_formula(random, 2, 4);
      const std::string id = "G" + std::to_string(k + 1);
      text += g.form == 0 ? id + ": the rover shall always satisfy " + g.response.text()
              : g.form == 1
                  ? id + ": whenever " + g.condition.text() +
                        " the rover shall immediately satisfy " + g.response.text()
                  : id + ": upon " + g.condition.text() +
                        " the rover shall at the next timepoint satisfy " + g.response.text();
      text += "\n";
    }
    std::optional<Formula> assumption;
    if (std::uniform_int_distribution<int>(0, 2)(random) == 0) {
      assumption = random_formula(random, 1, 2);
      text += "A: the Environment shall always satisfy " + assumption->text() + "\n";
    }
    t.write("requirements.fret", text);
    const realize::Result r = realizability(t);
    ASSERT_TRUE(r.realizable.has_value()) << text;
    ASSERT_EQ(*r.realizable, independent_realizable(guarantees, assumption)) << text;
    (*r.realizable ? realizable : unrealizable) += 1;
  }
  // Both answers are common enough for the agreement to mean something.
  EXPECT_GT(realizable, 50);
  EXPECT_GT(unrealizable, 50);
}

// The minimal conflicts against a hitting-set search built on the second solver: the maximal
// subsets of guarantees it finds realizable give the minimal correction sets (their
// complements), and the minimal conflicts are exactly the minimal sets that hit every one of
// them (MARCO's duality). Up to six guarantees a set, so that every subset is tried.
TEST(Realizability, MinimalConflictsAreTheMinimalHittingSetsOfTheCorrectionSets) {
  std::mt19937 random(41);
  const TempMission t({{"mission.xml", kRover}, {"domain.fret", "boolean a, b\n"}});
  std::size_t sets = 0, conflicts = 0, several = 0;
  for (int round = 0; round < 120; ++round) {
    const std::size_t n =
        static_cast<std::size_t>(std::uniform_int_distribution<int>(2, 6)(random));
    std::vector<Guarantee> guarantees(n);
    std::string text;
    for (std::size_t k = 0; k < n; ++k) {
      Guarantee& g = guarantees[k];
      g.form = std::uniform_int_distribution<int>(0, 2)(random);
      g.condition = random_formula(random, 1, 2);
      g.response = random_formula(random, 1, 4);
      const std::string id = "G" + std::to_string(k + 1);
      text += (g.form == 0 ? id + ": the rover shall always satisfy " + g.response.text()
               : g.form == 1
                   ? id + ": whenever " + g.condition.text() +
                         " the rover shall immediately satisfy " + g.response.text()
                   : id + ": upon " + g.condition.text() +
                         " the rover shall at the next timepoint satisfy " + g.response.text()) +
              "\n";
    }
    const unsigned all = (1u << n) - 1;
    std::vector<char> meets(all + 1);
    for (unsigned mask = 0; mask <= all; ++mask) {
      std::vector<Guarantee> subset;
      for (std::size_t k = 0; k < n; ++k)
        if (mask >> k & 1) subset.push_back(guarantees[k]);
      meets[mask] = independent_realizable(subset, std::nullopt);
    }
    if (meets[all]) continue;
    // Correction sets: complements of the maximal realizable subsets.
    std::vector<unsigned> corrections;
    for (unsigned mask = 0; mask <= all; ++mask) {
      if (!meets[mask]) continue;
      bool maximal = true;
      for (std::size_t k = 0; k < n && maximal; ++k)
        if (!(mask >> k & 1) && meets[mask | 1u << k]) maximal = false;
      if (maximal) corrections.push_back(all & ~mask);
    }
    const auto hits_all = [&](unsigned mask) {
      return std::all_of(corrections.begin(), corrections.end(),
                         [&](unsigned c) { return (mask & c) != 0; });
    };
    std::set<std::vector<std::string>> hitting;
    for (unsigned mask = 1; mask <= all; ++mask) {
      if (!hits_all(mask)) continue;
      bool minimal = true;
      for (std::size_t k = 0; k < n && minimal; ++k)
        if ((mask >> k & 1) && hits_all(mask & ~(1u << k))) minimal = false;
      if (!minimal) continue;
      std::vector<std::string> ids;
      for (std::size_t k = 0; k < n; ++k)
        if (mask >> k & 1) ids.push_back("G" + std::to_string(k + 1));
      hitting.insert(ids);
    }
    t.write("requirements.fret", text);
    const realize::Result r = realizability(t);
    ASSERT_EQ(r.realizable, false) << text;
    std::set<std::vector<std::string>> found;
    for (const auto& c : r.components) {
      EXPECT_TRUE(c.conflicts_complete) << text;
      found.insert(c.conflicts.begin(), c.conflicts.end());
    }
    ASSERT_EQ(found, hitting) << text;
    ++sets;
    conflicts += found.size();
    several += found.size() > 1 ? 1 : 0;
  }
  std::cout << "unrealizable sets: " << sets << ", minimal conflicts: " << conflicts
            << " (as many as the hitting-set search), sets with several: " << several << "\n";
  // Enough sets, and enough with several conflicts, for the agreement to mean something.
  EXPECT_GT(sets, 30u);
  EXPECT_GT(several, 5u);
}

}  // namespace
}  // namespace uabt::testing
