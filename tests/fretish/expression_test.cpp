// Expressions: precedence, associativity, atoms, to_fretish round trips, nesting limits.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fretish/parse.hpp"
#include "fretish_test_support.hpp"

namespace uabt::testing {
namespace {

using fretish::ExprKind;
using fretish::ExprPtr;

TEST(FretishExpression, BooleanPrecedenceFollowsFretFormalization) {
  EXPECT_EQ(grouped("!a & b"), "((!a) & b)");
  EXPECT_EQ(grouped("a & b | c"), "((a & b) | c)");
  EXPECT_EQ(grouped("a | b & c"), "(a | (b & c))");
  EXPECT_EQ(grouped("a xor b | c"), "(a xor (b | c))");
  EXPECT_EQ(grouped("a | b xor c"), "((a | b) xor c)");
  EXPECT_EQ(grouped("a xor b xor c"), "((a xor b) xor c)");
  EXPECT_EQ(grouped("a -> b -> c"), "(a -> (b -> c))");
  EXPECT_EQ(grouped("a => b => c"), "(a -> (b -> c))");
  EXPECT_EQ(grouped("a <-> b -> c"), "(a <-> (b -> c))");
  EXPECT_EQ(grouped("a -> b <-> c"), "((a -> b) <-> c)");
  EXPECT_EQ(grouped("a <=> b <=> c"), "((a <-> b) <-> c)");
  EXPECT_EQ(grouped("a xor b -> c"), "((a xor b) -> c)");
  EXPECT_EQ(grouped("~a | !b"), "((!a) | (!b))");
  EXPECT_EQ(grouped("!!a"), "(!(!a))");
  EXPECT_EQ(grouped("a & b & c"), "(a & b & c)");
  EXPECT_EQ(grouped("(a & b) & c"), "((a & b) & c)");
}

TEST(FretishExpression, IfThenIsImplication) {
  EXPECT_EQ(grouped("if a then b"), "(a -> b)");
  EXPECT_EQ(grouped("if a then b | c"), "(a -> (b | c))");
  EXPECT_EQ(grouped("IF ! liquid_level_1 THEN valve_0"), "((!liquid_level_1) -> valve_0)");
}

// FRET rewrites `if A then B` to `A => B` before formalizing (SemanticsAnalyzer's
// enterPre_condition / enterPost_condition), so `then` binds like `->`, looser than `&`, `|`
// and `xor`, and tighter than `<->`.
TEST(FretishExpression, IfThenInsideAnExpressionReadsAsFretRewritesIt) {
  EXPECT_EQ(grouped("q & if p then r"), "((q & p) -> r)");
  EXPECT_EQ(grouped("a | if p then r | b"), "((a | p) -> (r | b))");
  EXPECT_EQ(grouped("a xor if p then r"), "((a xor p) -> r)");
  EXPECT_EQ(grouped("if a then b <-> c"), "((a -> b) <-> c)");
  EXPECT_EQ(grouped("if a then if b then c"), "(a -> (b -> c))");
  EXPECT_EQ(grouped("(q & if p then r) | s"), "(((q & p) -> r) | s)");
  EXPECT_EQ(grouped("f(q & if p then r) & s"), "(f(((q & p) -> r)) & s)");
}

// FRET's NUMBER token carries its sign: `-1 ^ 2` is (-1) ^ 2; with a space it is a negation.
TEST(FretishExpression, SignedNumberUnderPower) {
  EXPECT_EQ(grouped("x > -1 ^ 2"), "(x > ((-1) ^ 2))");
  EXPECT_EQ(grouped("-2 ^ 2"), "((-2) ^ 2)");
  EXPECT_EQ(grouped("- 1 ^ 2"), "(-(1 ^ 2))");
  EXPECT_EQ(grouped("-x ^ 2"), "(-(x ^ 2))");
  EXPECT_EQ(grouped("2 ^ -1 ^ 2"), "(2 ^ ((-1) ^ 2))");
  // Between operands '-' is a subtraction: x-1 is x minus 1.
  EXPECT_EQ(grouped("x-1 ^ 2"), "(x - (1 ^ 2))");
  EXPECT_EQ(fretish::to_fretish(*expr("- 1 ^ 2")), "- 1 ^ 2");
  EXPECT_EQ(fretish::to_fretish(*expr("-1 ^ 2")), "(-1) ^ 2");
}

TEST(FretishExpression, RelationsAndNegation) {
  EXPECT_EQ(grouped("x > 3"), "(x > 3)");
  EXPECT_EQ(grouped("!x > 3"), "(!(x > 3))");
  EXPECT_EQ(grouped("a = b & c != d"), "((a = b) & (c != d))");
  EXPECT_EQ(grouped("a == b"), "(a = b)");
  EXPECT_EQ(grouped("a<=b | a>=c | a<b | a>c"), "((a <= b) | (a >= c) | (a < b) | (a > c))");
  EXPECT_EQ(grouped("a<-1"), "(a < (-1))");
  EXPECT_EQ(grouped("a<->b"), "(a <-> b)");
}

TEST(FretishExpression, ArithmeticPrecedence) {
  EXPECT_EQ(grouped("x-1 > 0"), "((x - 1) > 0)");
  EXPECT_EQ(grouped("x - -1 > 0"), "((x - (-1)) > 0)");
  EXPECT_EQ(grouped("-x ^ 2"), "(-(x ^ 2))");
  EXPECT_EQ(grouped("2 ^ 3 ^ 2"), "(2 ^ (3 ^ 2))");
  EXPECT_EQ(grouped("x ^ -y ^ 2"), "(x ^ (-(y ^ 2)))");
  EXPECT_EQ(grouped("(-x) ^ 2"), "((-x) ^ 2)");
  EXPECT_EQ(grouped("a + b * c"), "(a + (b * c))");
  EXPECT_EQ(grouped("a - b - c"), "((a - b) - c)");
  EXPECT_EQ(grouped("a / b mod c * d"), "(((a / b) mod c) * d)");
  EXPECT_EQ(grouped("a + b < c * d"), "((a + b) < (c * d))");
  EXPECT_EQ(grouped("--x"), "(-(-x))");
}

TEST(FretishExpression, Atoms) {
  ExprPtr e = expr("absReal(x - 1, ite(c, 1, 2)) >= 0.5e-3");
  ASSERT_TRUE(e);
  EXPECT_EQ(grouped(*e), "(absReal((x - 1), ite(c, 1, 2)) >= 0.5e-3)");
  EXPECT_EQ(e->args[0]->kind, ExprKind::call);
  EXPECT_EQ(e->args[0]->text, "absReal");
  EXPECT_EQ(e->args[1]->kind, ExprKind::number);
  EXPECT_EQ(e->args[1]->text, "0.5e-3");

  EXPECT_EQ(grouped("f()"), "f()");
  EXPECT_EQ(grouped("TRUE & False"), "(true & false)");
  EXPECT_EQ(grouped("sensor.temp% > 3"), "(sensor.temp% > 3)");

  ExprPtr quoted = expr("\"battery level\" < 20 & \"a \\\"b\\\"\"");
  ASSERT_TRUE(quoted);
  EXPECT_EQ(quoted->args[0]->args[0]->text, "battery level");
  EXPECT_EQ(quoted->args[1]->text, "a \"b\"");
  // A quoted keyword is an ordinary identifier.
  EXPECT_EQ(expr("\"then\"")->text, "then");

  EXPECT_EQ(grouped("at the previous occurrence of a, b"), "prevOcc(a, b)");
  EXPECT_EQ(grouped("at the next occurrence of a & c, b"), "nextOcc((a & c), b)");
}

TEST(FretishExpression, RangesAreFilePositions) {
  std::vector<Finding> findings;
  ExprPtr e = fretish::parse_expression("a &\n  (b | c)", test_origin(10, 5), findings);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->range.begin_line, 10);
  EXPECT_EQ(e->range.begin_column, 5);
  EXPECT_EQ(e->range.end_line, 11);
  EXPECT_EQ(e->range.end_column, 9);
  const fretish::Expr& paren = *e->args[1];
  EXPECT_TRUE(paren.parenthesized);
  EXPECT_EQ(paren.kind, ExprKind::logical_or);
  EXPECT_EQ(paren.range.begin_line, 11);
  EXPECT_EQ(paren.range.begin_column, 3);
  EXPECT_EQ(paren.args[1]->range.begin_column, 8);
  EXPECT_EQ(paren.args[1]->range.end_column, 8);
}

TEST(FretishExpression, IdentifiersInFirstOccurrenceOrder) {
  ExprPtr e = expr("f(b, a) & a | c > b");
  ASSERT_TRUE(e);
  EXPECT_EQ(fretish::identifiers_of(*e), (std::vector<std::string>{"b", "a", "c"}));
}

TEST(FretishExpression, SameExprIgnoresParenthesesAndRanges) {
  EXPECT_TRUE(fretish::same_expr(*expr("(a & b)"), *expr("a&b")));
  EXPECT_FALSE(fretish::same_expr(*expr("a & b"), *expr("b & a")));
  EXPECT_FALSE(fretish::same_expr(*expr("(a & b) & c"), *expr("a & b & c")));
  EXPECT_FALSE(fretish::same_expr(*expr("x = 1"), *expr("x = 1.0")));
  EXPECT_FALSE(fretish::same_expr(*expr("true"), *expr("false")));
}

TEST(FretishExpression, ToFretishRoundTrips) {
  const std::vector<std::string> cases = {
      "a",
      "!a & b",
      "!(a & b)",
      "a & b & c",
      "(a & b) & c",
      "a & (b & c)",
      "a | b & c",
      "(a | b) & c",
      "a xor b | c",
      "(a xor b) | c",
      "a xor (b xor c)",
      "a -> b -> c",
      "(a -> b) -> c",
      "a <-> b -> c",
      "(a <-> b) <-> c",
      "a <-> (b <-> c)",
      "if a then b",
      "q & if p then r",
      "-1 ^ 2 < x",
      "- 1 ^ 2 < x",
      "x - 1 > 0",
      "x - (y - z) = 0",
      "-x ^ 2 < 4",
      "(-x) ^ 2",
      "2 ^ 3 ^ 2",
      "(2 ^ 3) ^ 2",
      "x ^ -y",
      "--x = x",
      "x - -y = 1",
      "a * (b + c) mod 3 >= d / e",
      "!(x > 3) | (y <= 2)",
      "(a = b) = c",
      "absReal(x - 1) < 0.5",
      "ite(c, a + 1, -b) != 0",
      "\"battery level\" < 20",
      "\"then\" & \"x\\\"y\"",
      "true xor FALSE",
      "at the previous occurrence of a, b & c",
      "!!a",
      "!a = b",
  };
  for (const std::string& text : cases) {
    ExprPtr original = expr(text);
    ASSERT_TRUE(original) << text;
    const std::string printed = fretish::to_fretish(*original);
    std::vector<Finding> findings;
    ExprPtr reparsed = fretish::parse_expression(printed, test_origin(), findings);
    ASSERT_TRUE(reparsed) << text << " printed as " << printed;
    EXPECT_TRUE(fretish::same_expr(*original, *reparsed)) << text << " printed as " << printed;
    // The printed form never needs a precedence warning.
    EXPECT_TRUE(findings.empty()) << printed << ": " << findings.front().message;
  }
}

TEST(FretishExpression, ToFretishParenthesizesOnlyWhereNeeded) {
  EXPECT_EQ(fretish::to_fretish(*expr("((a & (b)))")), "a & b");
  EXPECT_EQ(fretish::to_fretish(*expr("(a | b) & !(c)")), "(a | b) & !c");
  EXPECT_EQ(fretish::to_fretish(*expr("a xor b | c")), "a xor (b | c)");
  EXPECT_EQ(fretish::to_fretish(*expr("if a then b")), "a -> b");
  EXPECT_EQ(fretish::to_fretish(*expr("x-1>0")), "x - 1 > 0");
  EXPECT_EQ(fretish::to_fretish(*fretish::make_identifier("in")), "\"in\"");
}

TEST(FretishExpression, BuildersAndClassifiers) {
  auto sum =
      fretish::make_expr(ExprKind::add, {fretish::make_identifier("x"), fretish::make_number("2")});
  EXPECT_EQ(
      fretish::to_fretish(*fretish::make_expr(ExprKind::gt, {sum, fretish::make_bool(false)})),
      "x + 2 > false");
  EXPECT_TRUE(fretish::is_boolean_connective(ExprKind::logical_xor));
  EXPECT_FALSE(fretish::is_boolean_connective(ExprKind::eq));
  EXPECT_TRUE(fretish::is_relation(ExprKind::ge));
  EXPECT_FALSE(fretish::is_relation(ExprKind::add));
  EXPECT_TRUE(fretish::is_arithmetic(ExprKind::negate));
  EXPECT_FALSE(fretish::is_arithmetic(ExprKind::logical_not));
}

TEST(FretishExpression, PrecedenceWarningOnlyOnUnparenthesizedMixes) {
  struct Case {
    std::string text;
    int warnings;
    int column;  // of the outer operator
  };
  const std::vector<Case> cases = {
      {"a xor b | c", 1, 3},   {"a | b xor c", 1, 7},    {"a -> b <-> c", 1, 8},
      {"a <-> b -> c", 1, 3},  {"a <=> b => c", 1, 3},   {"a xor (b | c)", 0, 0},
      {"(a xor b) | c", 0, 0}, {"a <-> (b -> c)", 0, 0}, {"(a -> b) <-> c", 0, 0},
      {"a xor b xor c", 0, 0}, {"a | b | c", 0, 0},      {"a -> b -> c", 0, 0},
      {"a xor b & c", 0, 0},   {"a <-> b xor c", 0, 0},
  };
  for (const Case& c : cases) {
    std::vector<Finding> findings;
    ASSERT_TRUE(fretish::parse_expression(c.text, test_origin(), findings)) << c.text;
    const auto warnings = findings_of(findings, "fretish-precedence");
    ASSERT_EQ(static_cast<int>(warnings.size()), c.warnings) << c.text;
    EXPECT_EQ(findings.size(), warnings.size()) << c.text;
    if (c.warnings > 0) {
      EXPECT_EQ(warnings[0].severity, Severity::warning);
      EXPECT_EQ(warnings[0].location.line, 1);
      EXPECT_EQ(warnings[0].location.column, c.column) << c.text;
    }
  }
}

TEST(FretishExpression, DeepNestingIsAnErrorNotACrash) {
  {
    std::vector<Finding> findings;
    const std::string text = std::string(100000, '(') + "a" + std::string(100000, ')');
    EXPECT_EQ(fretish::parse_expression(text, test_origin(), findings), nullptr);
    ASSERT_EQ(findings.size(), 1u);
    EXPECT_EQ(findings[0].check, "fretish-syntax");
    EXPECT_NE(findings[0].message.find("nesting deeper than 200"), std::string::npos);
    EXPECT_EQ(findings[0].location.column, 201);
  }
  {
    // 200 levels are fine.
    std::vector<Finding> findings;
    const std::string text = std::string(199, '(') + "a" + std::string(199, ')');
    EXPECT_NE(fretish::parse_expression(text, test_origin(), findings), nullptr);
    EXPECT_TRUE(findings.empty());
  }
  for (const std::string& prefix :
       {std::string("if a then "), std::string("f("), std::string("!("), std::string("-(")}) {
    std::vector<Finding> findings;
    std::string text;
    for (int i = 0; i < 5000; ++i) text += prefix;
    text += "b";
    EXPECT_EQ(fretish::parse_expression(text, test_origin(), findings), nullptr) << prefix;
    ASSERT_FALSE(findings.empty()) << prefix;
    EXPECT_NE(findings[0].message.find("nesting deeper than 200"), std::string::npos);
  }
  // Long flat chains do not recurse in the parser; the AST depth is bounded.
  for (const std::string& op : {std::string("!"), std::string("-")}) {
    std::vector<Finding> findings;
    std::string text;
    for (int i = 0; i < 5000; ++i) text += op;
    EXPECT_EQ(fretish::parse_expression(text + "x", test_origin(), findings), nullptr);
    ASSERT_EQ(findings.size(), 1u);
    EXPECT_NE(findings[0].message.find("deeper than 1000"), std::string::npos);
  }
  {
    std::vector<Finding> findings;
    std::string text = "a";
    for (int i = 0; i < 3000; ++i) text += " -> a";
    EXPECT_EQ(fretish::parse_expression(text, test_origin(), findings), nullptr);
    ASSERT_EQ(findings.size(), 1u);
  }
  {
    std::vector<Finding> findings;
    std::string text = "a";
    for (int i = 0; i < 5000; ++i) text += " & a";
    ExprPtr flat = fretish::parse_expression(text, test_origin(), findings);
    ASSERT_TRUE(flat);
    EXPECT_EQ(flat->args.size(), 5001u);
  }
}

}  // namespace
}  // namespace uabt::testing
