// Type checking of guards: ref-type-mismatch findings and identifier resolution.
#include <gtest/gtest.h>

#include "smt/expr_support.hpp"
#include "smt/types.hpp"

namespace uabt::smt {
namespace {

using testing::domain;
using testing::expr;

const char* const kDomain =
    "boolean OnDust, OnRocks\n"
    "integer battery in [0, 100]\n"
    "real slope in [-45, 45]\n"
    "enum terrain in {dust, rocks, sand, mud}\n"
    "enum level in {low, high}\n";

struct Checked {
  bool ok;
  std::vector<Finding> findings;
  Typing typing;
};

Checked check(const fretish::ExprPtr& e, const fretish::Domain& d) {
  Checked c;
  c.ok = check_condition(*e, d, {"requirements.fret", 1, 1}, c.typing, c.findings);
  return c;
}

class TypesTest : public ::testing::Test {
 protected:
  fretish::Domain d = domain(kDomain);

  void expect_mismatch(const std::string& text, const std::string& fragment, int column = 0) {
    SCOPED_TRACE(text);
    const Checked c = check(expr(text), d);
    EXPECT_FALSE(c.ok);
    ASSERT_EQ(c.findings.size(), 1u);
    EXPECT_EQ(c.findings[0].check, "ref-type-mismatch");
    EXPECT_NE(c.findings[0].message.find(fragment), std::string::npos) << c.findings[0].message;
    EXPECT_EQ(c.findings[0].location.file, "requirements.fret");
    if (column > 0) {
      EXPECT_EQ(c.findings[0].location.column, column);
    }
  }
  void expect_well_typed(const std::string& text) {
    SCOPED_TRACE(text);
    const Checked c = check(expr(text), d);
    EXPECT_TRUE(c.ok);
    EXPECT_TRUE(c.findings.empty()) << c.findings.front().message;
  }
};

TEST_F(TypesTest, WellTypedGuards) {
  expect_well_typed("OnDust & !OnRocks");
  expect_well_typed("terrain = rocks");
  expect_well_typed("rocks = terrain");
  expect_well_typed("terrain != mud | level = high");
  expect_well_typed("battery + 1 < slope * 2");
  expect_well_typed("battery mod 3 = 0");
  expect_well_typed("absInt(battery - 50) <= 10 & absReal(slope) < 20.5");
  expect_well_typed("minInt(battery, 10) = maxInt(battery, 10)");
  expect_well_typed("ite(OnDust, battery, 3) > 2");
  expect_well_typed("ite(OnDust, rocks, dust) = terrain");
  expect_well_typed("UndeclaredCondition | OnDust");
  expect_well_typed("OnDust = OnRocks");
  expect_well_typed("battery ^ 2 > 100");
}

TEST_F(TypesTest, EnumComparedWithANumber) {
  expect_mismatch("terrain = 3", "cannot compare 'terrain'", 1);
}

TEST_F(TypesTest, BooleanOrderedWithLessThan) {
  expect_mismatch("OnDust < OnRocks", "'<' needs numbers; 'OnDust' is a boolean", 1);
}

TEST_F(TypesTest, ArithmeticOnBooleans) {
  expect_mismatch("OnDust + 1 > 2", "'+' needs numbers; 'OnDust' is a boolean");
}

TEST_F(TypesTest, NumericUseOfAnUndeclaredName) {
  expect_mismatch("speed > 2", "'speed' is used as a number but is not declared");
}

TEST_F(TypesTest, EqualityOfUndeclaredNamesIsNotGuessed) {
  expect_mismatch("gear = fast", "'gear' is compared but not declared", 1);
  expect_well_typed("OnDust = Undeclared");  // the other side says it is a condition
}

TEST_F(TypesTest, ConditionTheLoaderInferredUsedAsANumber) {
  fretish::Variable inferred;
  inferred.name = "speed";
  inferred.declared = false;  // the loader saw it as a condition elsewhere
  d.variables.push_back(inferred);
  expect_mismatch("speed > 2", "'speed' is used as a number but is not declared");
}

TEST_F(TypesTest, LiteralOfAnotherEnum) {
  expect_mismatch("terrain = high", "'high' is a literal of enum level, not of an enum {dust");
  expect_mismatch("level = rocks",
                  "'rocks' is a literal of enum terrain, not of an enum {low, high}", 9);
}

TEST_F(TypesTest, NumberUsedAsACondition) {
  expect_mismatch("battery & OnDust",
                  "'battery' is an integer, but a logical operator needs a condition", 1);
  expect_mismatch("battery + 1", "is an integer, not true/false");
}

TEST_F(TypesTest, EnumLiteralUsedAsACondition) {
  expect_mismatch("rocks", "is a literal of enum terrain");
}

TEST_F(TypesTest, ModOfARealAndUnknownFunctions) {
  expect_mismatch("slope mod 2 = 0", "'mod' needs integers");
  expect_mismatch("sqrt(battery) > 2", "'sqrt' is not a function");
  expect_mismatch("absInt(slope) > 2", "'absInt' needs integers");
  expect_mismatch("ite(OnDust, battery, terrain) > 2", "branches");
}

TEST_F(TypesTest, MismatchIsLocatedAtTheOffendingSubExpression) {
  // "OnDust & " is 9 characters: the comparison starts at column 10.
  expect_mismatch("OnDust & terrain < 2", "'<' needs numbers", 10);
}

TEST_F(TypesTest, DivisionByLiteralZeroIsAnErrorButStillTyped) {
  // Well typed (the solver can still reason about the rest), but a guard that divides by zero
  // means nothing on board: the finding is an error, so the gate fails closed.
  const Checked c = check(expr("battery / 0 > 2"), d);
  EXPECT_TRUE(c.ok);
  ASSERT_EQ(c.findings.size(), 1u);
  EXPECT_EQ(c.findings[0].check, "arith-division-by-zero");
  EXPECT_EQ(c.findings[0].severity, Severity::error);
  EXPECT_TRUE(check(expr("battery / 2 > 2"), d).findings.empty());
}

TEST_F(TypesTest, IdentifiersResolveToVariablesLiteralsAndImplicitBooleans) {
  const auto e = expr("terrain = rocks & Fresh & battery < 20.5");
  const Checked c = check(e, d);
  ASSERT_TRUE(c.ok);
  const auto& eq = *e->args[0];
  EXPECT_EQ(c.typing.at(*eq.args[0]).variable->name, "terrain");
  EXPECT_EQ(c.typing.at(*eq.args[1]).enum_index, 1);
  EXPECT_TRUE(c.typing.at(*e->args[1]).implicit_boolean);
  EXPECT_EQ(c.typing.at(*e->args[2]->args[1]).sort, Sort::real);
  EXPECT_EQ(c.typing.at(*e->args[2]->args[0]).sort, Sort::integer);
}

}  // namespace
}  // namespace uabt::smt
