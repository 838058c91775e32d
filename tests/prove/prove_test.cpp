// uabt prove on whole missions: verdicts, shortest counterexamples that replay, bounds.
#include <nlohmann/json.hpp>

#include "prove_support.hpp"
#include "runtime/runner.hpp"

namespace uabt::testing {
namespace {

using prove::Verdict;

// What a counterexample row shows of each value: its text.
std::vector<std::pair<std::string, std::string>> texts(
    const std::vector<std::pair<std::string, Value>>& values) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [name, value] : values) out.emplace_back(name, value.to_string());
  return out;
}

TEST(Prove, BrokenAlternativeIsViolatedAtTheFirstTick) {
  const prove::Result r = prove_dir(mission_dir("sample_drilling"));
  EXPECT_TRUE(r.complete);
  ASSERT_EQ(r.answers.size(), 2u);
  const prove::Answer& cool = answer(r, "CoolBit");
  ASSERT_EQ(cool.verdict, Verdict::violated);
  ASSERT_TRUE(cool.counterexample);
  // Shortest: the rotary alternative starts drilling with a hot bit in the very first tick.
  EXPECT_EQ(cool.counterexample->tick, 1u);
  ASSERT_EQ(cool.counterexample->rows.size(), 1u);
  const auto& row = cool.counterexample->rows[0];
  EXPECT_EQ(row.root, "RUNNING");
  EXPECT_EQ(texts(row.values), (std::vector<std::pair<std::string, std::string>>{
                                   {"Drill.running", "true"}, {"IsBitCool", "false"}}));
  EXPECT_EQ(row.actions, std::vector<std::string>{"Drill started"});
  const auto scenario = nlohmann::json::parse(cool.counterexample->scenario);
  EXPECT_EQ(scenario["max_ticks"], 1);
  EXPECT_EQ(scenario["initial"]["HardRock"], false);
  EXPECT_EQ(scenario["initial"]["IsBitCool"], false);
  EXPECT_EQ(answer(r, "OneTool").verdict, Verdict::proved);
}

TEST(Prove, RepairedAlternativeIsProved) {
  auto files = mission_files("sample_drilling");
  files["alternatives/drilling/rotary.xml"] = kFixedRotary;
  TempMission m(files);
  const prove::Result r = prove_dir(m.dir());
  EXPECT_TRUE(r.complete);
  EXPECT_TRUE(r.passed());
  EXPECT_EQ(answer(r, "CoolBit").verdict, Verdict::proved);
}

TEST(Prove, ADepthBoundGivesBoundedNotProved) {
  auto files = mission_files("sample_drilling");
  files["alternatives/drilling/rotary.xml"] = kFixedRotary;
  TempMission m(files);
  prove::Options options;
  options.depth = 2;
  const prove::Result r = prove_dir(m.dir(), options);
  EXPECT_FALSE(r.complete);
  EXPECT_EQ(answer(r, "CoolBit").verdict, Verdict::bounded);
  EXPECT_EQ(answer(r, "CoolBit").depth, 2u);
  const auto findings = gate::findings_of(r);
  ASSERT_EQ(findings.size(), 2u);
  EXPECT_EQ(findings[0].check, "prove-bounded");
  EXPECT_EQ(findings[0].location.line, 5);
}

// The explicit engine's work is bounded by steps, not only by states: a Sequence of actions
// without a world.json contract has few states, but each tick may end in any of them and each
// state is compared by all of its bytes. With the budget spent the answer is bounded, with a
// note naming the budget, and the gate fails closed on it.
TEST(Prove, TheExplicitBudgetStopsTheSearchWithBoundedAndANote) {
  auto files = mission_files("sample_drilling");
  std::string hops;
  for (int i = 0; i < 60; ++i) hops += "        <Hop/>\n";
  std::string rotary = kFixedRotary;
  const std::string drill = "      <Drill mode=\"rotary\"/>";
  rotary.replace(rotary.find(drill), 0, "      <Sequence>\n" + hops + "      </Sequence>\n");
  files["alternatives/drilling/rotary.xml"] = rotary;
  TempMission m(files);
  const prove::Result whole = prove_dir(m.dir());
  EXPECT_TRUE(whole.complete);
  EXPECT_EQ(answer(whole, "CoolBit").verdict, Verdict::proved);
  for (const std::string& note : whole.notes) EXPECT_EQ(note.find("budget"), std::string::npos);

  prove::Options options;
  options.explicit_steps = 20'000;
  const prove::Result cut = prove_dir(m.dir(), options);
  EXPECT_FALSE(cut.complete);
  EXPECT_LT(cut.states, whole.states);
  EXPECT_EQ(answer(cut, "CoolBit").verdict, Verdict::bounded);
  EXPECT_EQ(answer(cut, "OneTool").verdict, Verdict::bounded);
  ASSERT_EQ(cut.notes.size(), 1u);
  EXPECT_EQ(cut.notes[0].rfind("the explicit-state engine spent its budget (20000 steps: node "
                               "ticks, the bytes of the states it compared, and 256 a "
                               "transition) at tick ",
                               0),
            0u)
      << cut.notes[0];
  const auto findings = gate::findings_of(cut);
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings[0].check, "prove-bounded");
  EXPECT_EQ(findings[0].severity, Severity::error);
}

// Only a later tick can break this one: the second drilling cycle on a hot bit.
TEST(Prove, CounterexampleIsTheShortest) {
  TempMission m(hot_bit_after_a_drill());
  const prove::Result r = prove_dir(m.dir());
  const prove::Answer& a = answer(r, "Cool");
  ASSERT_EQ(a.verdict, Verdict::violated);
  // Tick 1: the first drill starts on a cool bit. Tick 2: it ends and heats the bit, and
  // Repeat's wake-up re-tick starts the next cycle within the same tick: on HardRock the
  // percussive alternative drills the hot bit.
  EXPECT_EQ(a.counterexample->tick, 2u);
  const auto scenario = nlohmann::json::parse(a.counterexample->scenario);
  EXPECT_EQ(scenario["actions"]["Drill"]["runs"][0]["ticks"], 2);
  EXPECT_EQ(scenario["actions"]["Drill"]["runs"][0]["effects"]["IsBitCool"], false);
  ASSERT_TRUE(scenario.contains("events"));
  EXPECT_EQ(scenario["events"][0]["at"], 2);
  EXPECT_EQ(scenario["events"][0]["set"]["HardRock"], true);
}

// The counterexample is a scenario the runtime's own runner plays to the same state.
TEST(Prove, CounterexampleRunsOnTheRuntime) {
  const prove::Result r = prove_dir(mission_dir("sample_drilling"));
  const prove::Answer& a = answer(r, "CoolBit");
  ASSERT_TRUE(a.counterexample);
  runtime::Scenario s = runtime::parse_scenario(a.counterexample->scenario, "cex.json");
  std::string error;
  auto mission = load::load_mission(mission_dir("sample_drilling"), {}, error);
  gate::Outcome outcome = gate::run_gate(std::move(*mission), {}, "test");
  std::vector<Finding> findings;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  runtime::Runner runner(*doc, s);
  const runtime::RunResult run = runner.run();
  EXPECT_EQ(run.ticks, 1u);
  EXPECT_EQ(run.verdict, "timeout");
  const runtime::ScriptValue* cool = runner.engine().blackboard().get("IsBitCool");
  ASSERT_NE(cool, nullptr);
  EXPECT_EQ(cool->to_string(), "false");
  ASSERT_FALSE(run.log.empty());
  EXPECT_EQ(run.log.back().leaf, "Drill");
  EXPECT_EQ(run.log.back().event, runtime::LeafEvent::action_started);
}

// A contract whose maximum no explored run reaches ("ticks": [2, 9223372036854775807]: as long
// as it takes) answers as a short one does, and completely: the ticks past the minimum look
// alike, so they are not counted one state each. A small state limit makes a counter per tick
// show as an incomplete (bounded) search.
TEST(Prove, AContractWithoutAReachableMaximumCostsNoStatePerTick) {
  prove::Options options;
  options.max_states = 5'000;
  for (const char* ticks : {"[2, 3]", "[2, 9223372036854775807]"}) {
    SCOPED_TRACE(ticks);
    auto files = mission_files("sample_drilling");
    files["alternatives/drilling/rotary.xml"] = kFixedRotary;
    files["world.json"] =
        std::string(R"({"initial": "!IsBitCool", "actions": {"Drill": {"ticks": )") + ticks +
        R"(, "on_success": "IsBitCool = false", "on_failure": "IsBitCool = false"},
        "CoolDown": {"ticks": )" +
        ticks + R"(, "on_success": "IsBitCool = true"}}})";
    TempMission m(files);
    const prove::Result r = prove_dir(m.dir(), options);
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(answer(r, "CoolBit").verdict, Verdict::proved);
    EXPECT_EQ(answer(r, "OneTool").verdict, Verdict::proved);
  }
  for (const char* ticks : {"2", "[2, 9223372036854775807]"}) {
    SCOPED_TRACE(ticks);
    auto files = hot_bit_after_a_drill();
    files["world.json"] =
        std::string(R"({"initial": "IsBitCool", "actions": {"Drill": {"ticks": )") + ticks +
        R"(, "results": ["success"], "on_success": "IsBitCool = false"},
        "CoolDown": {"ticks": 1, "results": ["success"], "on_success": "IsBitCool = true"}}})";
    TempMission m(files);
    const prove::Result r = prove_dir(m.dir(), options);
    const prove::Answer& a = answer(r, "Cool");
    ASSERT_EQ(a.verdict, Verdict::violated);
    EXPECT_EQ(a.counterexample->tick, 2u);
    EXPECT_EQ(
        nlohmann::json::parse(a.counterexample->scenario)["actions"]["Drill"]["runs"][0]["ticks"],
        2);
  }
}

// An Environment requirement is an assumption: runs that break it are not runs of the world.
TEST(Prove, EnvironmentRequirementsRestrictTheWorld) {
  auto files = mission_files("sample_drilling");
  // A drill that never fails: the percussive alternative then never falls through to rotary.
  files["world.json"] = R"({"initial": "!IsBitCool", "actions": {
      "Drill": {"ticks": [2, 3], "results": ["success"], "on_success": "IsBitCool = false"},
      "CoolDown": {"ticks": [1, 2], "results": ["success"], "on_success": "IsBitCool = true"}}})";
  {
    TempMission m(files);
    EXPECT_EQ(answer(prove_dir(m.dir()), "CoolBit").verdict, Verdict::violated);
  }
  files["requirements.fret"] += "HardOnly: Environment shall always satisfy HardRock\n";
  TempMission m(files);
  const prove::Result r = prove_dir(m.dir());
  EXPECT_EQ(answer(r, "CoolBit").verdict, Verdict::proved);
  EXPECT_EQ(r.answers.size(), 2u);  // the assumption is not a guarantee
}

// A failing drill heats the bit and makes the percussive branch fail; the selection Fallback
// then falls through to the default, which drills the hot bit (ARCHITECTURE §5's fall-through).
TEST(Prove, FallThroughToTheDefaultIsFound) {
  auto files = mission_files("sample_drilling");
  files["requirements.fret"] += "HardOnly: Environment shall always satisfy HardRock\n";
  TempMission m(files);
  const prove::Result r = prove_dir(m.dir());
  const prove::Answer& a = answer(r, "CoolBit");
  ASSERT_EQ(a.verdict, Verdict::violated);
  ASSERT_EQ(a.counterexample->rows.size(), 2u);
  EXPECT_EQ(a.counterexample->rows[1].actions,
            (std::vector<std::string>{"Drill failure", "Drill started"}));
}

TEST(Prove, UnreadablePropertyIsNotChecked) {
  auto files = mission_files("sample_drilling");
  files["requirements.fret"] += "Odd: Mission shall always satisfy Nowhere.success\n";
  TempMission m(files);
  const prove::Result r = prove_dir(m.dir());
  EXPECT_EQ(answer(r, "Odd").verdict, Verdict::unsupported);
  EXPECT_NE(answer(r, "Odd").reason.find("Nowhere.success"), std::string::npos)
      << answer(r, "Odd").reason;
  EXPECT_FALSE(r.passed());
}

TEST(Prove, WholeDomainWithoutWorldFile) {
  auto files = mission_files("sample_drilling");
  files.erase("world.json");
  TempMission m(files);
  const prove::Result r = prove_dir(m.dir());
  // Unconstrained actions: Drill may run while the bit is hot, and may end at once.
  EXPECT_EQ(answer(r, "CoolBit").verdict, Verdict::violated);
  EXPECT_EQ(answer(r, "OneTool").verdict, Verdict::proved);
}

TEST(Prove, GateFindingsAtTheRequirement) {
  std::string error;
  auto mission = load::load_mission(mission_dir("sample_drilling"), {}, error);
  // The checks pass; the gate fails in its proof step alone.
  ASSERT_TRUE(gate::check_mission(*mission, {}, "test").passed());
  gate::Outcome outcome = gate::run_gate(std::move(*mission), {}, "test");
  EXPECT_FALSE(outcome.passed());
  ASSERT_EQ(outcome.report.findings.size(), 1u);
  const Finding& f = outcome.report.findings[0];
  EXPECT_EQ(f.check, "prove-violated");
  EXPECT_EQ(f.location.file, "requirements.fret");
  EXPECT_EQ(f.location.line, 5);
  EXPECT_EQ(f.requirements, std::vector<std::string>{"CoolBit"});
  EXPECT_EQ(outcome.report.stages,
            (std::vector<std::string>{"load", "verify", "compile", "conform", "prove", "realize"}));
}

TEST(Prove, MissionWithoutGuaranteesIsLeftAlone) {
  std::string error;
  auto mission = load::load_mission(mission_dir("msl_curiosity_paper"), {}, error);
  const auto checked = gate::check_mission(*mission, {}, "test").report.findings.size();
  gate::Outcome outcome = gate::run_gate(std::move(*mission), {}, "test");
  EXPECT_EQ(outcome.report.findings.size(), checked);
  EXPECT_FALSE(outcome.report.proofs);
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

// HoldOnUnknown holds only with the reactive selection; ArmClosed is violated in both styles
// (with one-tick actions the drive and the opening of the arm succeed in the same tick).
TEST(ProveMsl, ShippedGuaranteesAnswered) {
  // The paper's sequence style: a running drive runs on over an unknown terrain.
  const prove::Result r = prove_dir(mission_dir("msl_curiosity"));
  EXPECT_TRUE(r.complete);
  ASSERT_EQ(r.answers.size(), 4u);
  for (const auto& a : r.answers) {
    const bool violated = a.requirement == "HoldOnUnknown";
    EXPECT_EQ(a.verdict, violated ? Verdict::violated : Verdict::proved) << a.requirement;
  }
  ASSERT_TRUE(answer(r, "HoldOnUnknown").counterexample);
  EXPECT_EQ(answer(r, "HoldOnUnknown").counterexample->tick, 3u);
  // The style the mission declares (reactive): every guarantee proved.
  const prove::Result reactive =
      prove_dir(mission_dir("msl_curiosity"), {}, compile::SelectionStyle::reactive);
  EXPECT_TRUE(reactive.complete);
  for (const auto& a : reactive.answers) EXPECT_EQ(a.verdict, Verdict::proved) << a.requirement;
}

// The paper's sequence-style selection keeps running the alternative it started when the
// terrain changes; the reactive style re-checks the guards every tick.
TEST(ProveMsl, TerrainChangeNeedsTheReactiveStyle) {
  auto files = mission_files("msl_curiosity");
  files["requirements.fret"] +=
      "RocksDrive: In navigation mode whenever OnRocks Mission shall immediately satisfy "
      "navigation.selected = on_rocks\n";
  TempMission m(files);
  const prove::Result sequence = prove_dir(m.dir());
  const prove::Answer& a = answer(sequence, "RocksDrive");
  ASSERT_EQ(a.verdict, Verdict::violated);
  ASSERT_EQ(a.counterexample->tick, 2u);
  const auto last = texts(a.counterexample->rows.back().values);
  EXPECT_EQ(
      last,
      (std::vector<std::pair<std::string, std::string>>{
          {"navigation", "true"}, {"OnRocks", "true"}, {"navigation.selected", "hold_position"}}));
  const prove::Result reactive = prove_dir(m.dir(), {}, compile::SelectionStyle::reactive);
  EXPECT_EQ(answer(reactive, "RocksDrive").verdict, Verdict::proved);
}

}  // namespace
}  // namespace uabt::testing
