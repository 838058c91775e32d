#include <gtest/gtest.h>

#include "manager/manager.hpp"
#include "test_support.hpp"

namespace uabt::manager {
namespace {

using namespace uabt::runtime;  // the scenarios and traces the manager runs on

std::filesystem::path curiosity() {
  return uabt::testing::mission_dir("msl_curiosity");
}

ManagerRun run_scenario(const std::string& name, compile::SelectionStyle style,
                        std::vector<std::pair<std::int64_t, std::string>> uplinks = {}) {
  Scenario scenario = load_scenario(curiosity() / "scenarios" / (name + ".json"));
  ManagerOptions options;
  options.gate.compile.selection = style;
  options.gate.compile.selection_forced = true;
  BehaviorTreeManager manager(curiosity(), std::move(scenario), options);
  for (const auto& [tick, dir] : uplinks) manager.add_uplink(tick, dir);
  return manager.run();
}

std::vector<std::string> selected(const ManagerRun& run) {
  std::vector<std::string> out;
  for (const auto& e : run.trace)
    if (e.event == "select") out.push_back(e.alternative);
  return out;
}

const TraceEvent* first(const ManagerRun& run, const std::string& event) {
  for (const auto& e : run.trace)
    if (e.event == event) return &e;
  return nullptr;
}

TEST(Manager, DustyStartDrivesOnDustAndCollectsTheSample) {
  for (auto style : {compile::SelectionStyle::sequence, compile::SelectionStyle::reactive}) {
    ManagerRun run = run_scenario("dusty_start", style);
    EXPECT_EQ(selected(run), std::vector<std::string>{"on_dust"}) << trace_summary(run);
    EXPECT_TRUE(run.finished);
    EXPECT_EQ(run.status, NodeStatus::success) << trace_summary(run);
    EXPECT_EQ(run.trace.back().event, "done");
    EXPECT_EQ(run.trace.back().verdict, "success");
  }
}

TEST(Manager, RocksMidDriveTakeEffectAfterTheDriveWithThePapersFallback) {
  ManagerRun run = run_scenario("rocks_mid_drive", compile::SelectionStyle::sequence);
  // The plain Fallback does not re-check guards while on_dust runs: it finishes the drive.
  EXPECT_EQ(selected(run), std::vector<std::string>{"on_dust"}) << trace_summary(run);
  EXPECT_EQ(run.status, NodeStatus::success);
}

TEST(Manager, RocksMidDrivePreemptOnDustWithTheReactiveSelection) {
  ManagerRun run = run_scenario("rocks_mid_drive", compile::SelectionStyle::reactive);
  EXPECT_EQ(selected(run), (std::vector<std::string>{"on_dust", "on_rocks"})) << trace_summary(run);
  const TraceEvent* rocks = nullptr;
  for (const auto& e : run.trace)
    if (e.event == "select" && e.alternative == "on_rocks") rocks = &e;
  ASSERT_NE(rocks, nullptr);
  EXPECT_EQ(rocks->tick, 8u) << "the terrain changes before tick 8; the next tick pre-empts";
  EXPECT_EQ(rocks->requirement, "Req2");
  EXPECT_EQ(run.status, NodeStatus::success);
}

TEST(Manager, MudUplinkIsGatedSwappedAndCompletesTheMission) {
  ManagerRun run = run_scenario("mud_uplink", compile::SelectionStyle::reactive);
  const TraceEvent* uplink = first(run, "uplink");
  ASSERT_NE(uplink, nullptr);
  EXPECT_EQ(uplink->verdict, "accepted");
  EXPECT_EQ(uplink->tick, 30u);
  EXPECT_NE(std::find(uplink->swapped.begin(), uplink->swapped.end(), "navigation"),
            uplink->swapped.end());
  EXPECT_NE(std::find(uplink->swapped.begin(), uplink->swapped.end(), "on_mud"),
            uplink->swapped.end());
  auto alternatives = selected(run);
  ASSERT_FALSE(alternatives.empty());
  EXPECT_EQ(alternatives.front(), "on_rocks");
  EXPECT_EQ(alternatives.back(), "on_mud") << trace_summary(run);
  // Mud pre-empts on_rocks and, unknown until the uplink, gets the safe default.
  EXPECT_NE(std::find(alternatives.begin(), alternatives.end(), "hold_position"),
            alternatives.end())
      << trace_summary(run);
  EXPECT_EQ(uplink->halted, 1u) << "the running navigation instance is halted and rebuilt";
  EXPECT_EQ(run.accepted_uplinks, std::vector<std::string>{"uplinks/on_mud"});
  EXPECT_EQ(run.status, NodeStatus::success) << trace_summary(run);
}

// The hot swap takes the gate's whole decision, proofs included: compiled with the plain
// Sequence selection, the merged mission cannot hold HoldOnUnknown (on_rocks keeps driving on
// mud), so `uabt gate --selection sequence --uplink` rejects the package and so does the run.
TEST(Manager, MudUplinkWithTheSequenceSelectionIsRejectedByItsProof) {
  ManagerRun run = run_scenario("mud_uplink", compile::SelectionStyle::sequence);
  const TraceEvent* uplink = first(run, "uplink");
  ASSERT_NE(uplink, nullptr);
  EXPECT_EQ(uplink->verdict, "rejected");
  bool violated = false;
  for (const Finding& f : uplink->findings)
    violated |=
        f.check == "prove-violated" && f.requirements == std::vector<std::string>{"HoldOnUnknown"};
  EXPECT_TRUE(violated) << trace_summary(run);
  EXPECT_TRUE(run.accepted_uplinks.empty());
  EXPECT_EQ(selected(run), std::vector<std::string>{"on_rocks"}) << trace_summary(run);
}

TEST(Manager, AmbiguousUplinkIsRejectedAndTheRunningVersionIsUntouched) {
  ManagerRun run = run_scenario("rejected_uplink", compile::SelectionStyle::sequence);
  const TraceEvent* uplink = first(run, "uplink");
  ASSERT_NE(uplink, nullptr);
  EXPECT_EQ(uplink->verdict, "rejected");
  ASSERT_FALSE(uplink->findings.empty());
  bool overlap = false;
  for (const auto& f : uplink->findings) overlap |= f.check == "guard-overlap";
  EXPECT_TRUE(overlap) << trace_summary(run);
  EXPECT_TRUE(uplink->swapped.empty());
  EXPECT_TRUE(run.accepted_uplinks.empty());
  EXPECT_EQ(selected(run), std::vector<std::string>{"on_dust"});
  EXPECT_EQ(run.status, NodeStatus::success);
}

TEST(Manager, UplinkSwapDoesNotHaltAnUnrelatedRunningAction) {
  // The uplink arrives while on_dust's MoveForward runs. It changes only the navigation
  // selection tree ... which is the running one here, so use the command-line uplink on a
  // mission part that is not running: swap in on_mud while the rover drills.
  Scenario scenario = load_scenario(curiosity() / "scenarios" / "dusty_start.json");
  BehaviorTreeManager manager(curiosity(), std::move(scenario));
  manager.add_uplink(40, "uplinks/on_mud");  // ticks 24..53: Drill runs
  ManagerRun run = manager.run();
  const TraceEvent* uplink = first(run, "uplink");
  ASSERT_NE(uplink, nullptr);
  EXPECT_EQ(uplink->verdict, "accepted");
  EXPECT_EQ(uplink->halted, 0u) << "navigation was not running: nothing is halted";
  EXPECT_EQ(run.status, NodeStatus::success);
  EXPECT_EQ(selected(run), std::vector<std::string>{"on_dust"});
}

TEST(Manager, RefusesToRunAMissionThatFailsTheGate) {
  Scenario scenario = load_scenario(curiosity() / "scenarios" / "dusty_start.json");
  BehaviorTreeManager manager(uabt::testing::mission_dir("msl_curiosity_paper"), scenario);
  EXPECT_THROW(manager.run(), std::runtime_error);
  // The refusal carries the findings, mission-relative, for the caller to print.
  try {
    manager.run();
  } catch (const NotAdmitted& e) {
    ASSERT_FALSE(e.findings.empty());
    EXPECT_EQ(e.findings.front().location.file, "requirements.fret");
  }
}

TEST(Manager, TraceIsJsonLinesWithTheDesignFields) {
  ManagerRun run = run_scenario("rejected_uplink", compile::SelectionStyle::sequence);
  const std::string lines = trace_json_lines(run.trace);
  EXPECT_NE(lines.find("\"event\":\"select\""), std::string::npos);
  EXPECT_NE(lines.find("\"event\":\"uplink\""), std::string::npos);
  EXPECT_NE(lines.find("\"verdict\":\"rejected\""), std::string::npos);
  EXPECT_NE(lines.find("\"event\":\"done\""), std::string::npos);
  std::size_t count = 0;
  for (char c : lines) count += c == '\n';
  EXPECT_EQ(count, run.trace.size());
}

}  // namespace
}  // namespace uabt::manager
