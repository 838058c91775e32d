// The independent evaluator that checks every witness.
#include <gtest/gtest.h>

#include "smt/evaluate.hpp"
#include "smt/expr_support.hpp"

namespace uabt::smt {
namespace {

using testing::domain;
using testing::expr;

const fretish::Domain kDomain = domain(
    "integer x in [-10, 10]\ninteger y in [-10, 10]\nreal r in [0, 1]\nboolean A, B\n"
    "enum terrain in {dust, rocks, sand}\nassume not_both: !(A & B)\n");

State state(std::int64_t x, std::int64_t y, bool a = false, bool b = false,
            const std::string& t = "dust") {
  return {{"x", Value::of_int(x)},  {"y", Value::of_int(y)},  {"r", Value::of_real(0.5, "1/2")},
          {"A", Value::of_bool(a)}, {"B", Value::of_bool(b)}, {"terrain", Value::of_enum(t)}};
}

bool eval(const std::string& text, const State& s) {
  return evaluate(*expr(text), kDomain, s);
}

// FRET's targets (C, Lustre, SMV) truncate the quotient toward zero; the remainder has the
// sign of the dividend.
TEST(Evaluate, IntegerDivisionAndModTruncateAsFretTargets) {
  EXPECT_TRUE(eval("x / y = -3", state(-7, 2)));
  EXPECT_TRUE(eval("x mod y = -1", state(-7, 2)));
  EXPECT_TRUE(eval("x / y = -3", state(7, -2)));
  EXPECT_TRUE(eval("x mod y = 1", state(7, -2)));
  EXPECT_TRUE(eval("x / y = 3", state(-7, -2)));
  EXPECT_TRUE(eval("x mod y = -1", state(-7, -2)));
  EXPECT_TRUE(eval("x / 2 = 0", state(1, 0)));
  EXPECT_THROW(eval("x / y = 0", state(1, 0)), EvaluationError);
  EXPECT_FALSE(try_evaluate(*expr("x mod y = 0"), kDomain, state(1, 0)).has_value());
}

TEST(Evaluate, EnumLiteralsTakeTheirMeaningFromTheOtherSide) {
  EXPECT_TRUE(eval("terrain = rocks", state(0, 0, false, false, "rocks")));
  EXPECT_TRUE(eval("sand != terrain", state(0, 0, false, false, "rocks")));
  EXPECT_FALSE(eval("terrain = dust", state(0, 0, false, false, "rocks")));
}

TEST(Evaluate, BooleanConnectivesWithFretMeaning) {
  EXPECT_TRUE(eval("A -> B -> A", state(0, 0, true, false)));  // A -> (B -> A)
  EXPECT_FALSE(eval("(A -> B) -> B", state(0, 0, false, false)));
  EXPECT_TRUE(eval("A xor B", state(0, 0, true, false)));
  EXPECT_TRUE(eval("A <-> B", state(0, 0, false, false)));
  EXPECT_TRUE(eval("A = B", state(0, 0, true, true)));
}

TEST(Evaluate, MixedArithmeticAndFunctions) {
  EXPECT_TRUE(eval("x + r = 3.5", state(3, 0)));
  EXPECT_TRUE(eval("absInt(x) = 4 & minInt(x, y) = -4 & maxReal(r, 0.25) = 0.5", state(-4, 2)));
  EXPECT_TRUE(eval("x ^ 3 = -8", state(-2, 0)));
  EXPECT_TRUE(eval("ite(A, x, y) = 2", state(1, 2)));
}

TEST(Evaluate, MissingNameIsAnError) {
  EXPECT_THROW(eval("Unknown", state(0, 0)), EvaluationError);
}

TEST(Evaluate, SatisfiesDomainChecksRangesEnumsAndAssumptions) {
  EXPECT_TRUE(satisfies_domain(kDomain, state(0, 0)));
  EXPECT_FALSE(satisfies_domain(kDomain, state(11, 0)));
  EXPECT_FALSE(satisfies_domain(kDomain, state(0, 0, true, true)));  // not_both
  EXPECT_FALSE(satisfies_domain(kDomain, state(0, 0, false, false, "mud")));
  State missing = state(0, 0);
  missing.pop_back();
  EXPECT_FALSE(satisfies_domain(kDomain, missing));
}

}  // namespace
}  // namespace uabt::smt
