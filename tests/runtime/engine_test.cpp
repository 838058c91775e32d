// Engine-level behaviour: load errors, leaves, scripts at tick, observers, paths, statistics.
#include <chrono>

#include "runtime/selection.hpp"
#include "runtime_test_support.hpp"

namespace uabt::runtime::testing {
namespace {

struct EngineTest : ::testing::Test {
  ScriptedWorld world;
  Engine build(const std::string& body, const std::string& more = "") {
    return Engine::build(main_tree(body, more), world);
  }
  std::string load_error(const std::string& body, const std::string& more = "") {
    try {
      build(body, more);
    } catch (const LoadError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(EngineTest, AlwaysSuccessAlwaysFailureAndScript) {
  Engine e = build(
      "<Sequence><AlwaysSuccess/><Script code=\"n := 1\"/>"
      "<Fallback><AlwaysFailure/><Script code=\"n += 1\"/></Fallback></Sequence>");
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(*e.blackboard().get("n"), ScriptValue::of_int(2));
  EXPECT_EQ(world.events.size(), 0u);  // built-ins never reach the World
}

TEST_F(EngineTest, ScriptConditionReadsTheBlackboardEveryTick) {
  Engine e = build("<ScriptCondition code=\"terrain == 'rocks' &amp;&amp; battery &lt; 20\"/>");
  e.blackboard().set("terrain", ScriptValue::of_string("rocks"));
  e.blackboard().set("battery", ScriptValue::of_int(10));
  EXPECT_EQ(e.tick(), S);
  e.blackboard().set("battery", ScriptValue::of_int(50));
  EXPECT_EQ(e.tick(), F);
  EXPECT_TRUE(e.errors().empty());
}

TEST_F(EngineTest, UndefinedScriptKeyStopsTheTickAsBtcppThrows) {
  Engine e =
      build("<Fallback><ScriptCondition name=\"low\" code=\"battery &lt; 20\"/><A/></Fallback>");
  try {
    e.tick();
    FAIL() << "no TickException";
  } catch (const TickException& x) {
    EXPECT_EQ(x.error.path, "Main/Fallback/ScriptCondition[0]");
    EXPECT_EQ(x.error.script, "battery < 20");
  }
  EXPECT_EQ(world.ticks("A"), 0);  // the Fallback did not go on
  // Nothing was halted or reset: the Fallback is still RUNNING at its first child.
  EXPECT_EQ(e.status(), R);
  ASSERT_EQ(e.errors().size(), 1u);
  const TickError& err = e.errors()[0];
  EXPECT_EQ(err.tick, 1u);
  EXPECT_EQ(e.info(err.node).name, "low");
  EXPECT_NE(err.message.find("test.xml:1:"), std::string::npos) << err.message;
  EXPECT_NE(err.message.find("ScriptCondition 'low'"), std::string::npos) << err.message;
  EXPECT_NE(err.message.find("undefined blackboard key 'battery'"), std::string::npos);
  EXPECT_NE(err.message.find("`battery < 20`"), std::string::npos);
  EXPECT_EQ(e.stats().errors, 1u);
}

TEST_F(EngineTest, ScriptConditionNeedsABooleanResult) {
  Engine e = build("<ScriptCondition code=\"'rocks'\"/>");
  EXPECT_THROW(e.tick(), TickException);
  ASSERT_EQ(e.errors().size(), 1u);
  EXPECT_NE(e.errors()[0].message.find("not a boolean"), std::string::npos);
}

TEST_F(EngineTest, LoadErrorsNameTheElement) {
  EXPECT_NE(load_error("<Script code=\"a := \"/>").find("test.xml:1:"), std::string::npos);
  EXPECT_NE(load_error("<Script code=\"a := \"/>").find("does not parse"), std::string::npos);
  EXPECT_NE(load_error("<SubTree ID=\"Nowhere\"/>").find("names no <BehaviorTree>"),
            std::string::npos);
  EXPECT_NE(load_error("<SubTree ID=\"Loop\"/>",
                       "<BehaviorTree ID=\"Loop\"><SubTree ID=\"Main\"/></BehaviorTree>")
                .find("recursive SubTree: Main -> Loop -> Main"),
            std::string::npos);
  EXPECT_NE(load_error("<Adaptable ID=\"navigation\"/>").find("compile the mission first"),
            std::string::npos);
  EXPECT_NE(load_error("<Delay delay_msec=\"10\"><A/></Delay>").find("not supported"),
            std::string::npos);
  EXPECT_NE(load_error("<Sequence name=\"s\" speed=\"1\"><A/></Sequence>").find("no port named"),
            std::string::npos);
  EXPECT_NE(load_error("<Inverter><A/><B/></Inverter>").find("exactly one child"),
            std::string::npos);
  EXPECT_NE(load_error("<Move><A/></Move>").find("not a control or decorator"), std::string::npos);
  EXPECT_NE(load_error("<A _skipIf=\"(\"/>").find("A _skipIf: the script `(` does not parse"),
            std::string::npos);
  EXPECT_NE(load_error("<RunOnce then_skip=\"maybe\"><A/></RunOnce>").find("not a boolean"),
            std::string::npos);
}

// The node catalogue has every built-in of BT.CPP 4.10: one the runtime does not run is
// refused as such, not as a robot node with children.
TEST_F(EngineTest, BtCpp410BuiltInsItDoesNotRunAreRefusedByName) {
  EXPECT_EQ(load_error("<AsyncSequence><A/></AsyncSequence>"),
            "test.xml:1:76: BehaviorTree.CPP's AsyncSequence is not supported by the uabt runtime");
  EXPECT_NE(load_error("<AsyncFallback><A/></AsyncFallback>").find("not supported"),
            std::string::npos);
  // Parallel still reads BT.CPP 3.8's port names.
  EXPECT_EQ(load_error("<Parallel success_threshold=\"1\"><A/></Parallel>"), "");
  EXPECT_NE(load_error("<Parallel threshold=\"1\"><A/></Parallel>").find("no port named"),
            std::string::npos);
}

TEST_F(EngineTest, PreAndPostConditionScripts) {
  Engine e = build(
      "<Sequence><A _skipIf=\"!go\"/><B _successIf=\"true\"/>"
      "<C _onSuccess=\"count += 1\" _post=\"last := 'C'\"/>"
      "<D _failureIf=\"count &gt; 5\" _onFailure=\"count = 100\"/></Sequence>");
  e.blackboard().set("go", ScriptValue::of_bool(false));
  e.blackboard().set("count", ScriptValue::of_int(0));
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(world.joined_events(), "C D");  // A skipped, B succeeded without a tick
  EXPECT_EQ(*e.blackboard().get("count"), ScriptValue::of_int(1));
  EXPECT_EQ(*e.blackboard().get("last"), ScriptValue::of_string("C"));
  e.blackboard().set("count", ScriptValue::of_int(6));
  world.clear_events();
  EXPECT_EQ(e.tick(), F);  // C: count 7; D: _failureIf holds, then _onFailure
  EXPECT_EQ(world.joined_events(), "C");
  EXPECT_EQ(*e.blackboard().get("count"), ScriptValue::of_int(100));
  EXPECT_TRUE(e.errors().empty());
}

TEST_F(EngineTest, WhileConditionHaltsARunningNode) {
  world.script("Act", {R});
  Engine e = build("<Act _while=\"go\" _onHalted=\"halted := true\"/>");
  e.blackboard().set("go", ScriptValue::of_bool(true));
  EXPECT_EQ(e.tick(), R);
  e.blackboard().set("go", ScriptValue::of_bool(false));
  EXPECT_EQ(e.tick(), K);
  EXPECT_EQ(e.status(), I);
  EXPECT_EQ(*e.blackboard().get("halted"), ScriptValue::of_real(1.0));  // true is 1.0
  EXPECT_EQ(e.tick(), K);  // not started while the condition is false
  EXPECT_EQ(world.joined_events(), "Act ~Act");
  e.blackboard().set("go", ScriptValue::of_string("maybe"));
  EXPECT_THROW(e.tick(), TickException);
  ASSERT_EQ(e.errors().size(), 1u);
  EXPECT_NE(e.errors()[0].message.find("_while: the result of `go` is not a boolean"),
            std::string::npos);
}

TEST_F(EngineTest, ExplicitSyntaxAndLeafPorts) {
  struct PortWorld : ScriptedWorld {
    std::vector<std::string> seen;
    std::uint32_t bind_leaf(const LeafBinding& leaf) override {
      seen.push_back(leaf.kind + "/" + leaf.declared_family);
      for (const LeafPort& p : leaf.ports)
        seen.push_back(p.name + (p.from_blackboard() ? "={" + leaf.blackboard.key(p.slot) + "}"
                                                     : "=" + p.literal));
      return ScriptedWorld::bind_leaf(leaf);
    }
  } ports;
  Engine e = Engine::build(main_tree("<Sequence><Action ID=\"Move\" speed=\"2\"/>"
                                     "<Condition ID=\"IsArm\" function=\"{f}\"/></Sequence>"),
                           ports);
  EXPECT_EQ(ports.seen, (std::vector<std::string>{"Move/Action", "speed=2", "IsArm/Condition",
                                                  "function={f}"}));
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(ports.joined_events(), "Move IsArm");
}

TEST_F(EngineTest, ObserverSeesStatusChangesInBtcppOrder) {
  world.script("B", {R, S});
  Engine e = build("<Sequence name=\"seq\"><A/><B/></Sequence>");
  RecordingObserver rec(e);
  e.add_observer(&rec);
  e.tick();
  EXPECT_EQ(rec.changes,
            (std::vector<std::string>{"seq:IDLE>RUNNING", "A:IDLE>SUCCESS", "B:IDLE>RUNNING"}));
  rec.changes.clear();
  e.tick();
  // The completed root goes back to IDLE at the end of the tick (BT.CPP's tickRoot).
  EXPECT_EQ(rec.changes,
            (std::vector<std::string>{"B:RUNNING>SUCCESS", "A:SUCCESS>IDLE", "B:SUCCESS>IDLE",
                                      "seq:RUNNING>SUCCESS", "seq:SUCCESS>IDLE"}));
  e.remove_observer(&rec);
  rec.changes.clear();
  e.tick();
  EXPECT_TRUE(rec.changes.empty());
}

// An engine kept for the next run (a campaign's scenarios, prove's counterexample replays)
// must not call an observer of a run that ended, however it ended.
TEST_F(EngineTest, AnObserverOfOneScopeIsGoneWhenTheScopeThrows) {
  world.script("B", {R, S});
  Engine e = build("<Sequence name=\"seq\"><A/><B/></Sequence>");
  RecordingObserver rec(e);
  try {
    const Observing observing(e, rec);
    e.tick();
    throw std::runtime_error("the run stops");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(rec.changes,
            (std::vector<std::string>{"seq:IDLE>RUNNING", "A:IDLE>SUCCESS", "B:IDLE>RUNNING"}));
  rec.changes.clear();
  e.tick();
  EXPECT_TRUE(rec.changes.empty());
}

TEST_F(EngineTest, PathsAndNodeInfo) {
  Engine e = build(
      "<Sequence><Fallback><IsInLocation/><SubTree ID=\"navigation\"/></Fallback>"
      "<Stop/></Sequence>",
      "<BehaviorTree ID=\"navigation\"><Fallback name=\"navigation\">"
      "<Sequence name=\"Req1\"><OnDust/><Drive/></Sequence></Fallback></BehaviorTree>");
  const NodeId drive =
      e.find_path("Main/Sequence/Fallback[0]/SubTree[1]/navigation/Fallback/Sequence[0]/Drive[1]");
  ASSERT_NE(drive, kNoNode);
  EXPECT_EQ(e.tree_path(drive), "navigation/Fallback/Sequence[0]/Drive[1]");
  const NodeInfo& info = e.info(drive);
  EXPECT_EQ(info.tree_id, "navigation");
  EXPECT_EQ(info.kind, "Drive");
  EXPECT_EQ(info.location.file, "test.xml");
  EXPECT_EQ(e.info(info.parent).name, "Req1");
  EXPECT_EQ(e.tree_path(e.root()), "Main/Sequence");
  EXPECT_EQ(e.subtree_calls("navigation").size(), 1u);
}

TEST_F(EngineTest, SelectionObserverReportsTheAlternativeThatStarts) {
  world.script("OnDust", {F});
  world.script("Drive", {R});
  const std::string trees =
      "<BehaviorTree ID=\"navigation\"><Fallback name=\"navigation\">"
      "<Sequence name=\"Req1\"><OnDust/><SubTree ID=\"on_dust\"/></Sequence>"
      "<Sequence name=\"Req2\"><OnRocks/><SubTree ID=\"on_rocks\"/></Sequence>"
      "</Fallback></BehaviorTree>"
      "<BehaviorTree ID=\"on_dust\"><Drive/></BehaviorTree>"
      "<BehaviorTree ID=\"on_rocks\"><Drive/></BehaviorTree>";
  Engine e = build("<SubTree ID=\"navigation\" _autoremap=\"true\"/>", trees);
  std::vector<Selection> selections;
  SelectionObserver observer(e, [&](const Selection& s) { selections.push_back(s); });
  e.add_observer(&observer);
  EXPECT_EQ(e.tick(), R);
  EXPECT_EQ(e.tick(), R);  // still running: no new selection
  ASSERT_EQ(selections.size(), 1u);
  EXPECT_EQ(selections[0].tick, 1u);
  EXPECT_EQ(selections[0].adaptable, "navigation");
  EXPECT_EQ(selections[0].branch, 1u);
  EXPECT_EQ(selections[0].requirement, "Req2");
  EXPECT_EQ(selections[0].alternative, "on_rocks");
}

TEST_F(EngineTest, CountsNodeTicksAndIsFastOnALargeTree) {
  // 10 000 nodes: a Sequence of 2 499 Fallback[Inverter[AlwaysSuccess], AlwaysSuccess] + 4.
  std::string body = "<Sequence>";
  for (int i = 0; i < 2499; ++i)
    body += "<Fallback><Inverter><AlwaysSuccess/></Inverter><AlwaysSuccess/></Fallback>";
  body += "<AlwaysSuccess/><AlwaysSuccess/><AlwaysSuccess/></Sequence>";
  Engine e = build(body);
  EXPECT_EQ(e.node_count(), 10000u);
  EXPECT_EQ(e.tick(), S);
  EXPECT_EQ(e.stats().node_ticks, 10000u);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 200; ++i) e.tick();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double rate = 200 * 10000 / seconds;
  RecordProperty("node_ticks_per_second", std::to_string(static_cast<long long>(rate)));
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
  EXPECT_GE(rate, 1e6) << "node ticks per second";
#endif
  EXPECT_EQ(e.stats().root_ticks, 201u);
}

}  // namespace
}  // namespace uabt::runtime::testing
