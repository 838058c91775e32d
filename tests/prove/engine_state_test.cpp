// Saving and restoring the engine between ticks, and scenario action runs.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

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

// A world whose robot leaves end as a sequence of choices says (0 SUCCESS, 1 FAILURE, and for
// those named Run* 2 RUNNING); choices past it take 0 and are recorded, so that every sequence
// of a tick is enumerated like an odometer, as prove's chooser does.
struct ChoosingWorld : runtime::World {
  std::vector<std::string> names;
  std::vector<std::uint32_t> taken, arity;
  std::size_t pos = 0;
  std::string trace;
  std::function<void(std::size_t)> reached;  // before each choice, with its number

  std::uint32_t bind_leaf(const runtime::LeafBinding& leaf) override {
    names.push_back(leaf.kind);
    return static_cast<std::uint32_t>(names.size() - 1);
  }
  runtime::NodeStatus tick_leaf(const runtime::LeafContext& leaf) override {
    if (reached) reached(pos);
    const std::uint32_t options = names[leaf.handle].rfind("Run", 0) == 0 ? 3 : 2;
    if (pos == taken.size()) taken.push_back(0);
    if (pos >= arity.size()) arity.resize(pos + 1);
    arity[pos] = options;
    const std::uint32_t pick = taken[pos++];
    trace += names[leaf.handle] + std::to_string(pick) + " ";
    return pick == 0   ? runtime::NodeStatus::success
           : pick == 1 ? runtime::NodeStatus::failure
                       : runtime::NodeStatus::running;
  }
  void halt_leaf(const runtime::LeafContext& leaf) override {
    trace += "halt:" + names[leaf.handle] + " ";
  }
  // The next sequence after the one just taken, false when every one was.
  bool advance() {
    taken.resize(pos);
    while (!taken.empty()) {
      if (taken.back() + 1 < arity[taken.size() - 1]) {
        ++taken.back();
        return true;
      }
      taken.pop_back();
    }
    return false;
  }
};

const char* kChoices = R"(<root BTCPP_format="4" main_tree_to_execute="T">
  <BehaviorTree ID="T">
    <Sequence>
      <Fallback>
        <A/>
        <Inverter><B/></Inverter>
        <Sequence>
          <RunC/>
          <Script code="n := n + 1"/>
        </Sequence>
      </Fallback>
      <ForceSuccess>
        <SubTree ID="S" _autoremap="true"/>
      </ForceSuccess>
      <Fallback>
        <D/>
        <RunE/>
      </Fallback>
      <Script code="n := n * 3"/>
    </Sequence>
  </BehaviorTree>
  <BehaviorTree ID="S">
    <Fallback>
      <F/>
      <Script code="n := n + 10"/>
    </Fallback>
  </BehaviorTree>
</root>
)";

// One tick under every sequence of choices: the result, the leaves it ticked and halted, and
// the state it leaves (the engine's key), per sequence.
using Runs = std::map<std::vector<std::uint32_t>, std::string>;

std::string outcome(runtime::Engine& engine, runtime::NodeStatus result, const std::string& trace) {
  std::string key;
  runtime::EngineState::append_key(engine, key);
  return std::to_string(static_cast<int>(result)) + " " + trace + "| " + key;
}

// Each sequence ticked from the start of the tick.
Runs fresh_runs(runtime::Engine& engine, ChoosingWorld& world) {
  const auto before = runtime::EngineState::save(engine);
  Runs runs;
  world.taken.clear();
  do {
    before.restore(engine);
    world.pos = 0;
    world.trace.clear();
    const auto result = engine.tick();
    runs[std::vector<std::uint32_t>(world.taken.begin(), world.taken.begin() + world.pos)] =
        outcome(engine, result, world.trace);
  } while (world.advance());
  before.restore(engine);
  return runs;
}

// Each sequence resumed at the choice it changes, from a checkpoint taken there (or at the
// deepest choice before it where the tick can be resumed).
Runs resumed_runs(runtime::Engine& engine, ChoosingWorld& world, std::size_t* resumed) {
  runtime::TickTrail trail(engine);
  struct Checkpoint {
    std::size_t at, trace;
  };
  std::vector<Checkpoint> checkpoints;
  world.reached = [&](std::size_t at) {
    if ((!checkpoints.empty() && checkpoints.back().at >= at) || !trail.resumable()) return;
    trail.push();
    checkpoints.push_back({at, world.trace.size()});
  };
  Runs runs;
  std::size_t ticks = 0;
  world.taken.clear();
  trail.begin();
  trail.push();  // the state before the tick
  do {
    while (!checkpoints.empty() && checkpoints.back().at >= world.taken.size()) {
      checkpoints.pop_back();
      trail.pop();
    }
    trail.restore();
    runtime::NodeStatus result;
    if (checkpoints.empty()) {
      world.pos = 0;
      world.trace.clear();
      result = engine.tick();
    } else {
      world.pos = checkpoints.back().at;
      world.trace.resize(checkpoints.back().trace);
      result = engine.resume_tick();
      ++*resumed;
    }
    std::string live, sparse;
    runtime::EngineState::append_key(engine, live);
    trail.append_key(sparse);
    EXPECT_EQ(live, sparse);
    runs[std::vector<std::uint32_t>(world.taken.begin(), world.taken.begin() + world.pos)] =
        outcome(engine, result, world.trace);
    // A resumed tick that goes elsewhere than the tick from the start may never let the
    // enumeration end.
    if (++ticks > 1000) {
      ADD_FAILURE() << "the sequences of choices do not end";
      break;
    }
  } while (world.advance());
  while (!checkpoints.empty()) {
    checkpoints.pop_back();
    trail.pop();
  }
  trail.restore();
  world.reached = nullptr;
  return runs;
}

// A tick resumed at a checkpoint goes on exactly as the tick from its start with the same
// choices: same result, same leaves ticked and halted, same state after it (and the trail's
// key of that state is the engine's), from the first state and from every state one tick on
// (where C or E still runs).
TEST(TickTrail, ResumedTicksAreTheTicksFromTheStart) {
  std::vector<Finding> findings;
  auto doc = bt::parse_document(kChoices, "t.xml", findings);
  ASSERT_TRUE(doc);
  ChoosingWorld world;
  auto engine = runtime::Engine::build(*doc, world);
  engine.blackboard().value(engine.blackboard().resolve(runtime::Blackboard::kRootScope, "n")) =
      runtime::ScriptValue::of_int(1);
  std::size_t resumed = 0;
  const Runs first = fresh_runs(engine, world);
  EXPECT_EQ(resumed_runs(engine, world, &resumed), first);
  EXPECT_GE(first.size(), 10u);
  // Every state after the first tick, as its own start.
  const auto start = runtime::EngineState::save(engine);
  std::set<std::string> seen;
  for (const auto& [sequence, _] : first) {
    start.restore(engine);
    world.taken = sequence;
    world.pos = 0;
    world.trace.clear();
    engine.tick();
    std::string key;
    runtime::EngineState::append_key(engine, key);
    if (!seen.insert(key).second) continue;
    const auto next = runtime::EngineState::save(engine);
    const Runs again = fresh_runs(engine, world);
    next.restore(engine);
    EXPECT_EQ(resumed_runs(engine, world, &resumed), again);
  }
  EXPECT_GE(seen.size(), 4u);
  EXPECT_GE(resumed, 20u);  // most sequences were resumed, not ticked from the start
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
