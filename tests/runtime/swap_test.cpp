// Hot swap: replacing one tree's definition between two ticks.
#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

bt::TreeDef tree_def(const std::string& id, const std::string& body) {
  bt::Document doc = parse_xml("<root BTCPP_format=\"4\"><BehaviorTree ID=\"" + id + "\">" + body +
                               "</BehaviorTree></root>");
  return doc.trees.at(0);
}

struct Swap : ::testing::Test {
  ScriptedWorld world;
  // Drive runs for ever beside the navigation subtree.
  Engine build(const std::string& nav_body) {
    return Engine::build(main_tree("<Parallel success_count=\"-1\"><Drive/>"
                                   "<SubTree ID=\"nav\" _autoremap=\"true\"/></Parallel>",
                                   "<BehaviorTree ID=\"nav\">" + nav_body + "</BehaviorTree>"),
                         world);
  }
};

TEST_F(Swap, IdleSubtreeIsSwappedAndTheUnrelatedRunningActionKeepsRunning) {
  world.script("Drive", {R});
  Engine e = build("<OldStep/>");
  EXPECT_EQ(e.tick(), R);  // OldStep done, Drive running
  const NodeId drive = e.find_path("Main/Parallel/Drive[0]");
  ASSERT_NE(drive, kNoNode);
  EXPECT_EQ(e.status(drive), R);

  RecordingObserver rec(e);
  e.add_observer(&rec);
  const SwapResult r = e.replace_tree("nav", tree_def("nav", "<Sequence><NewStep/></Sequence>"),
                                      SwapPolicy::refuse_if_running);
  EXPECT_EQ(r.outcome, SwapResult::Outcome::swapped);
  EXPECT_EQ(r.swapped, 1u);
  EXPECT_EQ(r.halted, 0u);
  EXPECT_TRUE(rec.changes.empty());  // nothing halted or reset by the swap
  EXPECT_EQ(e.status(drive), R);

  world.clear_events();
  EXPECT_EQ(e.tick(), R);
  // The Parallel remembers that its nav child completed, so the new tree is not run yet;
  // Drive simply goes on.
  EXPECT_EQ(world.joined_events(), "Drive");
  EXPECT_EQ(world.halts("Drive"), 0);
  EXPECT_EQ(e.stats().swaps, 1u);
  const NodeId call = e.subtree_calls("nav").at(0);
  EXPECT_EQ(e.info(e.children(call)[0]).kind, "Sequence");
}

TEST_F(Swap, NewDefinitionRunsTheNextTimeTheSubtreeIsTicked) {
  world.script("Step", {R});
  Engine e = Engine::build(main_tree("<Sequence><SubTree ID=\"nav\"/><Done/></Sequence>",
                                     "<BehaviorTree ID=\"nav\"><OldStep/></BehaviorTree>"),
                           world);
  EXPECT_EQ(e.tick(), S);
  e.replace_tree("nav", tree_def("nav", "<Step/>"), SwapPolicy::refuse_if_running);
  world.clear_events();
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.joined_events(), "Step");
}

TEST_F(Swap, RunningInstanceRefusedChangesNothing) {
  world.script("Slow", {R});
  world.script("Drive", {R});
  Engine e = build("<Slow/>");
  EXPECT_EQ(e.tick(), R);
  const std::size_t nodes = e.node_count();
  const SwapResult r =
      e.replace_tree("nav", tree_def("nav", "<Fast/>"), SwapPolicy::refuse_if_running);
  EXPECT_EQ(r.outcome, SwapResult::Outcome::refused);
  EXPECT_EQ(e.node_count(), nodes);
  world.clear_events();
  e.tick();
  EXPECT_EQ(world.joined_events(), "Drive Slow");
}

TEST_F(Swap, HaltThenSwapHaltsOnlyTheInstance) {
  world.script("Slow", {R});
  world.script("Drive", {R});
  Engine e = build("<Sequence><Prep/><Slow/></Sequence>");
  EXPECT_EQ(e.tick(), R);
  const SwapResult r =
      e.replace_tree("nav", tree_def("nav", "<Fast/>"), SwapPolicy::halt_then_swap);
  EXPECT_EQ(r.outcome, SwapResult::Outcome::swapped);
  EXPECT_EQ(r.halted, 1u);
  EXPECT_EQ(world.halts("Slow"), 1);
  EXPECT_EQ(world.halts("Drive"), 0);
  world.clear_events();
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.joined_events(), "Drive Fast");
}

TEST_F(Swap, DeferredSwapWaitsUntilTheInstanceIsIdle) {
  world.script("Slow", {R, R, S});
  world.script("Drive", {R});
  Engine e = build("<Slow/>");
  EXPECT_EQ(e.tick(), R);
  const SwapResult r =
      e.replace_tree("nav", tree_def("nav", "<Fast/>"), SwapPolicy::defer_until_idle);
  EXPECT_EQ(r.outcome, SwapResult::Outcome::deferred);
  EXPECT_EQ(e.pending_swaps(), 1u);
  EXPECT_EQ(e.tick(), R);  // Slow still running: old tree
  EXPECT_EQ(e.pending_swaps(), 1u);
  EXPECT_EQ(e.tick(), R);  // Slow completes: swapped at the end of this tick
  EXPECT_EQ(e.pending_swaps(), 0u);
  EXPECT_EQ(world.halts("Slow"), 0);
  EXPECT_EQ(e.info(e.children(e.subtree_calls("nav").at(0))[0]).kind, "Fast");
}

TEST_F(Swap, InvalidDefinitionIsRejectedAndNothingChanges) {
  Engine e = build("<Step/>");
  e.tick();
  const std::size_t nodes = e.node_count();
  const std::size_t slots = e.blackboard().slot_count();
  EXPECT_THROW(e.replace_tree("nav", tree_def("nav", "<SubTree ID=\"missing\"/>"),
                              SwapPolicy::halt_then_swap),
               LoadError);
  EXPECT_THROW(
      e.replace_tree("nav", tree_def("nav", "<SubTree ID=\"Main\"/>"), SwapPolicy::halt_then_swap),
      LoadError);  // a cycle through the caller
  EXPECT_THROW(e.replace_tree("nav", tree_def("nav", "<Script code=\"x := (\"/>"),
                              SwapPolicy::halt_then_swap),
               LoadError);
  EXPECT_EQ(e.node_count(), nodes);
  EXPECT_EQ(e.blackboard().slot_count(), slots);
  EXPECT_EQ(e.stats().swaps, 0u);
}

TEST_F(Swap, NewTreesAreDefinedFirstAndBlackboardEntriesSurvive) {
  bt::Document doc =
      main_tree("<Sequence><Script code=\"_count := 0\"/><SubTree ID=\"nav\"/></Sequence>",
                "<BehaviorTree ID=\"nav\"><Script code=\"_n := 1\"/></BehaviorTree>");
  doc.format = 3;  // the shared blackboard is v3's
  Engine e = Engine::build(doc, world);
  EXPECT_EQ(e.tick(), S);
  EXPECT_FALSE(e.has_tree("on_mud"));
  e.define_tree(tree_def("on_mud", "<Script code=\"_n += 10\"/>"));
  EXPECT_TRUE(e.has_tree("on_mud"));
  // The new nav calls on_mud with the same blackboard (shared) so _n carries over.
  e.replace_tree("nav", tree_def("nav", "<SubTree ID=\"on_mud\" __shared_blackboard=\"true\"/>"),
                 SwapPolicy::refuse_if_running);
  EXPECT_EQ(e.tick(), S);
  const NodeId call = e.subtree_calls("nav").at(0);
  const auto entries = e.blackboard().entries(e.scope(e.children(call)[0]));
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].second, ScriptValue::of_int(11));
}

TEST_F(Swap, TheMainTreeCanBeReplaced) {
  world.script("Old", {R});
  Engine e = Engine::build(main_tree("<Old/>"), world);
  EXPECT_EQ(e.tick(), R);
  e.replace_tree("Main", tree_def("Main", "<New/>"), SwapPolicy::halt_then_swap);
  EXPECT_EQ(world.halts("Old"), 1);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "Old ~Old New");
}

}  // namespace
}  // namespace uabt::runtime::testing
