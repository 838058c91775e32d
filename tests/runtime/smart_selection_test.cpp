// EngineOptions::smart_selection at the engine level: what is skipped, what never is.
#include <gtest/gtest.h>

#include "runtime/condition_count.hpp"
#include "runtime_test_support.hpp"

namespace uabt::runtime {
namespace {

using namespace testing;

// A reactive selection over a blackboard reading; "Drive" runs for several ticks.
const char* kSelection =
    "<ReactiveFallback name=\"Main\">"
    "  <ReactiveSequence name=\"Low\"><ScriptCondition code=\"%GUARD%\"/>"
    "    <Action ID=\"Drive\"/></ReactiveSequence>"
    "  <ReactiveSequence name=\"Default\"><Action ID=\"Hold\"/></ReactiveSequence>"
    "</ReactiveFallback>";

struct Trial {
  std::uint64_t conditions = 0;
  std::string events;
  std::vector<NodeStatus> results;
};

// Five ticks; before tick 4 the reading becomes `later`.
Trial run(const std::string& guard, bool smart, std::int64_t later) {
  std::string body = kSelection;
  body.replace(body.find("%GUARD%"), 7, guard);
  ScriptedWorld world;
  world.script("Drive", {R, R, R, R, R, R});
  world.script("Hold", {R, R, R, R, R, R});
  EngineOptions options;
  options.smart_selection = smart;
  Engine engine = Engine::build(main_tree(body), world, options);
  engine.blackboard().set("battery", ScriptValue::of_int(10));
  engine.blackboard().set("n", ScriptValue::of_int(0));
  ConditionCounter counter(engine);
  engine.add_observer(&counter);
  Trial out;
  for (int t = 1; t <= 5; ++t) {
    if (t == 4) engine.blackboard().set("battery", ScriptValue::of_int(later));
    out.results.push_back(engine.tick());
  }
  out.conditions = counter.count();
  out.events = world.joined_events();
  return out;
}

TEST(SmartSelection, GuardsAreSkippedWhileTheirReadingDoesNotChange) {
  const Trial plain = run("battery < 20", false, 10);
  const Trial smart = run("battery < 20", true, 10);
  EXPECT_EQ(plain.events, smart.events);
  EXPECT_EQ(plain.results, smart.results);
  EXPECT_EQ(plain.conditions, 5u);
  EXPECT_EQ(smart.conditions, 1u);
}

TEST(SmartSelection, AChangedReadingRerunsTheGuardsAndPreempts) {
  const Trial plain = run("battery < 20", false, 50);
  const Trial smart = run("battery < 20", true, 50);
  EXPECT_EQ(plain.events, smart.events);  // Drive halted at tick 4, Hold started
  EXPECT_NE(smart.events.find("~Drive Hold"), std::string::npos) << smart.events;
  EXPECT_EQ(plain.conditions, 5u);
  EXPECT_EQ(smart.conditions, 2u);  // tick 1, and tick 4 where the reading changed
}

TEST(SmartSelection, AGuardThatAssignsIsNeverSkipped) {
  const Trial plain = run("n += 1; battery < 20", false, 10);
  const Trial smart = run("n += 1; battery < 20", true, 10);
  EXPECT_EQ(smart.conditions, plain.conditions);
  EXPECT_EQ(plain.events, smart.events);
}

TEST(SmartSelection, RobotConditionsOfAWorldThatNamesNoReadsAreNeverSkipped) {
  const std::string body =
      "<ReactiveFallback><ReactiveSequence><Condition ID=\"OnDust\"/><Action ID=\"Drive\"/>"
      "</ReactiveSequence><Action ID=\"Hold\"/></ReactiveFallback>";
  ScriptedWorld world;
  world.script("Drive", {R, R, R, R});
  EngineOptions options;
  options.smart_selection = true;
  Engine engine = Engine::build(main_tree(body), world, options);
  for (int t = 0; t < 4; ++t) engine.tick();
  EXPECT_EQ(world.ticks("OnDust"), 4);
}

}  // namespace
}  // namespace uabt::runtime
