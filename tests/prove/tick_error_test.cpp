// A tick that stops with an error (BT.CPP throws on a read of a blackboard entry nothing has
// written) ends that run, as in `uabt run`. Both engines say so with the runtime's own error at
// the first such tick, and a guarantee whose trigger only such runs would reach is proved with
// the prove-trigger-unreachable warning, never silently.
#include <gtest/gtest.h>

#include "cli/cli_support.hpp"
#include "prove_support.hpp"

namespace uabt::testing {
namespace {

using prove::Verdict;

const char* kBallastNodes = R"(<root BTCPP_format="4">
  <TreeNodesModel>
    <Action ID="Descend"/>
    <Action ID="Trim"><input_port name="mass" type="int"/></Action>
    <Action ID="WeighBallast"><output_port name="mass" type="int"/></Action>
  </TreeNodesModel>
</root>
)";

// Trim reads {ballast_kg} before WeighBallast writes it: every run stops at tick 3, in the tick
// Descend succeeds, so no run shows Descend.success and TrimAfterDescent never asks anything
// (without the error it would be violated: Trim may fail).
std::map<std::string, std::string> ballast_mission() {
  return {{"mission.xml", mission_with("    <Sequence>\n"
                                       "      <Descend/>\n"
                                       "      <Trim mass=\"{ballast_kg}\"/>\n"
                                       "      <WeighBallast mass=\"{ballast_kg}\"/>\n"
                                       "    </Sequence>")},
          {"nodes.xml", kBallastNodes},
          {"domain.fret", "boolean Surfaced\n"},
          {"requirements.fret",
           "TrimAfterDescent: upon Descend.success Mission shall within 2 ticks satisfy "
           "Trim.success\n"
           "StaysDown: Mission shall always satisfy !Surfaced | Descend.running\n"},
          {"world.json", R"({"initial": "!Surfaced", "actions": {
             "Descend": {"ticks": 3, "results": ["success"]},
             "WeighBallast": {"outputs": {"mass": 40}}}})"}};
}

std::vector<std::string> error_notes(const prove::Result& r) {
  std::vector<std::string> out;
  for (const std::string& n : r.notes)
    if (n.find("stops with an error") != std::string::npos) out.push_back(n);
  return out;
}

TEST(TickError, BothEnginesNameTheTickThatStopsEveryRunAndWarnOfTheUnreachableTrigger) {
  TempMission m(ballast_mission());
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const std::string error =
      "a reachable tick stops with an error: tick 3 of a run: compiled.xml:6:7: Trim: input port "
      "'mass' reads {ballast_kg}, which nothing has written: getInput() failed because it was "
      "unable to find the key [mass] remapped to [ballast_kg]";
  for (const std::string engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    const prove::Result r = g.prove(engine);
    EXPECT_FALSE(r.vacuity) << r.vacuity->message;
    EXPECT_EQ(error_notes(r), std::vector<std::string>{error});
    const prove::Answer& trim = answer(r, "TrimAfterDescent");
    ASSERT_EQ(trim.verdict, Verdict::proved);
    EXPECT_TRUE(trim.has_trigger);
    EXPECT_TRUE(trim.trigger_decided);
    EXPECT_EQ(trim.first_trigger, 0u);
    std::vector<std::string> unreachable;
    for (const Finding& f : gate::findings_of(r))
      if (f.check == "prove-trigger-unreachable") unreachable.push_back(f.requirements.at(0));
    EXPECT_EQ(unreachable, std::vector<std::string>{"TrimAfterDescent"});
    EXPECT_EQ(answer(r, "StaysDown").verdict, Verdict::proved);
  }
}

// From the command line, the symbolic engine's output says the same as the explicit one's.
TEST(TickError, TheSymbolicEngineSaysSoOnTheCommandLine) {
  TempMission m(ballast_mission());
  const CliRun run = run_shell(std::string(UABT_BINARY) + " prove " + m.dir().string() +
                               " --engine symbolic 2>&1");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("note: a reachable tick stops with an error: tick 3 of a run: "),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("guarantee 'TrimAfterDescent' is proved, but its trigger (its mode and "
                         "condition) holds on no run, so it never asks anything"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("[prove-trigger-unreachable]"), std::string::npos) << run.out;
}

// Once WeighBallast runs first the runs go on: the trigger holds at tick 3 and the guarantee
// is violated at the same tick in both engines, with no error to note.
TEST(TickError, WithTheEntryWrittenFirstBothEnginesRefuteTheGuaranteeAtTheSameTick) {
  auto files = ballast_mission();
  files["mission.xml"] = mission_with(
      "    <Sequence>\n"
      "      <WeighBallast mass=\"{ballast_kg}\"/>\n"
      "      <Descend/>\n"
      "      <Trim mass=\"{ballast_kg}\"/>\n"
      "    </Sequence>");
  TempMission m(files);
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result x = g.prove("explicit"), s = g.prove("symbolic");
  for (const prove::Result* r : {&x, &s}) {
    SCOPED_TRACE(r->engine);
    EXPECT_TRUE(error_notes(*r).empty());
    const prove::Answer& trim = answer(*r, "TrimAfterDescent");
    ASSERT_EQ(trim.verdict, Verdict::violated);
    EXPECT_EQ(trim.depth, answer(x, "TrimAfterDescent").depth);
  }
}

}  // namespace
}  // namespace uabt::testing
