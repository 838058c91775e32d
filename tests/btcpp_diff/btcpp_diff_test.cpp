// The recorded differences between BehaviorTree.CPP 4.10.0 and uabt (shared reference
// btcpp-diff/): each reproducer's compiled tree runs in its scenario, and uabt's per-tick
// record (root status, leaf activity) and outcome must equal BT.CPP's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bt/xml_io.hpp"
#include "compile/compile.hpp"
#include "load/mission.hpp"
#include "runtime/runner.hpp"
#include "runtime/trace.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::runtime {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

fs::path reproducer(const std::string& name) {
  return uabt::testing::shared_dir() / "reference" / "btcpp-diff" / name;
}

Json read_json(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return Json::parse(text.str());
}

Json leaf_json(const LeafLogEntry& e) {
  switch (e.event) {
    case LeafEvent::condition: return {"cond", e.leaf, status_name(e.status)};
    case LeafEvent::action_started: return {"start", e.leaf};
    case LeafEvent::action_finished: return {"finish", e.leaf, status_name(e.status)};
    case LeafEvent::action_halted: return {"halt", e.leaf};
  }
  return nullptr;
}

struct Recorded {
  Json record = Json::array();  // the probe's format
  std::optional<TickError> error;
};

// Runs the reproducer's compiled.xml in its scenario.json, one Runner step a tick, recording
// what BT.CPP's probe records.
Recorded run_document(const bt::Document& doc, const fs::path& dir) {
  Runner runner(doc, load_scenario(dir / "scenario.json"));
  Recorded out;
  while (!runner.done() && static_cast<std::int64_t>(runner.ticks()) < runner.max_ticks()) {
    const NodeStatus s = runner.step();
    Json leaves = Json::array();
    for (const LeafLogEntry& e : runner.world().log()) leaves.push_back(leaf_json(e));
    runner.world().clear_log();
    out.record.push_back({{"tick", runner.ticks()},
                          {"root", runner.error() ? "EXCEPTION" : status_name(s)},
                          {"leaves", leaves}});
  }
  std::string verdict = runner.verdict();
  if (verdict == "success" || verdict == "failure")
    verdict = verdict == "success" ? "SUCCESS" : "FAILURE";
  Json state = Json::object();
  for (const auto& [key, value] : runner.engine().blackboard().entries())
    state[key] = Json(value_json(value));
  out.record.push_back(
      {{"event", "done"}, {"verdict", verdict}, {"ticks", runner.ticks()}, {"state", state}});
  out.error = runner.error();
  return out;
}

Recorded run_reproducer(const fs::path& dir) {
  std::vector<Finding> findings;
  auto doc = bt::read_document(dir / "compiled.xml", bt::ReadOptions{dir, dir}, findings);
  if (!doc) throw std::runtime_error("compiled.xml does not read");
  return run_document(*doc, dir);
}

// uabt's record equals BT.CPP's, tick by tick; BT.CPP's exception text is not compared (uabt
// names the node and the script its own way), its presence is.
void expect_record(const std::string& name, const std::function<Recorded(const fs::path&)>& run) {
  const fs::path dir = reproducer(name);
  if (!fs::exists(dir / "outputs.json")) GTEST_SKIP() << "no btcpp-diff reference data";
  Json expected = read_json(dir / "outputs.json")["btcpp_probe"];
  ASSERT_FALSE(expected.empty());
  const bool expects_error = expected.back().value("verdict", "") == "error";
  expected.back().erase("error");
  const Recorded got = run(dir);
  ASSERT_EQ(got.record.size(), expected.size()) << got.record.dump(1);
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(got.record[i], expected[i]) << "record " << i;
  EXPECT_EQ(got.error.has_value(), expects_error);
}

void expect_btcpp_record(const std::string& name) {
  expect_record(name, run_reproducer);
}

// What `uabt compile` writes from the reproducer's mission today, played the same way: what
// compile accepts, the engine runs as BT.CPP does.
Recorded compile_and_run(const fs::path& dir) {
  std::string error;
  auto mission = load::load_mission(dir, {}, error);
  if (!mission) throw std::runtime_error("the mission does not load: " + error);
  const compile::Result compiled = compile::compile_mission(*mission, {});
  if (!compiled.ok) throw std::runtime_error("the mission does not compile");
  return run_document(compiled.document, dir);
}

// The run stops at tick 1 in `path`'s script `script`, with a message that says `message`.
void expect_tick_error(const std::string& name, const std::string& path, const std::string& script,
                       const std::string& message) {
  const fs::path dir = reproducer(name);
  if (!fs::exists(dir)) return;
  const Recorded got = run_reproducer(dir);
  ASSERT_TRUE(got.error.has_value());
  EXPECT_EQ(got.error->tick, 1u);
  EXPECT_EQ(got.error->path, path);
  EXPECT_EQ(got.error->script, script);
  EXPECT_NE(got.error->message.find(message), std::string::npos) << got.error->message;
}

TEST(BtcppDiff, SequenceWithMemoryUnderParallelAllFailsAtTickOne) {
  // The wake-up re-tick lets A1 finish within tick 1, so the Inverter sees C1 true.
  expect_btcpp_record("wakeup-seqmem-verdict-flip");
}

TEST(BtcppDiff, RepeatInsideAReactiveSequenceNeverEnds) {
  // Every tick restarts the Repeat, whose wake-up halts the running A0: timeout at 40.
  expect_btcpp_record("wakeup-repeat-reactive-never-ends");
}

TEST(BtcppDiff, ReservedAttributesAreNotPartOfTheLeafKey) {
  expect_btcpp_record("leaf-key-has-reserved-attrs");
}

TEST(BtcppDiff, ScriptConditionOnAnUnsetKeyStopsTheRun) {
  expect_btcpp_record("tick-error-random-minimal");
  expect_tick_error("tick-error-random-minimal", "MainTree/Sequence/ScriptCondition[1]",
                    "x >= 1 && C1 == false", "undefined blackboard key 'x'");
}

TEST(BtcppDiff, SkippedWhileDoElseConditionStopsTheRun) {
  expect_btcpp_record("skipped-condition-whiledoelse");
  const fs::path dir = reproducer("skipped-condition-whiledoelse");
  if (!fs::exists(dir)) return;
  const Recorded got = run_reproducer(dir);
  ASSERT_TRUE(got.error.has_value());
  EXPECT_EQ(got.error->path, "MainTree/Sequence/WhileDoElse[1]");
}

TEST(BtcppDiff, UnboundedRetryLoopIsAnErrorInsteadOfAHang) {
  // BT.CPP's first tickOnce() never returns (no record). uabt stops the run within tick 1
  // and names the node that keeps asking for a re-tick.
  const fs::path dir = reproducer("unbounded-retry-loop");
  if (!fs::exists(dir / "outputs.json")) GTEST_SKIP() << "no btcpp-diff reference data";
  EXPECT_TRUE(read_json(dir / "outputs.json")["btcpp_probe"].empty());
  const Recorded got = run_reproducer(dir);
  ASSERT_TRUE(got.error.has_value());
  EXPECT_EQ(got.error->tick, 1u);
  EXPECT_EQ(got.error->path, "MainTree/Sequence/RetryUntilSuccessful[1]");
  EXPECT_NE(got.error->message.find("tickOnce() would never return"), std::string::npos);
  EXPECT_EQ(got.record.back()["verdict"], "error");
}

TEST(BtcppDiff, LogicOperatorOnAnIntegerOtherThanZeroOrOneStopsTheRun) {
  expect_btcpp_record("script-logic-on-integers");
  expect_tick_error("script-logic-on-integers", "MainTree/Sequence/ScriptCondition[1]", "x && b0",
                    "operator [&&] takes an integer only when it is 0 or 1, not 2");
}

TEST(BtcppDiff, ScriptResultsAreDoublesSoAnEntryTakesALaterReal) {
  expect_btcpp_record("script-result-types");
}

TEST(BtcppDiff, AnIntegerAssignedToABooleanEntryIsStored) {
  expect_btcpp_record("script-int-into-bool-entry");
}

// A boolean entry that receives an integer stays boolean. BehaviorTree.CPP 4.10.0 keeps bools
// and integers as int64 in its Any (safe_any.hpp, the EnableIntegral constructor), so
// ExprAssignment::evaluate's Any::copyInto copies the raw integer and the entry keeps its
// original type bool: a later 0, 1, 1.0, true or false makes it a boolean again, an entry
// created from it (`y := e`) is typed bool too, a whole real is converted to its integer
// (convertNumber), a fraction throws. BT.CPP's probe writes a bool-typed entry as true/false
// when Any::cast<bool> succeeds, else as its integer (b0 = 3 in script-int-into-bool-entry).
// The expected record below is BT.CPP's for this tree and scenario, from those functions (each
// conversion checked against BT.CPP 4.10.0's safe_any.hpp).
Recorded run_inline(const std::string& tree, const std::string& scenario) {
  const uabt::testing::TempMission dir({{"compiled.xml", tree}, {"scenario.json", scenario}});
  return run_reproducer(dir.dir());
}

const char* kBoolEntryTree = R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence>
      <Script code="a := x; a := 0"/>
      <Script code="b := x; b = true"/>
      <Script code="c := x; c += 1"/>
      <Script code="d := x; d := 1.0"/>
      <Script code="e := x; y := e; y = false"/>
    </Sequence>
  </BehaviorTree>
</root>
)";

TEST(BtcppDiff, ABooleanEntryThatReceivesAnIntegerStaysBoolean) {
  const Recorded got = run_inline(kBoolEntryTree, R"({"max_ticks": 5, "initial": {
      "x": 3, "a": true, "b": false, "c": true, "d": false, "e": true}})");
  const Json btcpp = Json::parse(R"([
    {"tick": 1, "root": "SUCCESS", "leaves": []},
    {"event": "done", "verdict": "SUCCESS", "ticks": 1, "state": {
      "a": false, "b": true, "c": 4, "d": true, "e": 3, "x": 3, "y": false}}])");
  EXPECT_EQ(got.record, btcpp) << got.record.dump(1);
  EXPECT_FALSE(got.error.has_value());
}

// A fraction into a boolean entry that holds an integer: Any::copyInto converts it to int64
// and convertNumber refuses the fraction; the run stops at that script.
TEST(BtcppDiff, AFractionIntoABooleanEntryStopsTheRun) {
  const Recorded got = run_inline(R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Script code="f := x; f := 2.5"/>
  </BehaviorTree>
</root>
)",
                                  R"({"max_ticks": 5, "initial": {"x": 3, "f": true}})");
  ASSERT_TRUE(got.error.has_value());
  EXPECT_EQ(got.record[0], Json::parse(R"({"tick": 1, "root": "EXCEPTION", "leaves": []})"));
  EXPECT_NE(got.error->message.find("cannot assign 2.5 (real) to 'f', which holds a bool"),
            std::string::npos)
      << got.error->message;
  EXPECT_EQ(got.record.back()["state"], Json::parse(R"({"f": 3, "x": 3})"));
}

TEST(BtcppDiff, ChainedAssignmentAssignsBothEntries) {
  expect_btcpp_record("script-chained-assignment");
}

TEST(BtcppDiff, SubTreeLiteralPortKeepsItsNumericType) {
  expect_btcpp_record("subtree-literal-port-typed");
}

TEST(BtcppDiff, WhatCompileAcceptsTheEngineRunsAsBtcpp) {
  // Each script reproducer's mission, compiled now: the engine neither refuses a tree compile
  // wrote (the chained assignment was refused at build) nor runs it differently from BT.CPP.
  for (const char* name :
       {"script-logic-on-integers", "script-result-types", "script-int-into-bool-entry",
        "script-chained-assignment", "subtree-literal-port-typed"}) {
    SCOPED_TRACE(name);
    expect_record(name, compile_and_run);
  }
}

}  // namespace
}  // namespace uabt::runtime
