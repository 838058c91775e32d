// Lowering into Z3, models as states, and agreement with the independent evaluator.
#include <gtest/gtest.h>

#include <random>

#include "smt/encoder.hpp"
#include "smt/evaluate.hpp"
#include "smt/expr_support.hpp"

namespace uabt::smt {
namespace {

using testing::domain;
using testing::expr;

const SourceLocation kWhere{"requirements.fret", 1, 1};

TEST(Encoder, IllTypedConditionIsNotLowered) {
  const fretish::Domain d = domain("enum terrain in {dust, rocks}\n");
  Encoder encoder(d);
  std::vector<Finding> findings;
  EXPECT_FALSE(encoder.lower_condition(*expr("terrain = 2"), kWhere, findings));
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].check, "ref-type-mismatch");
}

TEST(Encoder, ModelBecomesAFullStateInDeclarationOrder) {
  const fretish::Domain d = domain(
      "real slope in [-45, 45]\nboolean OnDust\nenum terrain in {dust, rocks, sand}\n"
      "integer battery in [0, 100]\n");
  Encoder encoder(d);
  std::vector<Finding> findings;
  const auto parts = encoder.domain_parts(findings);
  const auto guard = encoder.lower_condition(
      *expr("3 * slope = 1 & terrain = sand & battery = 7 & Implicit"), kWhere, findings);
  ASSERT_TRUE(guard);
  z3::solver solver(encoder.context());
  for (const auto& p : parts) solver.add(p.constraint);
  solver.add(*guard);
  ASSERT_EQ(solver.check(), z3::sat);
  const State s = encoder.state_of(solver.get_model());
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[0].first, "slope");
  EXPECT_EQ(s[0].second.text, "1/3");
  EXPECT_NEAR(s[0].second.real, 1.0 / 3.0, 1e-12);
  EXPECT_EQ(s[1].first, "OnDust");  // unconstrained: model completion still assigns it
  EXPECT_EQ(s[1].second.kind, Value::Kind::boolean);
  EXPECT_EQ(s[2], (std::pair<std::string, Value>{"terrain", Value::of_enum("sand")}));
  EXPECT_EQ(s[3], (std::pair<std::string, Value>{"battery", Value::of_int(7)}));
  EXPECT_EQ(s[4], (std::pair<std::string, Value>{"Implicit", Value::of_bool(true)}));
  EXPECT_TRUE(satisfies_domain(d, s));
}

// A witness is written as people write numbers (README, "Numbers"): 256/125 as 2.048, -7/4 as
// -1.75, while a fraction with no finite decimal stays a fraction.
TEST(Encoder, ARealWithAFiniteDecimalIsWrittenAsThatDecimal) {
  const fretish::Domain d = domain("real wind in [-20, 20]\n");
  for (const auto& [condition, text] :
       std::vector<std::pair<std::string, std::string>>{{"125 * wind = 256", "2.048"},
                                                        {"4 * wind = -7", "-1.75"},
                                                        {"80 * wind = 1", "0.0125"},
                                                        {"wind = 3", "3"},
                                                        {"7 * wind = 2", "2/7"},
                                                        {"6 * wind = 1", "1/6"}}) {
    Encoder encoder(d);
    std::vector<Finding> findings;
    const auto parts = encoder.domain_parts(findings);
    const auto guard = encoder.lower_condition(*expr(condition), kWhere, findings);
    ASSERT_TRUE(guard) << condition;
    z3::solver solver(encoder.context());
    for (const auto& p : parts) solver.add(p.constraint);
    solver.add(*guard);
    ASSERT_EQ(solver.check(), z3::sat);
    EXPECT_EQ(encoder.state_of(solver.get_model())[0].second.text, text) << condition;
  }
}

TEST(Encoder, DomainPartsDescribeRangesEnumsAndAssumptions) {
  const fretish::Domain d = domain(
      "integer battery in [0, 100]\nenum terrain in {dust, rocks}\nboolean A\n"
      "assume charged: battery > 10\n");
  Encoder encoder(d);
  std::vector<Finding> findings;
  const auto parts = encoder.domain_parts(findings);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].description, "battery in [0, 100]");
  EXPECT_EQ(parts[1].description, "terrain in {dust, rocks}");
  EXPECT_EQ(parts[2].description, "assumption charged");
  EXPECT_TRUE(findings.empty());
}

TEST(Encoder, ExactRealLiteralsAreNotRounded) {
  const fretish::Domain d = domain("real x\n");
  Encoder encoder(d);
  std::vector<Finding> findings;
  // 0.1 + 0.2 = 0.3 holds exactly over the rationals (not in binary floating point).
  const auto g = encoder.lower_condition(*expr("x = 0.1 + 0.2 & x != 0.3"), kWhere, findings);
  ASSERT_TRUE(g);
  z3::solver solver(encoder.context());
  solver.add(*g);
  EXPECT_EQ(solver.check(), z3::unsat);
}

// Asks Z3 for the truth value of `condition` in `state` (every variable pinned).
std::optional<bool> solver_truth(Encoder& encoder, const z3::expr& condition, const State& state) {
  z3::solver solver(encoder.context());
  for (const auto& [name, value] : state) {
    const Encoder::Slot* slot = encoder.find_slot(name);
    if (slot == nullptr) continue;
    switch (value.kind) {
      case Value::Kind::boolean:
        solver.add(slot->constant == encoder.context().bool_val(value.boolean));
        break;
      case Value::Kind::integer:
        solver.add(slot->constant == encoder.context().int_val(value.integer));
        break;
      case Value::Kind::real:
        solver.add(slot->constant == encoder.context().real_val(value.text.c_str()));
        break;
      case Value::Kind::enumeration: {
        const auto& values = slot->declaration->enum_values;
        const auto index = std::find(values.begin(), values.end(), value.text) - values.begin();
        solver.add(slot->constant == encoder.context().int_val(static_cast<int>(index)));
        break;
      }
    }
  }
  solver.push();
  solver.add(condition);
  const bool can_hold = solver.check() == z3::sat;
  solver.pop();
  solver.add(!condition);
  const bool can_fail = solver.check() == z3::sat;
  if (can_hold == can_fail) return std::nullopt;  // unspecified (x / 0) or undecided
  return can_hold;
}

TEST(Encoder, AgreesWithTheIndependentEvaluatorOnRandomStates) {
  const fretish::Domain d = domain(
      "integer x in [-12, 12]\ninteger y in [-12, 12]\nboolean A, B, C\n"
      "enum terrain in {dust, rocks, sand}\nreal r in [-4, 4]\n");
  const std::vector<std::string> conditions = {"x / y = 2",
                                               "x mod y = 1",
                                               "-x / 3 < y",
                                               "x mod 4 = y mod 4",
                                               "(x - y) / -3 >= 1",
                                               "absInt(x) > y",
                                               "minInt(x, y) = x",
                                               "maxReal(r, 1.5) > 2",
                                               "absReal(r - 1) <= 0.5",
                                               "ite(A, x, y) > 0",
                                               "ite(B, terrain, dust) = rocks",
                                               "x ^ 2 + y ^ 3 > 20",
                                               "A xor B xor C",
                                               "A -> B -> C",
                                               "A <-> B <-> C",
                                               "(A = B) != C",
                                               "terrain != sand & (r * 2 > x | y < r)",
                                               "x + r > 1.25",
                                               "r / 2 = 0.75 | x * y > 7",
                                               "!(x < 3 & y >= -2) | terrain = dust"};
  std::mt19937 random(20240611);
  std::uniform_int_distribution<int> coordinate(-12, 12), bit(0, 1), literal(0, 2),
      quarter(-16, 16);
  const std::vector<std::string> terrain = {"dust", "rocks", "sand"};
  for (const auto& text : conditions) {
    SCOPED_TRACE(text);
    Encoder encoder(d);
    std::vector<Finding> findings;
    const auto lowered = encoder.lower_condition(*expr(text), kWhere, findings);
    ASSERT_TRUE(lowered) << (findings.empty() ? "" : findings.front().message);
    int compared = 0;
    for (int trial = 0; trial < 60; ++trial) {
      const int quarters = quarter(random);
      const State state = {{"x", Value::of_int(coordinate(random))},
                           {"y", Value::of_int(coordinate(random))},
                           {"A", Value::of_bool(bit(random))},
                           {"B", Value::of_bool(bit(random))},
                           {"C", Value::of_bool(bit(random))},
                           {"terrain", Value::of_enum(terrain[literal(random)])},
                           {"r", Value::of_real(quarters / 4.0, std::to_string(quarters) + "/4")}};
      const auto expected = try_evaluate(*expr(text), d, state);
      if (!expected) continue;  // division by zero: Z3 leaves the value open
      const auto actual = solver_truth(encoder, *lowered, state);
      ASSERT_TRUE(actual.has_value());
      EXPECT_EQ(*actual, *expected);
      ++compared;
    }
    EXPECT_GT(compared, 30);
  }
}

// A long disjunction of an integer's comparisons with numerals is lowered as the union of their
// ranges: the same truth in every state of the range and beyond it, next to atoms of others.
TEST(Encoder, ALongDisjunctionOfAnIntegersComparisonsKeepsItsMeaning) {
  const fretish::Domain d = domain("integer depth in [-100, 100]\nboolean OnDust\n");
  Encoder encoder(d);
  std::vector<Finding> findings;
  std::string text = "OnDust | depth < -90 | depth >= 95 | 50 = depth | depth != depth + 0";
  for (int k = 0; k < 20; ++k) text += " | depth = " + std::to_string(k);
  text += " | depth = 21 | -30 >= depth";
  const auto guard = encoder.lower_condition(*expr(text), kWhere, findings);
  ASSERT_TRUE(guard);
  z3::context& c = encoder.context();
  const z3::expr depth = c.int_const("depth"), on_dust = c.bool_const("OnDust");
  for (int v = -100; v <= 100; ++v)
    for (const bool dust : {false, true}) {
      const bool expected =
          dust || v < -90 || v >= 95 || v == 50 || (v >= 0 && v < 20) || v == 21 || v <= -30;
      z3::solver solver(c);
      solver.add(depth == v && on_dust == c.bool_val(dust) && *guard != c.bool_val(expected));
      EXPECT_EQ(solver.check(), z3::unsat) << "depth = " << v << ", OnDust = " << dust;
    }
}

}  // namespace
}  // namespace uabt::smt
