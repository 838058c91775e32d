// Cases read off BehaviorTree.CPP 4.10.0's node code (src/controls, src/decorators,
// Tree::tickRoot): the wake-up re-ticks, halting order, Parallel thresholds, the order in
// which RUNNING children are halted, and what makes a tick throw.
#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

struct Btcpp : ::testing::Test {
  ScriptedWorld world;
  Engine build(const std::string& body, const std::string& more = "") {
    return Engine::build(main_tree(body, more), world);
  }
};

// SequenceWithMemory: a child that was IDLE and succeeded yields; tickOnce re-ticks the root,
// so a Parallel sibling is ticked once per re-tick.
TEST_F(Btcpp, SequenceWithMemoryYieldsAndTheParallelSiblingIsTickedAgain) {
  world.script("Act", {R});
  Engine e =
      build("<Parallel><SequenceWithMemory><A/><B/><C/></SequenceWithMemory><Act/></Parallel>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.joined_events(), "A Act B Act C Act");
  EXPECT_EQ(e.stats().wakeup_reticks, 2u);
  EXPECT_EQ(e.stats().root_ticks, 1u);
}

// The re-tick starts from the root: a reactive condition is checked again in the same tick.
TEST_F(Btcpp, AReactiveConditionSeesTheWakeUpReTick) {
  world.script("Cond", {S, F});
  Engine e = build(
      "<ReactiveSequence><Cond/><Repeat name=\"r\" num_cycles=\"2\"><A/></Repeat>"
      "</ReactiveSequence>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "Cond A Cond");
  EXPECT_EQ(e.status(by_name(e, "r")), I);  // reset by the failing ReactiveSequence
}

// Repeat: a child that had been RUNNING and succeeds is ticked again at once inside the node
// (no wake-up); the next instant success yields.
TEST_F(Btcpp, RepeatRetickesAChildThatWasRunningWithoutAWakeUp) {
  world.script("A", {R, S, S, S});
  Engine e = build("<Repeat num_cycles=\"3\"><A/></Repeat>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.stats().wakeup_reticks, 0u);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.ticks("A"), 4);
  EXPECT_EQ(e.stats().wakeup_reticks, 1u);
}

TEST_F(Btcpp, RetryYieldsAfterEachInstantFailure) {
  world.script("A", {F});
  Engine e = build("<RetryUntilSuccessful num_attempts=\"3\"><A/></RetryUntilSuccessful>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.ticks("A"), 3);
  EXPECT_EQ(e.stats().wakeup_reticks, 2u);
}

// The flag is cleared only when tickOnce tests it, i.e. while the root is RUNNING: one set in
// a tick whose root completed carries into the next tick.
TEST_F(Btcpp, AWakeUpFromACompletedTickCarriesIntoTheNextTick) {
  world.script("C", {S, R});
  world.script("B", {R});
  Engine e = build(
      "<Parallel success_count=\"1\"><SequenceWithMemory><A/><B/></SequenceWithMemory><C/>"
      "</Parallel>");
  EXPECT_EQ(e.tick(), S);  // A yields, C succeeds: done, the flag stays set
  EXPECT_EQ(world.joined_events(), "A C");
  world.clear_events();
  EXPECT_EQ(e.tick(), R);  // the index survived the halt: B; then the carried re-tick
  EXPECT_EQ(world.joined_events(), "B C B C");
}

// Tree::tickRoot resets a completed root, so its pre-conditions are checked again.
TEST_F(Btcpp, ACompletedRootIsIdleAgainAndItsPreconditionsAreRechecked) {
  Engine e = build("<Sequence _successIf=\"done\"><A/></Sequence>");
  e.blackboard().set("done", ScriptValue::of_bool(false));
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(e.status(), I);
  EXPECT_EQ(e.last_result(), S);
  e.blackboard().set("done", ScriptValue::of_bool(true));
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.ticks("A"), 1);
}

// ReactiveSequence: a RUNNING child halts every other child in index order (a later running
// one is halted, earlier completed ones are only reset).
TEST_F(Btcpp, ReactiveSequenceHaltsTheOtherChildrenInIndexOrder) {
  world.script("A", {S, R});
  world.script("C", {R});
  world.script("D", {R});
  Engine e = build("<ReactiveSequence><A/><B/><Parallel><C/><D/></Parallel></ReactiveSequence>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.joined_events(), "A B C D A ~C ~D");
  EXPECT_EQ(world.halts("B"), 0);
}

TEST_F(Btcpp, ParallelHaltsItsRunningChildrenInIndexOrderWhenItFails) {
  world.script("A", {R});
  world.script("B", {R});
  world.script("C", {F});
  Engine e = build("<Parallel><A/><B/><C/></Parallel>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "A B C ~A ~B");
}

// success_count < 0 counts skipped children as successes; a positive one does not, and the
// Parallel then runs on with nothing left to tick.
TEST_F(Btcpp, ParallelCountsSkippedChildrenOnlyForANegativeSuccessCount) {
  Engine neg = build("<Parallel><A _skipIf=\"true\"/><B/></Parallel>");
  EXPECT_EQ(neg.tick(), S);
  Engine pos = build("<Parallel success_count=\"2\"><A _skipIf=\"true\"/><B/></Parallel>");
  EXPECT_EQ(pos.tick(), R);
  EXPECT_EQ(pos.tick(), R);
  EXPECT_EQ(world.ticks("B"), 2);  // once per engine: pos keeps B's SUCCESS, never re-ticks it
}

// Checked after each child: once N - failures < success_count it fails at once.
TEST_F(Btcpp, ParallelFailsAsSoonAsSuccessIsImpossible) {
  world.script("A", {F});
  world.script("C", {R});
  Engine e = build("<Parallel success_count=\"3\" failure_count=\"2\"><A/><B/><C/></Parallel>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "A");
}

TEST_F(Btcpp, ParallelAllWithZeroMaxFailuresAlwaysFails) {
  Engine e = build("<ParallelAll max_failures=\"0\"><A/><B/></ParallelAll>");
  EXPECT_EQ(e.tick(), F);
  Engine skipped = build("<ParallelAll><A _skipIf=\"true\"/><B _skipIf=\"true\"/></ParallelAll>");
  EXPECT_EQ(skipped.tick(), K);
}

TEST_F(Btcpp, ParallelAllTicksEveryChildWithoutAnEarlyStop) {
  world.script("A", {F});
  world.script("B", {R, S});
  Engine e = build("<ParallelAll max_failures=\"1\"><A/><B/><C/></ParallelAll>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "A B C B");
}

// IfThenElse throws on a SKIPPED condition without resetting anything; WhileDoElse returns
// IDLE after resetting its children, and setting IDLE throws.
TEST_F(Btcpp, ASkippedConditionOfIfThenElseOrWhileDoElseThrows) {
  Engine ite = build("<IfThenElse><C _skipIf=\"true\"/><A/><B/></IfThenElse>");
  EXPECT_THROW(ite.tick(), TickException);
  Engine wde = build("<WhileDoElse><C _skipIf=\"true\"/><A/><B/></WhileDoElse>");
  EXPECT_THROW(wde.tick(), TickException);
  EXPECT_EQ(world.joined_events(), "");
}

// Pre-conditions other than _while are checked only while a node is IDLE: a condition that
// WhileDoElse keeps at SUCCESS is ticked without its _skipIf.
TEST_F(Btcpp, SkipIfIsNotCheckedOnAConditionThatIsNotIdle) {
  world.script("A", {R});
  Engine e = build("<WhileDoElse><C _skipIf=\"skip\"/><A/><B/></WhileDoElse>");
  e.blackboard().set("skip", ScriptValue::of_bool(false));
  EXPECT_EQ(e.tick(), R);
  e.blackboard().set("skip", ScriptValue::of_bool(true));
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.joined_events(), "C A C A");
}

// RunOnce ignores a then_skip that does not read as a boolean (getInput's answer unused).
TEST_F(Btcpp, RunOnceWithAnUnreadableThenSkipSkips) {
  Engine e = build("<Sequence><RunOnce then_skip=\"{flag}\"><A/></RunOnce><B/></Sequence>");
  e.blackboard().set("flag", ScriptValue::of_string("maybe"));
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B B");
}

// KeepRunningUntilFailure: SUCCESS → RUNNING without a wake-up (the child runs next tick).
TEST_F(Btcpp, KeepRunningUntilFailureDoesNotYield) {
  Engine e = build("<KeepRunningUntilFailure><A/></KeepRunningUntilFailure>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.ticks("A"), 2);
  EXPECT_EQ(e.stats().wakeup_reticks, 0u);
}

// A script error leaves every status as it was: the next tick resumes at the failing child.
TEST_F(Btcpp, AfterAScriptErrorTheSequenceResumesAtTheFailingChild) {
  Engine e = build("<Sequence><A/><ScriptCondition code=\"x &gt; 1\"/><B/></Sequence>");
  EXPECT_THROW(e.tick(), TickException);
  e.blackboard().set("x", ScriptValue::of_int(2));
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B");
}

}  // namespace
}  // namespace uabt::runtime::testing

namespace uabt::runtime::testing {
namespace {

// Tree::haltTree halts the root, then calls halt on every node: every _onHalted runs (the
// root's twice), also on IDLE nodes; a robot leaf hears halt only while it is RUNNING.
TEST(BtcppHaltTree, EveryOnHaltedRunsAndOnlyRunningLeavesAreHalted) {
  ScriptedWorld world;
  world.script("B", {R});
  Engine e =
      Engine::build(main_tree("<Sequence _onHalted=\"root += 1\"><A _onHalted=\"a += 1\"/>"
                              "<B _onHalted=\"b += 1\"/><C _onHalted=\"c += 1\"/></Sequence>"),
                    world);
  for (const char* key : {"root", "a", "b", "c"}) e.blackboard().set(key, ScriptValue::of_int(0));
  EXPECT_EQ(e.tick(), R);
  e.halt();
  EXPECT_EQ(*e.blackboard().get("root"), ScriptValue::of_int(2));
  EXPECT_EQ(*e.blackboard().get("a"), ScriptValue::of_int(1));
  EXPECT_EQ(*e.blackboard().get("b"), ScriptValue::of_int(2));  // halted running, then visited
  EXPECT_EQ(*e.blackboard().get("c"), ScriptValue::of_int(1));
  EXPECT_EQ(world.halts("B"), 1);
  for (NodeId n = 0; n < e.node_count(); ++n) EXPECT_EQ(e.status(n), I);
}

}  // namespace
}  // namespace uabt::runtime::testing
