// Control nodes, against BehaviorTree.CPP 4.x semantics (shared/notes/BTCPP.md).
#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

struct Fixture : ::testing::Test {
  ScriptedWorld world;
  Engine build(const std::string& body, EngineOptions options = {}) {
    return Engine::build(main_tree(body), world, options);
  }
};

using Sequence = Fixture;

TEST_F(Sequence, ResumesAtTheRunningChildWithoutRetickingEarlierOnes) {
  world.script("B", {R, R, S});
  Engine e = build("<Sequence><A/><B/><C/></Sequence>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B B B C");
  // Completed: every child reset to IDLE, and the next run starts over.
  for (NodeId c : e.children(e.root())) EXPECT_EQ(e.status(c), I);
  world.clear_events();
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B C");
}

TEST_F(Sequence, FailureResetsToTheFirstChild) {
  world.script("B", {F, S});
  Engine e = build("<Sequence><A/><B/><C/></Sequence>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B A B C");
}

TEST_F(Sequence, HaltCallsTheRunningChildsHaltOnceAndRestarts) {
  world.script("B", {R});
  Engine e = build("<Sequence><A/><B/></Sequence>");
  EXPECT_EQ(e.tick(), R);
  e.halt();
  EXPECT_EQ(world.halts("B"), 1);
  EXPECT_EQ(world.halts("A"), 0);  // completed children are reset, not halted
  EXPECT_EQ(e.status(), I);
  e.tick();
  EXPECT_EQ(world.joined_events(), "A B ~B A B");
}

TEST_F(Sequence, AllChildrenSkippedMeansSkipped) {
  world.script("A", {S});
  Engine e = build("<Sequence><RunOnce><A/></RunOnce><RunOnce><B/></RunOnce></Sequence>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(e.tick(), K);
  // A skipped node keeps its status (BT.CPP executeTick): the RunOnce nodes stay IDLE.
  for (NodeId c : e.children(e.root())) EXPECT_EQ(e.status(c), I);
}

using SequenceWithMemory = Fixture;

TEST_F(SequenceWithMemory, KeepsItsIndexOnFailure) {
  world.script("B", {F, S});
  Engine e = build("<SequenceWithMemory><A/><B/><C/></SequenceWithMemory>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B B C");
}

TEST_F(SequenceWithMemory, V3SpellingSequenceStarAndHaltKeepsTheIndex) {
  world.script("B", {R});
  Engine e = build("<SequenceStar><A/><B/></SequenceStar>");
  EXPECT_EQ(e.tick(), R);
  e.halt();  // BT.CPP's SequenceWithMemory::halt leaves the index alone
  e.tick();
  EXPECT_EQ(world.joined_events(), "A B ~B B");
}

using ReactiveSequence = Fixture;

TEST_F(ReactiveSequence, RetickesChildZeroAndHaltsTheRunningChildWhenItFails) {
  world.script("Cond", {S, S, F});
  world.script("Act", {R});
  Engine e = build("<ReactiveSequence><Cond/><Act/></ReactiveSequence>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "Cond Act Cond Act Cond ~Act");
  EXPECT_EQ(world.halts("Act"), 1);
}

TEST_F(ReactiveSequence, ARunningChildHaltsTheOthers) {
  world.script("A", {S, R});
  world.script("B", {R});
  Engine e = build("<ReactiveSequence><A/><B/></ReactiveSequence>");
  EXPECT_EQ(e.tick(), R);  // A succeeds, B runs
  EXPECT_EQ(e.tick(), R);  // A runs: B is halted
  EXPECT_EQ(world.joined_events(), "A B A ~B");
}

using Fallback = Fixture;

TEST_F(Fallback, MirrorsSequence) {
  world.script("A", {F});
  world.script("B", {R, R, S});
  Engine e = build("<Fallback><A/><B/><C/></Fallback>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B B B");
  world.script("B", {F});
  world.script("C", {F});
  world.clear_events();
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "A B C");
}

using ReactiveFallback = Fixture;

TEST_F(ReactiveFallback, AHigherChildThatSucceedsPreemptsTheRunningOne) {
  world.script("Cond", {F, F, S});
  world.script("Act", {R});
  Engine e = build("<ReactiveFallback><Cond/><Act/></ReactiveFallback>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "Cond Act Cond Act Cond ~Act");
}

using Parallel = Fixture;

TEST_F(Parallel, SucceedsWhenSuccessCountIsReached) {
  world.script("B", {R, R, S});
  world.script("C", {R, F});
  Engine e = build("<Parallel success_count=\"2\" failure_count=\"2\"><A/><B/><C/></Parallel>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);  // A done (not ticked again), C failed: 1 success, 1 failure
  EXPECT_EQ(e.tick(), S);  // B succeeds: 2 successes
  EXPECT_EQ(world.joined_events(), "A B C B C B");
}

TEST_F(Parallel, DefaultsAllMustSucceedAndOneFailureFailsHaltingTheRest) {
  world.script("A", {R});
  world.script("B", {F});
  Engine e = build("<Parallel><A/><B/></Parallel>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "A B ~A");
}

TEST_F(Parallel, NegativeThresholdsCountFromTheNumberOfChildren) {
  // success_count -2 with 3 children: 3 + 1 - 2 = 2 successes needed.
  world.script("C", {R});
  Engine e = build("<Parallel success_count=\"-2\"><A/><B/><C/></Parallel>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B");  // checked after each child: C never ticked
}

TEST_F(Parallel, FailsWhenSuccessBecomesImpossible) {
  world.script("A", {F});
  world.script("B", {R});
  Engine e = build("<Parallel success_count=\"2\" failure_count=\"2\"><A/><B/></Parallel>");
  EXPECT_EQ(e.tick(), F);  // 2 children, 1 failed: 2 successes impossible
  EXPECT_EQ(world.joined_events(), "A");
}

TEST_F(Parallel, ImpossibleThresholdIsATickError) {
  Engine e = build("<Parallel success_count=\"4\"><A/><B/></Parallel>");
  EXPECT_THROW(e.tick(), TickException);
  ASSERT_EQ(e.errors().size(), 1u);
  EXPECT_NE(e.errors()[0].message.find("can never succeed"), std::string::npos);
  EXPECT_NE(e.errors()[0].message.find("test.xml:1:"), std::string::npos);
}

TEST_F(Parallel, ThresholdFromTheBlackboard) {
  world.script("B", {R});
  Engine e = build(
      "<Sequence><Script code=\"need := 1\"/>"
      "<Parallel success_count=\"{need}\"><A/><B/></Parallel></Sequence>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A");
}

using ParallelAll = Fixture;

TEST_F(ParallelAll, WaitsForAllThenCountsFailures) {
  world.script("B", {R, F});
  Engine e = build("<ParallelAll><A/><B/><C/></ParallelAll>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), F);  // max_failures defaults to 1
  EXPECT_EQ(world.joined_events(), "A B C B");
  world.script("B", {R, F});
  Engine tolerant = build("<ParallelAll max_failures=\"2\"><A/><B/><C/></ParallelAll>");
  EXPECT_EQ(tolerant.tick(), R);
  EXPECT_EQ(tolerant.tick(), S);
}

using IfThenElse = Fixture;

TEST_F(IfThenElse, ConditionIsNotRecheckedWhileTheBranchRuns) {
  world.script("Then", {R, R, S});
  Engine e = build("<IfThenElse><Cond/><Then/><Else/></IfThenElse>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "Cond Then Then Then");
}

TEST_F(IfThenElse, ElseBranchAndMissingElse) {
  world.script("Cond", {F});
  world.script("Else", {F});
  Engine e = build("<IfThenElse><Cond/><Then/><Else/></IfThenElse>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "Cond Else");
  Engine two = build("<IfThenElse><Cond/><Then/></IfThenElse>");
  EXPECT_EQ(two.tick(), F);
  Engine one = build("<IfThenElse><Cond/></IfThenElse>");  // BT.CPP checks this at tick
  EXPECT_THROW(one.tick(), TickException);
  ASSERT_EQ(one.errors().size(), 1u);
  EXPECT_NE(one.errors()[0].message.find("2 or 3 children"), std::string::npos);
}

using WhileDoElse = Fixture;

TEST_F(WhileDoElse, RechecksTheConditionAndHaltsTheOtherBranch) {
  world.script("Cond", {S, F, S});
  world.script("Do", {R});
  world.script("Else", {R});
  Engine e = build("<WhileDoElse><Cond/><Do/><Else/></WhileDoElse>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(world.joined_events(), "Cond Do Cond ~Do Else Cond ~Else Do");
  world.script("Cond", {F});
  Engine two = build("<WhileDoElse><Cond/><Do/></WhileDoElse>");
  EXPECT_EQ(two.tick(), F);
}

using Halt = Fixture;

TEST_F(Halt, PropagatesToEveryRunningLeafExactlyOnce) {
  world.script("Cond", {S, F});
  world.script("B", {R});
  world.script("C", {R});
  Engine e = build(
      "<ReactiveSequence><Cond/>"
      "<Sequence><A/><Parallel><B/><C/></Parallel></Sequence></ReactiveSequence>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.halts("B"), 1);
  EXPECT_EQ(world.halts("C"), 1);
  EXPECT_EQ(world.halts("A"), 0);
  EXPECT_EQ(e.last_result(), F);
  for (NodeId n = 0; n < e.node_count(); ++n) EXPECT_EQ(e.status(n), I) << e.instance_path(n);
  e.halt();  // nothing RUNNING any more: no second halt
  EXPECT_EQ(world.halts("B"), 1);
}

}  // namespace
}  // namespace uabt::runtime::testing
