// Saving and restoring the engine between ticks, and scenario action runs.
#include <gtest/gtest.h>

#include "bt/xml_io.hpp"
#include "runtime/engine_state.hpp"
#include "runtime/runner.hpp"

namespace uabt::testing {
namespace {

const char* kTree = R"(<root BTCPP_format="4" main_tree_to_execute="T">
  <BehaviorTree ID="T">
    <Repeat num_cycles="3">
      <Sequence>
        <Script code="n := 1"/>
        <Drill/>
        <Script code="n = n + 1"/>
      </Sequence>
    </Repeat>
  </BehaviorTree>
</root>
)";

runtime::Scenario scenario(const std::string& text) {
  return runtime::parse_scenario(text, "s.json");
}

TEST(EngineState, RestoreThenTickRepeatsTheSameTick) {
  std::vector<Finding> findings;
  auto doc = bt::parse_document(kTree, "t.xml", findings);
  runtime::Runner runner(*doc, scenario(R"({"actions": {"Drill": {"ticks": 2}}})"));
  runner.step();
  const auto saved = runtime::EngineState::save(runner.engine());
  std::string key;
  saved.append_key(key);
  const auto first = runner.engine().tick();
  const auto after = runtime::EngineState::save(runner.engine());
  saved.restore(runner.engine());
  std::string again;
  runtime::EngineState::save(runner.engine()).append_key(again);
  EXPECT_EQ(key, again);
  // The world's own progress is not part of the engine's state: Drill (2 ticks) is restarted
  // by nothing here, so the repeated tick completes it again.
  EXPECT_EQ(runner.engine().tick(), first);
  std::string k1, k2;
  after.append_key(k1);
  runtime::EngineState::save(runner.engine()).append_key(k2);
  EXPECT_NE(k1.size(), 0u);
}

// The key of the live engine and that of its saved state are the same bytes, also when a
// value is longer than the buffer the key is gathered in, and they tell apart texts that differ
// only past it.
TEST(EngineState, KeyOfTheEngineIsTheKeyOfItsSavedState) {
  auto key_after = [](char last) {
    const std::string text = std::string(6000, 'r') + last;
    const std::string tree = R"(<root BTCPP_format="4" main_tree_to_execute="T">
  <BehaviorTree ID="T">
    <Sequence>
      <Script code="log := ')" +
                             text + R"('"/>
      <Drill/>
    </Sequence>
  </BehaviorTree>
</root>
)";
    std::vector<Finding> findings;
    auto doc = bt::parse_document(tree, "t.xml", findings);
    runtime::Runner runner(*doc, scenario(R"({"actions": {"Drill": {"ticks": 2}}})"));
    runner.step();
    std::string live, saved;
    runtime::EngineState::append_key(runner.engine(), live);
    runtime::EngineState::save(runner.engine()).append_key(saved);
    EXPECT_EQ(live, saved);
    EXPECT_NE(live.find(text), std::string::npos);
    return live;
  };
  const std::string a = key_after('a'), b = key_after('b');
  EXPECT_EQ(a.size(), b.size());
  EXPECT_NE(a, b);
}

TEST(ScenarioRuns, EachStartFollowsItsRun) {
  std::vector<Finding> findings;
  auto doc = bt::parse_document(kTree, "t.xml", findings);
  runtime::Runner runner(*doc, scenario(R"({"actions": {"Drill": {"runs": [
      {"ticks": 2, "result": "success", "effects": {"x": 1}},
      {"ticks": 1, "result": "failure", "effects": {"x": 2}}]}}})"));
  const runtime::RunResult r = runner.run();
  // Start 1: 2 ticks then success; Repeat's wake-up re-tick starts the second cycle within
  // tick 2, and start 2 fails at once: Repeat fails in tick 2.
  EXPECT_EQ(r.verdict, "failure");
  EXPECT_EQ(r.ticks, 2u);
  EXPECT_EQ(runner.engine().blackboard().get("x")->to_string(), "2");
}

TEST(ScenarioRuns, ShapeErrorsPointIntoTheFile) {
  try {
    scenario(R"({"actions": {"Drill": {"runs": [{"ticks": 0}]}}})");
    ADD_FAILURE();
  } catch (const runtime::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("/actions/Drill/runs/0/ticks"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace uabt::testing
