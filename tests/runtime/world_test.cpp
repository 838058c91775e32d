// The simulated world, scenario files and the Runner.
#include <filesystem>
#include <fstream>

#include "runtime/runner.hpp"
#include "runtime/selection.hpp"
#include "runtime_test_support.hpp"
#include "test_support.hpp"

namespace uabt::runtime::testing {
namespace {

std::string scenario_error(const std::string& json) {
  try {
    parse_scenario(json, "scenarios/s.json");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(Scenario, ParsesTheDesignExample) {
  const Scenario s = parse_scenario(R"({"max_ticks": 2000,
    "initial": {"OnDust": true, "IsInLocation": false, "battery": 90, "slope": 2.5,
                "terrain": "dust"},
    "actions": {"MoveForward": {"ticks": 20, "effects": {"IsInLocation": true}},
                "Drill": {"ticks": 30, "effects": {"IsDug": true}, "result": "failure"}},
    "events": [{"at": 40, "uplink": "uplinks/on_mud"},
               {"at": 15, "set": {"OnDust": false, "OnRocks": true}}]})",
                                    "s.json");
  EXPECT_EQ(s.max_ticks, 2000);
  ASSERT_EQ(s.initial.size(), 5u);
  EXPECT_EQ(s.initial[0].first, "OnDust");  // file order
  EXPECT_EQ(s.initial[2].second, ScriptValue::of_int(90));
  EXPECT_EQ(s.initial[3].second, ScriptValue::of_real(2.5));
  EXPECT_EQ(s.initial[4].second, ScriptValue::of_string("dust"));
  EXPECT_EQ(s.actions.at("MoveForward").ticks, 20);
  EXPECT_EQ(s.actions.at("Drill").result, F);
  ASSERT_EQ(s.events.size(), 2u);
  EXPECT_EQ(s.events[0].at, 15);  // sorted by tick
  EXPECT_EQ(s.events[1].uplink, "uplinks/on_mud");
  EXPECT_EQ(s.events[1].index, 0);
  EXPECT_TRUE(s.mentions_state("OnRocks"));
  EXPECT_TRUE(s.mentions_state("IsDug"));
  EXPECT_FALSE(s.mentions_state("Drill"));
}

TEST(Scenario, SyntaxErrorsNameFileLineAndColumn) {
  const std::string e = scenario_error("{\n  \"initial\": {\"OnDust\": tru}\n}");
  EXPECT_EQ(e.rfind("scenarios/s.json:2:", 0), 0u) << e;
  EXPECT_NE(e.find("invalid JSON"), std::string::npos) << e;
  const std::string comma = scenario_error("{\"max_ticks\": 5,\n\n   }");
  EXPECT_EQ(comma.rfind("scenarios/s.json:3:4: error: invalid JSON", 0), 0u) << comma;
  const std::string eof = scenario_error("{\"a\": [1, 2");
  EXPECT_EQ(eof.rfind("scenarios/s.json:1:", 0), 0u) << eof;
}

TEST(Scenario, ShapeErrorsNameTheFileAndTheEntry) {
  EXPECT_EQ(scenario_error("[]"),
            "scenarios/s.json:1:1: error: a scenario must be a JSON object, not array");
  EXPECT_EQ(scenario_error(R"({"actions": {"Drill": {"ticks": 0}}})"),
            "scenarios/s.json:1:33: error: /actions/Drill/ticks: must be at least 1, not 0");
  EXPECT_EQ(scenario_error("{\"actions\": {\n  \"Drill\": {\"result\": \"maybe\"}}}"),
            "scenarios/s.json:2:23: error: /actions/Drill/result: must be \"success\" or "
            "\"failure\", not \"maybe\"");
  EXPECT_EQ(scenario_error("{\n \"evnts\": []}"),
            "scenarios/s.json:2:2: error: unknown key 'evnts' (expected: max_ticks, initial, "
            "actions, events, description, name, counterexample_of)");
  EXPECT_NE(scenario_error(R"({"events": [{"set": {}}]})").find("/events/0"), std::string::npos);
  EXPECT_NE(scenario_error(R"({"initial": {"x": [1]}})").find("/initial/x"), std::string::npos);
  EXPECT_NE(scenario_error(R"({"events": [{"at": 3}]})").find("\"set\" or \"uplink\""),
            std::string::npos);
}

TEST(Scenario, LoadsFromAFile) {
  const auto dir = std::filesystem::temp_directory_path() / "uabt_runtime_scenario_test";
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "ok.json") << R"({"max_ticks": 7})"; }
  EXPECT_EQ(load_scenario(dir / "ok.json", "ok.json").max_ticks, 7);
  try {
    load_scenario(dir / "missing.json", "scenarios/missing.json");
    ADD_FAILURE() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()), "scenarios/missing.json: no such file");
  }
  std::filesystem::remove_all(dir);
}

struct WorldTest : ::testing::Test {
  std::unique_ptr<Runner> runner(const std::string& body, const std::string& json,
                                 const std::string& more = "",
                                 std::vector<bt::NodeModel> models = {}) {
    return std::make_unique<Runner>(main_tree(body, more), parse_scenario(json, "s.json"),
                                    RunOptions{}, std::move(models));
  }
  static std::string log_text(const std::vector<LeafLogEntry>& log) {
    std::string s;
    for (const auto& e : log)
      s += (s.empty() ? "" : " ") + std::to_string(e.tick) + ":" + e.leaf + ":" +
           leaf_event_name(e.event) + ":" + status_name(e.status);
    return s;
  }
};

TEST_F(WorldTest, ConditionsReadTheStateAndUnsetIsFalse) {
  auto r =
      runner("<Sequence><OnDust/><Fallback><OnRocks/><AlwaysSuccess/></Fallback></Sequence>",
             R"({"initial": {"OnDust": true}, "events": [{"at": 99, "set": {"OnRocks": 1}}]})");
  const RunResult result = r->run();
  EXPECT_EQ(result.status, S);
  EXPECT_EQ(log_text(result.log), "1:OnDust:condition:SUCCESS 1:OnRocks:condition:FAILURE");
}

TEST_F(WorldTest, ActionsRunForTheirTicksThenApplyEffects) {
  auto r = runner("<Sequence><MoveForward/><IsInLocation/><Stop/></Sequence>",
                  R"({"initial": {"IsInLocation": false},
                      "actions": {"MoveForward": {"ticks": 3, "effects": {"IsInLocation": true}}}})");
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(*r->engine().blackboard().get("IsInLocation"), ScriptValue::of_bool(false));
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(r->step(), S);  // MoveForward done, IsInLocation now true, Stop: 1 tick
  const RunResult result = r->run();
  EXPECT_EQ(result.ticks, 3u);
  EXPECT_TRUE(result.finished);
  EXPECT_EQ(log_text(result.log),
            "1:MoveForward:started:RUNNING 3:MoveForward:finished:SUCCESS "
            "3:IsInLocation:condition:SUCCESS 3:Stop:started:RUNNING 3:Stop:finished:SUCCESS");
}

TEST_F(WorldTest, ResultFailureAndMaxTicks) {
  auto fails = runner("<Drill/>", R"({"actions": {"Drill": {"ticks": 2, "result": "failure"}}})");
  const RunResult a = fails->run();
  EXPECT_EQ(a.status, F);
  EXPECT_EQ(a.ticks, 2u);
  auto forever =
      runner("<KeepRunningUntilFailure><Step/></KeepRunningUntilFailure>", R"({"max_ticks": 25})");
  const RunResult b = forever->run();
  EXPECT_EQ(b.status, R);
  EXPECT_FALSE(b.finished);
  EXPECT_EQ(b.ticks, 25u);
}

TEST_F(WorldTest, EventsChangeStateAndAHaltedActionStartsOver) {
  auto r = runner("<ReactiveSequence><OnDust/><Drive/></ReactiveSequence>",
                  R"({"initial": {"OnDust": true},
                      "actions": {"Drive": {"ticks": 4}},
                      "events": [{"at": 3, "set": {"OnDust": false}},
                                 {"at": 4, "set": {"OnDust": true}}]})");
  r->world().log_conditions(false);
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(r->step(), F);  // OnDust false before tick 3: Drive halted
  EXPECT_TRUE(r->done());
  // Ticking on: Drive starts over at tick 4 and needs its 4 ticks again.
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(r->step(), R);
  EXPECT_EQ(r->step(), S);
  EXPECT_EQ(log_text(r->world().log()),
            "1:Drive:started:RUNNING 3:Drive:halted:IDLE 4:Drive:started:RUNNING "
            "7:Drive:finished:SUCCESS");
}

TEST_F(WorldTest, UplinksGoToTheHookOrAreReportedUnhandled) {
  const std::string json = R"({"actions": {"Wait": {"ticks": 5}},
                               "events": [{"at": 2, "uplink": "uplinks/on_mud"}]})";
  auto unhandled = runner("<Wait/>", json);
  const RunResult a = unhandled->run();
  ASSERT_EQ(a.unhandled_uplinks.size(), 1u);
  EXPECT_EQ(a.unhandled_uplinks[0].uplink, "uplinks/on_mud");

  auto hooked = runner("<Wait/>", json);
  std::vector<std::string> seen;
  hooked->on_uplink = [&](const ScenarioEvent& e, Runner& run) {
    seen.push_back(std::to_string(run.ticks()) + " " + e.uplink);
  };
  EXPECT_TRUE(hooked->run().unhandled_uplinks.empty());
  EXPECT_EQ(seen, (std::vector<std::string>{"1 uplinks/on_mud"}));  // after tick 1, before 2
}

TEST_F(WorldTest, PortsQualifyTheStateKey) {
  auto r = runner(
      "<Sequence><IsArmInPosition function=\"drilling\"/>"
      "<Fallback><IsArmInPosition function=\"closing_arm\"/><CloseToolArm/></Fallback>"
      "<Sequence><Script code=\"f := 'closing_arm'\"/><IsArmInPosition function=\"{f}\"/>"
      "</Sequence></Sequence>",
      R"J({"initial": {"IsArmInPosition(function=drilling)": true, "IsArmInPosition": false},
          "actions": {"CloseToolArm": {"effects": {"IsArmInPosition(function=closing_arm)": true}}}})J");
  const RunResult result = r->run();
  EXPECT_EQ(result.status, S) << log_text(result.log);
  EXPECT_EQ(log_text(result.log),
            "1:IsArmInPosition(function=drilling):condition:SUCCESS "
            "1:IsArmInPosition(function=closing_arm):condition:FAILURE "
            "1:CloseToolArm:started:RUNNING 1:CloseToolArm:finished:SUCCESS "
            "1:IsArmInPosition(function=closing_arm):condition:SUCCESS");
}

TEST_F(WorldTest, NodeModelsDeclareConditions) {
  bt::NodeModel model;
  model.family = "Condition";
  model.id = "IsDigged";
  auto r = runner("<Fallback><IsDigged/><Drill/></Fallback>", "{}", "", {model});
  const RunResult result = r->run();
  EXPECT_EQ(log_text(result.log),
            "1:IsDigged:condition:FAILURE 1:Drill:started:RUNNING 1:Drill:finished:SUCCESS");
  // Without the model IsDigged would be taken for an action (1 tick, SUCCESS).
  auto guess = runner("<Fallback><IsDigged/><Drill/></Fallback>", "{}");
  EXPECT_EQ(log_text(guess->run().log), "1:IsDigged:started:RUNNING 1:IsDigged:finished:SUCCESS");
}

TEST_F(WorldTest, ScriptsSeeAndChangeTheWorldState) {
  auto r = runner(
      "<Sequence><ScriptCondition code=\"battery &gt; 20 &amp;&amp; terrain == 'rocks'\"/>"
      "<Script code=\"OnDust := true\"/><OnDust/></Sequence>",
      R"({"initial": {"battery": 90, "terrain": "rocks", "OnDust": false}})");
  EXPECT_EQ(r->run().status, S);
}

// The paper's MSL mission shape after compilation (Fig. 4 selection subtree).
TEST_F(WorldTest, CompiledMissionSelectsAndReselectsAfterATerrainChange) {
  const std::string trees = R"(
    <BehaviorTree ID="navigation">
      <ReactiveFallback name="navigation">
        <ReactiveSequence name="Req1"><OnDust/><SubTree ID="on_dust" _autoremap="true"/></ReactiveSequence>
        <ReactiveSequence name="Req2"><OnRocks/><SubTree ID="on_rocks" _autoremap="true"/></ReactiveSequence>
      </ReactiveFallback>
    </BehaviorTree>
    <BehaviorTree ID="on_dust"><Sequence><TurnToTarget/><MoveForward/></Sequence></BehaviorTree>
    <BehaviorTree ID="on_rocks"><Sequence><CheckSafestSide/><MoveBackward/></Sequence></BehaviorTree>)";
  auto r = runner(
      R"(<Sequence><Fallback><IsInLocation/><SubTree ID="navigation" _autoremap="true"/></Fallback><Stop/></Sequence>)",
      R"({"initial": {"OnDust": true, "IsInLocation": false},
                      "actions": {"MoveForward": {"ticks": 10, "effects": {"IsInLocation": true}},
                                  "MoveBackward": {"ticks": 3, "effects": {"IsInLocation": true}}},
                      "events": [{"at": 4, "set": {"OnDust": false, "OnRocks": true}}]})",
      trees);
  std::vector<std::string> selections;
  SelectionObserver observer(r->engine(), [&](const Selection& s) {
    selections.push_back(std::to_string(s.tick) + " " + s.requirement + " " + s.alternative);
  });
  r->engine().add_observer(&observer);
  const RunResult result = r->run();
  EXPECT_EQ(result.status, S);
  EXPECT_EQ(result.ticks, 6u);  // MoveBackward from tick 4 to 6, then Stop
  EXPECT_EQ(selections, (std::vector<std::string>{"1 Req1 on_dust", "4 Req2 on_rocks"}));
  EXPECT_TRUE(result.errors.empty());
}

TEST_F(WorldTest, ReplicationPackageTreeRunsInAScenario) {
  // The paper's hand-written uncertainty-aware BT (BT.CPP v3, SubTrees without remapping).
  const auto file = uabt::testing::shared_dir() / "reference" / "seed-replication" /
                    "_from-gianlucafilippone-spaceros-demos" / "mars_rover_bt_manager" /
                    "uncertainty_aware_bt.xml";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no replication package";
  std::vector<Finding> findings;
  auto doc =
      bt::read_document(file, bt::ReadOptions{file.parent_path(), file.parent_path()}, findings);
  ASSERT_TRUE(doc.has_value());
  Runner run(*doc, parse_scenario(R"({"initial": {"IsInLocation": false, "OnDust": false,
                                                  "OnRocks": true, "IsRockInLeft": true}})",
                                  "s.json"));
  const RunResult result = run.run();
  EXPECT_EQ(result.status, S);
  EXPECT_TRUE(result.errors.empty());
  const std::string log = log_text(result.log);
  EXPECT_NE(log.find("1:OnDust:condition:FAILURE 1:OnRocks:condition:SUCCESS"), std::string::npos)
      << log;
  EXPECT_NE(log.find("1:IsRockInLeft:condition:SUCCESS 1:MoveBackward(speed=0.4,time=10)"),
            std::string::npos)
      << log;
}

}  // namespace
}  // namespace uabt::runtime::testing
