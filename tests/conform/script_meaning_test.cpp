// A script condition means one thing: what the engine computes (BT.CPP 4.10's rules) is what
// its reading into FRETISH evaluates to, so conform, verify and the prover judge the tree the
// engine runs. Random conditions over an integer, a real and an enum, in states chosen near
// the conditions' constants (within float epsilon of them too), through both.
#include <gtest/gtest.h>

#include <iostream>

#include "conform/script_parse.hpp"
#include "fretish/evaluate.hpp"
#include "script_conditions.hpp"

namespace uabt::conform {
namespace {

using testing::ConditionWriter;
using testing::engine_truth;
using testing::random_state;
using testing::rover_domain;
using testing::State;

fretish::Val reading_value(const fretish::Expr& reading, const State& s) {
  return fretish::evaluate(reading, [&](const std::string& name, bool) {
    if (name == "battery") return fretish::Val::of_whole(s.battery);
    if (name == "slope") return fretish::Val::of_number(s.slope);
    if (name == "terrain") return fretish::Val::of_symbol(s.terrain == "sand" ? 0 : 1);
    if (name == "sand") return fretish::Val::of_symbol(0);
    if (name == "rocks") return fretish::Val::of_symbol(1);
    return fretish::Val::none(fretish::Val::Fault::unset);
  });
}

TEST(ScriptMeaning, TheEngineAndTheReadingAgreeOnRandomConditions) {
  const fretish::Domain domain = rover_domain();
  ConditionWriter writer(20261203);
  std::mt19937 random(7);
  int compared = 0, held = 0, disagreements = 0;
  for (int k = 0; k < 3000; ++k) {
    const std::string code = writer.condition(2);
    const ScriptReading reading = parse_script_condition(code, domain);
    ASSERT_TRUE(reading.expr) << code << ": " << reading.error;
    for (int i = 0; i < 20; ++i) {
      const State s = random_state(random);
      const std::optional<bool> engine = engine_truth(code, s);
      const fretish::Val value = reading_value(*reading.expr, s);
      if (!engine || !value.known()) continue;
      ++compared;
      held += *engine ? 1 : 0;
      if (*engine != value.truth() && ++disagreements <= 5)
        ADD_FAILURE() << code << " in battery=" << s.battery << " slope=" << s.slope
                      << " terrain=" << s.terrain << ": the engine says " << *engine
                      << ", the reading '" << fretish::to_fretish(*reading.expr) << "' says "
                      << value.truth();
    }
  }
  std::cout << "script meaning: " << compared << " states compared, " << held
            << " where the condition holds, " << disagreements << " disagreements\n";
  EXPECT_EQ(disagreements, 0);
  // Most states are decided both ways, and both verdicts occur often.
  EXPECT_GT(compared, 50000);
  EXPECT_GT(held, compared / 5);
  EXPECT_LT(held, compared * 4 / 5);
}

// The two places FRETISH's meaning differs from a script's, each with a state that tells them
// apart: the reading takes the engine's side.
TEST(ScriptMeaning, DivisionAndEqualityReadAsTheEngineComputesThem) {
  const fretish::Domain domain = rover_domain();
  const struct {
    const char* code;
    State state;
    bool engine;
  } cases[] = {
      {"battery / 2 > 1", {3, 0, "sand"}, true},  // 1.5 > 1; FRETISH's 3 / 2 is 1
      {"battery / 2 == 1", {3, 0, "sand"}, false},
      {"slope == 0.5", {0, 0.5 + 1e-7, "sand"}, true},  // within float epsilon
      {"slope != 0.5", {0, 0.5 + 1e-7, "sand"}, false},
      {"slope == 0.5", {0, 0.5 + 3e-7, "sand"}, false},
      {"battery == 3", {3, 0, "sand"}, true},
  };
  for (const auto& c : cases) {
    const ScriptReading reading = parse_script_condition(c.code, domain);
    ASSERT_TRUE(reading.expr) << c.code;
    EXPECT_EQ(engine_truth(c.code, c.state), c.engine) << c.code;
    const fretish::Val value = reading_value(*reading.expr, c.state);
    ASSERT_TRUE(value.known()) << c.code;
    EXPECT_EQ(value.truth(), c.engine)
        << c.code << " read as " << fretish::to_fretish(*reading.expr);
  }
  EXPECT_EQ(fretish::to_fretish(*parse_script_condition("battery / 2 > 1", domain).expr),
            "battery / 2.0 > 1");
  EXPECT_EQ(
      fretish::to_fretish(*parse_script_condition("battery / (battery + 1) < 1", domain).expr),
      "battery * 1.0 / (battery + 1) < 1");
  EXPECT_EQ(fretish::to_fretish(*parse_script_condition("slope / 2 > 1", domain).expr),
            "slope / 2 > 1");
  EXPECT_EQ(fretish::to_fretish(*parse_script_condition("slope == 0.5", domain).expr),
            "slope - 0.5 <= 0.00000011920928955078125 & 0.5 - slope <= 0.00000011920928955078125");
}

}  // namespace
}  // namespace uabt::conform
