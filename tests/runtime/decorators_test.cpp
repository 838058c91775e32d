// Decorators and SubTree (blackboard scopes), against BehaviorTree.CPP 4.x semantics.
#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

struct Decorator : ::testing::Test {
  ScriptedWorld world;
  Engine build(const std::string& body, const std::string& more = "", EngineOptions options = {}) {
    return Engine::build(main_tree(body, more), world, options);
  }
};

TEST_F(Decorator, InverterSwapsCompletedResultsOnly) {
  world.script("A", {S, F, R});
  Engine e = build("<Inverter><A/></Inverter>");
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(e.tick(), R);
}

TEST_F(Decorator, ForceSuccessAndForceFailure) {
  world.script("A", {F, R});
  world.script("B", {S});
  Engine yes = build("<ForceSuccess><A/></ForceSuccess>");
  EXPECT_EQ(yes.tick(), S);
  EXPECT_EQ(yes.tick(), R);  // RUNNING passes through
  Engine no = build("<ForceFailure><B/></ForceFailure>");
  EXPECT_EQ(no.tick(), F);
}

TEST_F(Decorator, RepeatCyclesWithinOneTickThroughTheWakeUpSignal) {
  Engine e = build("<Repeat num_cycles=\"3\"><A/></Repeat>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.ticks("A"), 3);
  // Each instant success yields RUNNING with the wake-up signal; tick() re-ticks the root.
  EXPECT_EQ(e.stats().wakeup_reticks, 2u);
  EXPECT_EQ(e.stats().root_ticks, 1u);
}

TEST_F(Decorator, RepeatResumesAfterRunningAndStopsOnFailure) {
  world.script("A", {R, S, S});
  Engine e = build("<Repeat num_cycles=\"2\"><A/></Repeat>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.ticks("A"), 3);
  world.script("B", {S, F});
  Engine f = build("<Repeat num_cycles=\"5\"><B/></Repeat>");
  EXPECT_EQ(f.tick(), F);
  EXPECT_EQ(world.ticks("B"), 2);
}

TEST_F(Decorator, RepeatForeverOverAnInstantChildStopsTheRunWithAnError) {
  // BT.CPP's tickOnce() never returns here; uabt stops after max_wakeup_reticks.
  EngineOptions options;
  options.max_wakeup_reticks = 5;
  Engine e = build("<Sequence><Repeat name=\"loop\" num_cycles=\"-1\"><A/></Repeat></Sequence>", "",
                   options);
  try {
    e.tick();
    FAIL() << "no error";
  } catch (const TickException& x) {
    EXPECT_EQ(x.error.node, by_name(e, "loop"));
    EXPECT_EQ(x.error.path, "Main/Sequence/Repeat[0]");
    EXPECT_NE(x.error.message.find("tickOnce() would never return"), std::string::npos);
  }
  EXPECT_EQ(world.ticks("A"), 6);
}

TEST_F(Decorator, RepeatCountFromTheBlackboardAndMissingCount) {
  Engine e = build(
      "<Sequence><Script code=\"n := 2\"/><Repeat num_cycles=\"{n}\"><A/></Repeat></Sequence>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.ticks("A"), 2);
  Engine missing = build("<Repeat><B/></Repeat>");  // BT.CPP throws at tick
  EXPECT_THROW(missing.tick(), TickException);
  ASSERT_EQ(missing.errors().size(), 1u);
  EXPECT_NE(missing.errors()[0].message.find("num_cycles"), std::string::npos);
  EXPECT_THROW(build("<Repeat num_cycles=\"three\"><B/></Repeat>"), LoadError);
}

TEST_F(Decorator, RetryUntilSuccessfulMirrorsRepeat) {
  world.script("A", {F, F, S});
  Engine e = build("<RetryUntilSuccessful num_attempts=\"3\"><A/></RetryUntilSuccessful>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.ticks("A"), 3);
  world.script("B", {F});
  Engine v3 = build("<RetryUntilSuccesful num_attempts=\"2\"><B/></RetryUntilSuccesful>");
  EXPECT_EQ(v3.tick(), F);
  EXPECT_EQ(world.ticks("B"), 2);
}

TEST_F(Decorator, RetryCountsAttemptsAcrossTicksAndHaltResetsThem) {
  world.script("A", {F, R, F, R});
  Engine e = build("<RetryUntilSuccessful num_attempts=\"2\"><A/></RetryUntilSuccessful>");
  EXPECT_EQ(e.tick(), R);  // attempt 1 failed, attempt 2 running
  EXPECT_EQ(e.tick(), F);  // attempt 2 failed: no attempts left
  world.script("A", {F, R, S});
  EXPECT_EQ(e.tick(), R);
  e.halt();  // resets the attempt count
  EXPECT_EQ(e.tick(), S);
}

TEST_F(Decorator, KeepRunningUntilFailure) {
  world.script("A", {S, S, F});
  Engine e = build("<KeepRunningUntilFailure><A/></KeepRunningUntilFailure>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), F);
}

TEST_F(Decorator, RunOnceThenSkips) {
  Engine e = build("<Sequence><RunOnce><A/></RunOnce><B/></Sequence>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "A B B");
  world.script("C", {F});
  Engine cached = build("<RunOnce then_skip=\"false\"><C/></RunOnce>");
  EXPECT_EQ(cached.tick(), F);
  EXPECT_EQ(cached.tick(), F);  // the remembered result, C not ticked again
  EXPECT_EQ(world.ticks("C"), 1);
}

using SubTree = Decorator;

TEST_F(SubTree, AutoremapSharesKeysWithTheParentButNotPrivateOnes) {
  Engine e = build(
      "<Sequence><Script code=\"x := 1; mode := 'p'\"/>"
      "<SubTree ID=\"Sub\" _autoremap=\"true\"/>"
      "<ScriptCondition code=\"mode == 'changed' &amp;&amp; x == 5\"/></Sequence>",
      "<BehaviorTree ID=\"Sub\"><Script code=\"mode = 'changed'; x = 5; _mine := 7\"/>"
      "</BehaviorTree>");
  EXPECT_EQ(e.tick(), S) << (e.errors().empty() ? "" : e.errors()[0].message);
  EXPECT_EQ(*e.blackboard().get("x"), ScriptValue::of_int(5));
  EXPECT_EQ(e.blackboard().get("_mine"), nullptr);  // '_' keys stay in the SubTree's scope
  const NodeId call = e.subtree_calls("Sub").at(0);
  const auto local = e.blackboard().entries(e.scope(e.children(call)[0]));
  ASSERT_EQ(local.size(), 1u);
  EXPECT_EQ(local[0].first, "_mine");
}

TEST_F(SubTree, WithoutAutoremapTheScopeIsIsolated) {
  Engine e = build("<Sequence><Script code=\"x := 1\"/><SubTree ID=\"Sub\"/></Sequence>",
                   "<BehaviorTree ID=\"Sub\"><Script code=\"x = 5\"/></BehaviorTree>");
  EXPECT_THROW(e.tick(), TickException);
  ASSERT_EQ(e.errors().size(), 1u);
  EXPECT_NE(e.errors()[0].message.find("'x' does not exist"), std::string::npos);
  EXPECT_EQ(*e.blackboard().get("x"), ScriptValue::of_int(1));
}

TEST_F(SubTree, PortRemappingAndLiteralPorts) {
  Engine e = build(
      "<Sequence><SubTree ID=\"Sub\" target=\"{goal}\" speed=\"3\"/>"
      "<ScriptCondition code=\"goal == 42\"/></Sequence>",
      "<BehaviorTree ID=\"Sub\"><Sequence><ScriptCondition code=\"speed == 3\"/>"
      "<Script code=\"target := 42\"/></Sequence></BehaviorTree>");
  EXPECT_EQ(e.tick(), S) << (e.errors().empty() ? "" : e.errors()[0].message);
  EXPECT_EQ(*e.blackboard().get("goal"), ScriptValue::of_int(42));
  EXPECT_EQ(e.blackboard().get("speed"), nullptr);
}

TEST_F(SubTree, V3SharedBlackboard) {
  bt::Document doc = main_tree(
      "<Sequence><Script code=\"x := 1\"/>"
      "<SubTree ID=\"Sub\" __shared_blackboard=\"true\"/></Sequence>",
      "<BehaviorTree ID=\"Sub\"><Script code=\"x = 2; _y := 3\"/></BehaviorTree>");
  doc.format = 3;
  Engine e = Engine::build(doc, world);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(*e.blackboard().get("x"), ScriptValue::of_int(2));
  EXPECT_NE(e.blackboard().get("_y"), nullptr);  // one blackboard: nothing is private
}

TEST_F(SubTree, V3AttributesInAV4FileAreIgnoredAsBtcppDoes) {
  // BT.CPP 4 takes only attributes that start with a letter as ports: `__shared_blackboard`
  // and `__autoremap` do nothing in a v4 file, so Sub sees no `x` of its caller.
  for (const char* attr : {"__shared_blackboard", "__autoremap"}) {
    Engine e = build(std::string("<Sequence><Script code=\"x := 1\"/><SubTree ID=\"Sub\" ") + attr +
                         "=\"true\"/></Sequence>",
                     "<BehaviorTree ID=\"Sub\"><Script code=\"x = 2\"/></BehaviorTree>");
    try {
      e.tick();
      ADD_FAILURE() << attr << ": the tick did not stop";
    } catch (const TickException& x) {
      EXPECT_NE(x.error.message.find("the blackboard entry 'x' does not exist yet"),
                std::string::npos)
          << x.error.message;
      EXPECT_EQ(x.error.script, "x = 2");
    }
    EXPECT_EQ(*e.blackboard().get("x"), ScriptValue::of_int(1));
  }
}

TEST_F(SubTree, LiteralPortsKeepTheirNumericType) {
  // BT.CPP 4.10 recursivelyCreateSubtree: an integer, else a double, else the string.
  Engine e = build(
      "<SubTree ID=\"Sub\" n=\"5\" big=\"9000000000\" r=\"2.5\" e=\"1e3\" s=\"1;2\" "
      "t=\"true\" w=\"\"/>",
      "<BehaviorTree ID=\"Sub\"><Script code=\"sum := n + r + e\"/></BehaviorTree>");
  EXPECT_EQ(e.tick(), S);
  const NodeId call = e.subtree_calls("Sub").at(0);
  std::map<std::string, ScriptValue> got;
  for (const auto& [key, value] : e.blackboard().entries(e.scope(e.children(call)[0])))
    got[key] = value;
  EXPECT_EQ(got["n"], ScriptValue::of_int(5));
  EXPECT_EQ(got["big"], ScriptValue::of_int(9000000000));
  EXPECT_EQ(got["r"], ScriptValue::of_real(2.5));
  EXPECT_EQ(got["e"], ScriptValue::of_real(1000.0));
  EXPECT_EQ(got["s"], ScriptValue::of_string("1;2"));
  EXPECT_EQ(got["t"], ScriptValue::of_string("true"));
  EXPECT_EQ(got["w"], ScriptValue::of_string(""));
  EXPECT_EQ(got["sum"], ScriptValue::of_real(1007.5));
}

TEST_F(SubTree, RunningSubtreeResumesAndIsHaltedAsOneNode) {
  world.script("Act", {R});
  world.script("Cond", {S, F});
  Engine e = build("<ReactiveSequence><Cond/><SubTree ID=\"Sub\"/></ReactiveSequence>",
                   "<BehaviorTree ID=\"Sub\"><Sequence><Prep/><Act/></Sequence></BehaviorTree>");
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), F);
  EXPECT_EQ(world.joined_events(), "Cond Prep Act Cond ~Act");
}

}  // namespace
}  // namespace uabt::runtime::testing
