// Proofs over blackboard ports: an action's output port `{waypoint}` writes the entry (the value
// world.json gives, else any value its readers tell apart), a ScriptCondition, a guard or an
// input port reads it. Both engines answer alike, counterexamples say what each action wrote
// and replay in the runtime, and the gate no longer stops at prove-bounded.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"
#include "prove_support.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario.hpp"

namespace uabt::testing {
namespace {

const char* kNodes = R"(<root BTCPP_format="4">
  <TreeNodesModel>
    <Action ID="PlanOrbit"><output_port name="waypoint" type="int"/></Action>
    <Action ID="Burn"><input_port name="target" type="int"/></Action>
    <Action ID="Abort"/>
    <Action ID="Glide"/>
    <Action ID="Hover"/>
  </TreeNodesModel>
</root>
)";

// PlanOrbit writes {waypoint}; a ScriptCondition reads it (a far waypoint aborts), Burn's
// input port reads it, and the approach's guards may read it too.
std::map<std::string, std::string> orbit_mission(const std::string& first = "",
                                                 const std::string& domain = "",
                                                 const std::string& guard = "terrain = flat") {
  return {
      {"mission.xml",
       mission_with("    <Sequence>\n" +
                    (first.empty() ? "      <PlanOrbit waypoint=\"{waypoint}\"/>" : first) +
                    "\n      <Fallback>\n"
                    "        <ScriptCondition name=\"near\" code=\"waypoint "
                    "&lt; 5\"/>\n"
                    "        <Abort name=\"abort\"/>\n"
                    "      </Fallback>\n"
                    "      <Burn target=\"{waypoint}\"/>\n"
                    "      <Adaptable ID=\"approach\"/>\n"
                    "    </Sequence>")},
      {"nodes.xml", kNodes},
      {"domain.fret", "enum terrain in {flat, rough}\n" + domain},
      {"requirements.fret", "Flat: In approach if " + guard +
                                " Mission shall satisfy selected_alt = glide\n"
                                "Other: In approach Mission shall satisfy selected_alt = hover\n"
                                "NoAbort: Mission shall always satisfy !abort.success\n"},
      {"alternatives/approach/glide.xml", alternative_tree("glide", "<Glide/>")},
      {"alternatives/approach/hover.xml", alternative_tree("hover", "<Hover/>")}};
}

TEST(BlackboardPorts, BothEnginesRefuteAGuaranteeOnTheWrittenValueAndTheCounterexampleReplays) {
  TempMission m(orbit_mission());
  Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  for (const std::string engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    const prove::Result r = g.prove(engine);
    EXPECT_EQ(r.engine, engine);
    const prove::Answer& a = answer(r, "NoAbort");
    ASSERT_EQ(a.verdict, prove::Verdict::violated);
    EXPECT_EQ(a.depth, 1u);
    ASSERT_TRUE(a.counterexample);
    // The scenario says what PlanOrbit wrote: a waypoint the ScriptCondition finds far.
    const auto scenario = nlohmann::json::parse(a.counterexample->scenario);
    const auto& written = scenario["actions"]["PlanOrbit"]["runs"][0]["outputs"]["waypoint"];
    ASSERT_TRUE(written.is_number_integer()) << a.counterexample->scenario;
    EXPECT_GE(written.get<int>(), 5);
    // `uabt run` replays it to the same violation (prove replayed it too before reporting).
    std::vector<bt::NodeModel> nodes = *g.outcome->mission->nodes;
    runtime::Runner runner(*g.doc, runtime::parse_scenario(a.counterexample->scenario, "cex.json"),
                           {}, nodes);
    const runtime::RunResult run = runner.run();
    EXPECT_FALSE(run.error.has_value()) << run.error->message;
    // The violation replays: `abort` succeeds in tick 1 (what the root then returns is the
    // engine's choice for the alternative, not part of the property).
    bool aborted = false;
    for (const auto& entry : run.log)
      aborted |=
          entry.tick == 1 && entry.leaf == "Abort" && entry.status == runtime::NodeStatus::success;
    EXPECT_TRUE(aborted) << a.counterexample->scenario;
  }
}

TEST(BlackboardPorts, BothEnginesProveWhatTheWorldsValueGuarantees) {
  TempMission m(orbit_mission());
  m.write("world.json", R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": 3}}}})");
  Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  for (const std::string engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    const prove::Result r = g.prove(engine);
    EXPECT_EQ(answer(r, "NoAbort").verdict, prove::Verdict::proved);
    // No note but, for the symbolic engine, which of its methods proved it.
    for (const std::string& note : r.notes)
      EXPECT_EQ(note, "NoAbort is proved by IC3/PDR (Z3's Spacer)");
  }
}

// A guard of the selection reads the entry as the environment's values are read: the
// approach glides only near, so a guarantee on the selection depends on what PlanOrbit wrote.
TEST(BlackboardPorts, AGuardReadingTheEntryBranchesOverItsCellsInBothEngines) {
  auto files = orbit_mission("", "integer waypoint in [0, 100]\n", "waypoint < 3");
  files["requirements.fret"] +=
      "Glides: Mission shall always satisfy approach -> approach.selected = glide\n";
  TempMission m(files);
  // Glide always succeeds: the selection never falls through to hover after it.
  m.write("world.json", R"({"actions": {"Glide": {"results": ["success"]}}})");
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  for (const std::string engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    const prove::Result r = g.prove(engine);
    const prove::Answer& glides = answer(r, "Glides");
    ASSERT_EQ(glides.verdict, prove::Verdict::violated);
    const auto scenario = nlohmann::json::parse(glides.counterexample->scenario);
    const int written =
        scenario["actions"]["PlanOrbit"]["runs"][0]["outputs"]["waypoint"].get<int>();
    EXPECT_GE(written, 3);  // too far to glide
  }
  m.write("world.json", R"({"actions": {"Glide": {"results": ["success"]},
                             "PlanOrbit": {"outputs": {"waypoint": 2}}}})");
  Gated fixed(m.dir());
  ASSERT_TRUE(fixed.ok());
  for (const std::string engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    const prove::Result r = fixed.prove(engine);
    EXPECT_EQ(answer(r, "Glides").verdict, prove::Verdict::proved);
    EXPECT_EQ(answer(r, "NoAbort").verdict, prove::Verdict::proved);
  }
}

TEST(BlackboardPorts, TheGateNoLongerStopsAtProveBounded) {
  TempMission m(orbit_mission());
  m.write("world.json", R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": 3}}}})");
  std::string error;
  auto mission = load::load_mission(m.dir(), {}, error);
  ASSERT_TRUE(mission) << error;
  const gate::Outcome outcome = gate::run_gate(std::move(*mission), {}, "t");
  for (const Finding& f : outcome.report.findings)
    EXPECT_NE(f.severity, Severity::error) << f.check << ": " << f.message;
  EXPECT_TRUE(outcome.passed());
}

// Burn reads {waypoint} on a path where PlanOrbit did not run: the tick stops with BT.CPP's
// error there, that run ends, and the runs that write first are still proved over.
TEST(BlackboardPorts, AReadBeforeAnyWriteStopsThatRunInBothEngines) {
  TempMission m(
      orbit_mission("      <Fallback><Glide/><PlanOrbit waypoint=\"{waypoint}\"/></Fallback>"));
  Gated g(m.dir());
  ASSERT_TRUE(g.doc.has_value());
  const prove::Result x = g.prove("explicit");
  const prove::Result s = g.prove("symbolic");
  EXPECT_EQ(answer(x, "NoAbort").verdict, answer(s, "NoAbort").verdict);
  EXPECT_EQ(answer(x, "NoAbort").depth, answer(s, "NoAbort").depth);
  ASSERT_EQ(x.notes.size(), 1u);
  EXPECT_NE(x.notes[0].find("a reachable tick stops with an error: tick 1 of a run: "),
            std::string::npos)
      << x.notes[0];
  // The ScriptCondition reads it first: the error `uabt run` raises there.
  EXPECT_NE(x.notes[0].find("ScriptCondition 'near': undefined blackboard key 'waypoint'"),
            std::string::npos)
      << x.notes[0];
}

// From the command line: each engine's counterexample file replays in `uabt run` to the same
// violation, and the gate passes once world.json says what PlanOrbit writes.
TEST(BlackboardPorts, TheCounterexampleFileReplaysInUabtRunAndTheGatePasses) {
  TempMission m(orbit_mission());
  const std::string mission = m.dir().string();
  for (const std::string engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    const auto cex = m.dir().parent_path() / ("cex-" + engine);
    const CliRun proved = run_shell(std::string(UABT_BINARY) + " prove " + mission + " --engine " +
                                    engine + " --counterexamples " + cex.string() + " 2>&1");
    EXPECT_EQ(proved.exit_code, 1) << proved.out;
    EXPECT_NE(proved.out.find("guarantee 'NoAbort' is violated at tick 1"), std::string::npos)
        << proved.out;
    const CliRun replay = run_shell(std::string(UABT_BINARY) + " run " + mission + " --scenario " +
                                    (cex / "NoAbort.json").string() + " 2>&1");
    EXPECT_EQ(replay.exit_code, 1) << replay.out;
    EXPECT_NE(replay.out.find("tick 1: guarantee NoAbort violated (abort.success=true)"),
              std::string::npos)
        << replay.out;
  }
  m.write("world.json", R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": 3}}}})");
  const auto out = m.dir().parent_path() / "report";
  const CliRun gated =
      run_shell(std::string(UABT_BINARY) + " gate " + mission + " --out " + out.string() + " 2>&1");
  EXPECT_EQ(gated.exit_code, 0) << gated.out;
  EXPECT_EQ(gated.out.find("prove-bounded"), std::string::npos) << gated.out;
}

TEST(BlackboardPorts, WorldJsonOutputsAreCheckedAgainstTheNodesPortsAndTypes) {
  TempMission m(orbit_mission());
  std::string error;
  auto mission = load::load_mission(m.dir(), {}, error);
  ASSERT_TRUE(mission) << error;
  struct Case {
    std::string text, message;
    int line, column;
  };
  const std::vector<Case> cases = {
      {R"({"actions": {"PlanOrbit": {"outputs": {"waypoit": 3}}}})",
       "outputs of 'PlanOrbit': 'waypoit' is not an output port of 'PlanOrbit' (its output "
       "ports: waypoint) (did you mean 'waypoint'?)",
       1, 40},
      {R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": "far"}}}})",
       "outputs of 'PlanOrbit': the value of output port 'waypoint' of 'PlanOrbit', \"far\", is "
       "not an integer (the port's type is int)",
       1, 52},
      {"{\"actions\": {\"Burn\":\n  {\"outputs\": {\"target\": 1}}}}",
       "outputs of 'Burn': 'Burn' has no output port in nodes.xml, so it writes no 'target'", 2,
       16},
      {R"({"actions": {"PlanOrbit": {"outputs": {"waypoint": [1]}}}})",
       "the value of 'waypoint' must be a boolean, a number or a string", 1, 52},
      {R"({"actions": {"PlanOrbit": {"outputs": 3}}})", "outputs must be an object", 1, 28},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      prove::parse_world(c.text, "world.json", &*mission);
      ADD_FAILURE() << "accepted";
    } catch (const prove::WorldError& e) {
      EXPECT_NE(e.text.find(c.message), std::string::npos) << e.text;
      EXPECT_EQ(e.location.line, c.line) << e.what();
      EXPECT_EQ(e.location.column, c.column) << e.what();
    }
  }
}

// A value world.json gives that the domain rules out for the entry is the world's error, at
// the action, not a counterexample.
TEST(BlackboardPorts, AWorldValueOutsideTheDomainIsAnErrorAtTheAction) {
  TempMission m(orbit_mission("", "integer waypoint in [0, 10]\n"));
  m.write("world.json", "{\"actions\": {\n  \"PlanOrbit\": {\"outputs\": {\"waypoint\": 30}}}}");
  Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  try {
    g.prove("explicit");
    ADD_FAILURE() << "proved";
  } catch (const prove::WorldError& e) {
    EXPECT_EQ(e.location.line, 2);
    EXPECT_EQ(e.location.column, 3);
    EXPECT_NE(e.text.find("waypoint = 30 is out of its range [0, 10]"), std::string::npos)
        << e.text;
  }
}

}  // namespace
}  // namespace uabt::testing
