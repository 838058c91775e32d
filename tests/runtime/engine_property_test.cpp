// Property test: random trees over the ARCHITECTURE §8 node set, ticked with random leaf results,
// against invariants that BehaviorTree.CPP 4.10's tick semantics guarantee.
#include <random>

#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

// Random XML over the node set; leaves are L0..L5 (scripted), built-ins and scripts over
// the keys `flip` and `skip`, which every tick sets at random.
class TreeGenerator {
 public:
  explicit TreeGenerator(unsigned seed, bool subtrees = true) : rng_(seed), subtrees_(subtrees) {}

  std::string tree(int depth) {
    if (depth == 0 || pick(4) == 0) return leaf();
    const int n = 1 + pick(3);
    auto kids = [&](int count) {
      std::string s;
      for (int i = 0; i < count; ++i) s += tree(depth - 1);
      return s;
    };
    switch (pick(subtrees_ ? 16 : 15)) {
      case 0: return "<Sequence>" + kids(n) + "</Sequence>";
      case 1: return "<SequenceWithMemory>" + kids(n) + "</SequenceWithMemory>";
      case 2: return "<ReactiveSequence>" + kids(n) + "</ReactiveSequence>";
      case 3: return "<Fallback>" + kids(n) + "</Fallback>";
      case 4: return "<ReactiveFallback>" + kids(n) + "</ReactiveFallback>";
      case 5:  // thresholds that the child count can meet (others are tick errors)
        return "<Parallel success_count=\"" + std::to_string(pick(2) ? -1 - pick(n) : 1 + pick(n)) +
               "\" failure_count=\"" + std::to_string(1 + pick(n)) + "\">" + kids(n) +
               "</Parallel>";
      case 6:
        return "<ParallelAll max_failures=\"" + std::to_string(pick(n + 1)) + "\">" + kids(n) +
               "</ParallelAll>";
      case 7: return "<IfThenElse>" + kids(2 + pick(2)) + "</IfThenElse>";
      case 8: return "<WhileDoElse>" + kids(2 + pick(2)) + "</WhileDoElse>";
      case 9: return "<Inverter>" + kids(1) + "</Inverter>";
      case 10: {
        const std::string tag = pick(2) ? "ForceSuccess" : "ForceFailure";
        return "<" + tag + ">" + kids(1) + "</" + tag + ">";
      }
      case 11:
        return "<Repeat num_cycles=\"" + std::to_string(pick(4)) + "\">" + kids(1) + "</Repeat>";
      case 12:
        return "<RetryUntilSuccessful num_attempts=\"" + std::to_string(1 + pick(3)) + "\">" +
               kids(1) + "</RetryUntilSuccessful>";
      case 13: return "<KeepRunningUntilFailure>" + kids(1) + "</KeepRunningUntilFailure>";
      case 14:
        return std::string("<RunOnce then_skip=\"") + (pick(2) ? "true" : "false") + "\">" +
               kids(1) + "</RunOnce>";
      default: return "<SubTree ID=\"Sub\" _autoremap=\"true\"/>";
    }
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  std::string leaf() {
    switch (pick(8)) {
      case 0: return "<AlwaysSuccess/>";
      case 1: return "<AlwaysFailure/>";
      case 2: return "<ScriptCondition code=\"flip\"/>";
      case 3: return "<Script code=\"count += 1\"/>";
      default: {
        std::string l = "<L" + std::to_string(pick(6));
        if (pick(5) == 0) l += " _skipIf=\"skip\"";
        return l + "/>";
      }
    }
  }
  std::mt19937 rng_;
  bool subtrees_;
};

// Checks, per root pass (one executeTick of the root; a tick is one or more passes): a node
// is ticked at most 2^k times, k its Repeat/RetryUntilSuccessful ancestors (they re-tick a
// child that was RUNNING and succeeded/failed once more, BT.CPP's loop); everything else at
// most once.
class InvariantObserver : public Observer {
 public:
  explicit InvariantObserver(const Engine& e)
      : engine_(e), ticks_(e.node_count(), 0), last_(e.node_count(), NodeStatus::idle) {}
  void on_status_change(NodeId, NodeStatus, NodeStatus) override {}
  void on_node_ticked(NodeId node, NodeStatus result) override {
    last_[node] = result;
    ++ticks_[node];
    if (node != engine_.root()) return;
    for (NodeId n = 0; n < ticks_.size(); ++n) {
      if (ticks_[n] > bound(n))
        violations.push_back(engine_.instance_path(n) + " ticked " + std::to_string(ticks_[n]) +
                             " times in one root pass");
      ticks_[n] = 0;
    }
  }
  void reset_pass() { std::fill(ticks_.begin(), ticks_.end(), 0); }
  NodeStatus last_result(NodeId node) const { return last_[node]; }
  std::vector<std::string> violations;

 private:
  int bound(NodeId n) const {
    int b = 1;
    for (NodeId p = engine_.info(n).parent; p != kNoNode; p = engine_.info(p).parent) {
      const std::string& k = engine_.info(p).kind;
      if (k == "Repeat" || k == "RetryUntilSuccessful") b *= 2;
    }
    return b;
  }
  const Engine& engine_;
  std::vector<int> ticks_;
  std::vector<NodeStatus> last_;
};

// A RUNNING node's parent is RUNNING, unless the node returned SKIPPED last (BT.CPP keeps
// the RUNNING a control or decorator sets before ticking its child, and SequenceWithMemory's
// FAILURE resets only the failed child and later ones). A completed root is IDLE.
void check_statuses(const Engine& e, const InvariantObserver& o,
                    std::vector<std::string>& violations) {
  for (NodeId n = 0; n < e.node_count(); ++n) {
    const NodeId parent = e.info(n).parent;
    if (e.status(n) == NodeStatus::running && parent != kNoNode &&
        e.status(parent) != NodeStatus::running && o.last_result(n) != NodeStatus::skipped)
      violations.push_back("RUNNING under a non-RUNNING parent: " + e.instance_path(n));
  }
  if (is_completed(e.last_result()) && e.status() != NodeStatus::idle)
    violations.push_back("completed root not reset to IDLE");
}

// A world that also checks halts: only a RUNNING leaf is halted, once.
struct CheckingWorld : ScriptedWorld {
  const Engine* engine = nullptr;
  std::vector<std::string>* violations = nullptr;
  void halt_leaf(const LeafContext& context) override {
    if (engine && engine->status(context.node) != NodeStatus::running)
      violations->push_back("halt of a leaf that is not RUNNING: " +
                            engine->instance_path(context.node));
    ScriptedWorld::halt_leaf(context);
  }
};

TEST(EngineProperty, RandomTreesKeepBtcppInvariants) {
  constexpr int kTrees = 400, kTicks = 25;
  int errors = 0, completed_runs = 0;
  for (int t = 0; t < kTrees; ++t) {
    TreeGenerator gen(static_cast<unsigned>(t));
    const std::string body = gen.tree(4);
    const std::string sub =
        "<BehaviorTree ID=\"Sub\">" + TreeGenerator(1000u + t, false).tree(2) + "</BehaviorTree>";
    SCOPED_TRACE(body + sub);
    std::mt19937 rng(static_cast<unsigned>(t));
    std::vector<std::string> violations;
    CheckingWorld world;
    world.violations = &violations;
    for (int l = 0; l < 6; ++l) {
      std::vector<NodeStatus> script;
      for (int k = 0; k < 8; ++k) script.push_back(std::array{R, S, F}[rng() % 3]);
      world.script("L" + std::to_string(l), script);
    }
    Engine e = Engine::build(main_tree(body, sub), world);
    world.engine = &e;
    InvariantObserver observer(e);
    e.add_observer(&observer);
    e.blackboard().set("count", ScriptValue::of_int(0));
    for (int tick = 0; tick < kTicks; ++tick) {
      e.blackboard().set("flip", ScriptValue::of_bool(rng() % 2));
      e.blackboard().set("skip", ScriptValue::of_bool(rng() % 4 == 0));
      try {
        if (is_completed(e.tick())) ++completed_runs;
      } catch (const TickException& x) {
        // Only a skipped IfThenElse/WhileDoElse condition can throw in these trees.
        if (x.error.message.find("condition was skipped") == std::string::npos)
          violations.push_back("unexpected tick error: " + x.error.message);
        ++errors;
        observer.reset_pass();
        break;
      }
      check_statuses(e, observer, violations);
    }
    e.halt();
    for (NodeId n = 0; n < e.node_count(); ++n)
      if (e.status(n) != NodeStatus::idle)
        violations.push_back("not IDLE after halt: " + e.instance_path(n));
    violations.insert(violations.end(), observer.violations.begin(), observer.violations.end());
    ASSERT_TRUE(violations.empty()) << violations.front();
  }
  // The generator reaches both outcomes (a property over trees that never run is vacuous).
  EXPECT_GT(completed_runs, kTrees);
  EXPECT_GT(errors, 0);
}

// Same tree, same leaf results: the same events, twice (no hidden state between engines).
TEST(EngineProperty, TickingIsDeterministic) {
  for (int t = 0; t < 50; ++t) {
    const std::string body = TreeGenerator(static_cast<unsigned>(t)).tree(4);
    const std::string sub = "<BehaviorTree ID=\"Sub\"><L1/></BehaviorTree>";
    std::string runs[2];
    for (std::string& run : runs) {
      ScriptedWorld world;
      for (int l = 0; l < 6; ++l) world.script("L" + std::to_string(l), {R, S, F, R, F, S});
      Engine e = Engine::build(main_tree(body, sub), world);
      e.blackboard().set("count", ScriptValue::of_int(0));
      e.blackboard().set("skip", ScriptValue::of_bool(false));
      for (int tick = 0; tick < 10; ++tick) {
        e.blackboard().set("flip", ScriptValue::of_bool(tick % 3 == 0));
        try {
          run += status_name(e.tick());
        } catch (const TickException& x) {
          run += x.error.message;
          break;
        }
      }
      run += world.joined_events();
    }
    EXPECT_EQ(runs[0], runs[1]) << body;
  }
}

}  // namespace
}  // namespace uabt::runtime::testing
