// The BT.CPP 4.x script language: parsing, precedence, types, errors.
#include <gtest/gtest.h>

#include "runtime/blackboard.hpp"
#include "runtime/script/program.hpp"

namespace uabt::runtime::script {
namespace {

class ScriptTest : public ::testing::Test {
 protected:
  ScriptValue run(const std::string& code) {
    programs_.push_back(Program::parse(code));
    programs_.back().bind(bb_, Blackboard::kRootScope);
    return programs_.back().run(bb_);
  }
  // The column of the error the script raises (parse or run), or 0 when none.
  std::string error_of(const std::string& code) {
    try {
      run(code);
    } catch (const ScriptError& e) {
      return std::string(e.what()) + " @" + std::to_string(e.column());
    }
    return "";
  }
  Blackboard bb_;
  std::vector<Program> programs_;
};

TEST_F(ScriptTest, ArithmeticPrecedenceAndTypes) {
  // Every operator result is a double, as BT.CPP's ExprBinaryArithmetic gives.
  EXPECT_EQ(run("1 + 2 * 3"), ScriptValue::of_real(7));
  EXPECT_EQ(run("(1 + 2) * 3"), ScriptValue::of_real(9));
  EXPECT_EQ(run("7 / 2"), ScriptValue::of_real(3.5));
  EXPECT_EQ(run("-3 + 1"), ScriptValue::of_real(-2));
  EXPECT_EQ(run("10 - 2 - 3"), ScriptValue::of_real(5));  // left-associative
  EXPECT_EQ(run("0.5 * 4"), ScriptValue::of_real(2.0));
  EXPECT_EQ(run("0x10 + 1"), ScriptValue::of_real(17));
  EXPECT_EQ(run("1e2"), ScriptValue::of_real(100.0));
  EXPECT_EQ(run("3"), ScriptValue::of_int(3));        // an integer literal stays an integer
  EXPECT_EQ(run("true"), ScriptValue::of_real(1.0));  // true/false are 1.0/0.0
}

TEST_F(ScriptTest, IntegersBeyondTwoToThe53AreNotRounded) {
  // BT.CPP's convertNumber refuses an integer a double cannot hold exactly.
  EXPECT_EQ(run("9007199254740991 + 0"), ScriptValue::of_real(9007199254740991.0));
  const std::string e = error_of("9007199254740993 + 0");
  EXPECT_NE(e.find("the integer 9007199254740993 has no exact double value"), std::string::npos)
      << e;
  EXPECT_NE(e.find("@18"), std::string::npos) << e;
  EXPECT_NE(error_of("9223372036854775807 + 1").find("no exact double"), std::string::npos);
  EXPECT_NE(error_of("-9007199254740993 < 1").find("no exact double"), std::string::npos);
  run("big := 9007199254740993; r := 0.5");
  EXPECT_NE(error_of("r = big").find("no exact double"), std::string::npos);
  EXPECT_EQ(*bb_.get("big"), ScriptValue::of_int(9007199254740993));  // kept, not rounded
  EXPECT_EQ(run("big2 := 1; big2 = big; big2"), ScriptValue::of_int(9007199254740993));
}

TEST_F(ScriptTest, ComparisonsChainAndMixStringsWithNumbers) {
  EXPECT_EQ(run("1 < 2 < 3"), ScriptValue::of_real(1.0));
  EXPECT_EQ(run("3 > 2 > 2"), ScriptValue::of_real(0.0));
  EXPECT_EQ(run("'3' == 3"), ScriptValue::of_real(1.0));
  EXPECT_EQ(run("'rocks' == 'rocks'"), ScriptValue::of_real(1.0));
  EXPECT_EQ(run("'a' < 'b'"), ScriptValue::of_real(1.0));
  EXPECT_EQ(run("0.1 + 0.2 == 0.3"), ScriptValue::of_real(1.0));  // BT.CPP's epsilon
  EXPECT_EQ(run("true == 1"), ScriptValue::of_real(1.0));
  EXPECT_NE(error_of("'rocks' < 3"), "");  // not a number
}

TEST_F(ScriptTest, LogicalOperatorsShareOneLevelLeftToRight) {
  // BT.CPP parses || and && at the same precedence: (true || false) && false.
  EXPECT_EQ(run("true || false && false"), ScriptValue::of_real(0.0));
  EXPECT_EQ(run("false && true || true"), ScriptValue::of_real(1.0));
  // '!' applies to one operand: (!true) == false.
  bb_.set("x", ScriptValue::of_bool(true));
  EXPECT_EQ(run("!x == false"), ScriptValue::of_real(1.0));
  // Both sides are evaluated (no short-circuit in BT.CPP): an undefined key is an error.
  EXPECT_NE(error_of("false && nowhere"), "");
}

TEST_F(ScriptTest, StringsConcatenateAndConditionalPicks) {
  EXPECT_EQ(run("'ab' + 'cd'"), ScriptValue::of_string("abcd"));
  EXPECT_EQ(run("'n=' .. 3"), ScriptValue::of_string("n=3"));
  bb_.set("battery", ScriptValue::of_int(15));
  EXPECT_EQ(run("battery < 20 ? 'low' : 'ok'"), ScriptValue::of_string("low"));
  EXPECT_EQ(run("6 & 3"), ScriptValue::of_real(2));
  EXPECT_EQ(run("6 | 1 ^ 2"), ScriptValue::of_real(5));
  EXPECT_EQ(run("~0"), ScriptValue::of_real(-1));
  EXPECT_EQ(run("6.0 & 3"), ScriptValue::of_real(2));  // a whole real is an integer
  EXPECT_NE(error_of("6.5 & 3").find("needs integers"), std::string::npos);
}

TEST_F(ScriptTest, AssignmentCreatesAndKeepsEntryTypes) {
  EXPECT_EQ(run("a := 1; b := a; b"), ScriptValue::of_int(1));
  EXPECT_EQ(*bb_.get("b"), ScriptValue::of_int(1));
  run("b = a + 1");  // an integral real into an int entry stays an int
  EXPECT_EQ(*bb_.get("b"), ScriptValue::of_int(2));
  run("b += 3");
  EXPECT_EQ(*bb_.get("b"), ScriptValue::of_int(5));
  run("q := a + 1");  // a new entry takes the type of its first value: a double
  EXPECT_EQ(*bb_.get("q"), ScriptValue::of_real(2.0));
  run("s := 'x'; s += 'y'");
  EXPECT_EQ(*bb_.get("s"), ScriptValue::of_string("xy"));
  run("r := 1.5; r = 2");  // an int into a real entry becomes a real
  EXPECT_EQ(*bb_.get("r"), ScriptValue::of_real(2.0));
  run("n := 0; n = '7'");  // a numeric string into a number entry (BT.CPP's StringToDouble)
  EXPECT_EQ(*bb_.get("n"), ScriptValue::of_int(7));

  EXPECT_NE(error_of("b = 2.5").find("cannot assign 2.5"), std::string::npos);
  EXPECT_NE(error_of("b = 'abc'"), "");
  EXPECT_NE(error_of("s = 3"), "");
  EXPECT_NE(error_of("b /= 2").find("cannot assign 2.5"), std::string::npos);
  EXPECT_NE(error_of("fresh = 1").find("use ':='"), std::string::npos);
  EXPECT_NE(error_of("fresh2 += 1").find("not initialized"), std::string::npos);
}

TEST_F(ScriptTest, UndefinedKeyIsAnErrorNamingIt) {
  const std::string e = error_of("battery2 < 20");
  EXPECT_NE(e.find("undefined blackboard key 'battery2'"), std::string::npos) << e;
  EXPECT_NE(e.find("@1"), std::string::npos) << e;
}

TEST_F(ScriptTest, ParseErrorsCarryTheColumn) {
  EXPECT_EQ(error_of("a +"), "expected an operand, found end of script @4");
  EXPECT_NE(error_of("1 = 2").find("must be a blackboard key"), std::string::npos);
  EXPECT_NE(error_of("!a + 1").find("cannot be mixed"), std::string::npos);
  EXPECT_NE(error_of("a & b + c").find("cannot be mixed"), std::string::npos);
  EXPECT_EQ(run("a := 1; (!a) + 1"), ScriptValue::of_real(1));  // parenthesized: fine
  EXPECT_NE(error_of("x == \"rocks\"").find("single quotes"), std::string::npos);
  EXPECT_NE(error_of("'open").find("unterminated"), std::string::npos);
  EXPECT_NE(error_of("a ? 1 : 2 ? 3 : 4").find("chained"), std::string::npos);
  EXPECT_NE(error_of("1 2"), "");
  EXPECT_NE(error_of("12abc").find("malformed number"), std::string::npos);
}

TEST_F(ScriptTest, NestingIsBounded) {
  const std::string deep = std::string(500, '(') + "1" + std::string(500, ')');
  EXPECT_NE(error_of(deep).find("nested"), std::string::npos);
  std::string chain = "1";
  for (int i = 0; i < 300; ++i) chain += " + 1";
  EXPECT_NE(error_of(chain).find("nested deeper"), std::string::npos);
  std::string ok = "1";
  for (int i = 0; i < 100; ++i) ok += " + 1";
  EXPECT_EQ(run(ok), ScriptValue::of_real(101));
}

TEST_F(ScriptTest, EmptyStatementsAndNames) {
  EXPECT_TRUE(run("").empty());
  EXPECT_EQ(run("a := 1;; a;"), ScriptValue::of_int(1));
  const Program p = Program::parse("x := y + y * z");
  EXPECT_EQ(p.names(), (std::vector<std::string>{"x", "y", "z"}));
}

TEST_F(ScriptTest, NestedAssignmentReadsValuesInOrder) {
  run("s := 'ab'");
  // The left operand is read before the right one changes the entry.
  EXPECT_EQ(run("s .. (s = 'a much longer string than before')"),
            ScriptValue::of_string("aba much longer string than before"));
}

TEST_F(ScriptTest, LogicOperatorsTakeIntegersOnlyWhenZeroOrOne) {
  bb_.set("x", ScriptValue::of_int(2));
  bb_.set("one", ScriptValue::of_int(1));
  bb_.set("b", ScriptValue::of_bool(false));
  // BT.CPP casts each operand to bool: an integer other than 0 and 1 throws.
  const std::string e = error_of("x && b");
  EXPECT_NE(e.find("operator [&&] takes an integer only when it is 0 or 1, not 2"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("@3"), std::string::npos) << e;
  EXPECT_NE(error_of("b || x").find("[||]"), std::string::npos);
  EXPECT_EQ(run("one && true"), ScriptValue::of_real(1.0));
  EXPECT_EQ(run("2.5 && true"), ScriptValue::of_real(1.0));  // a real is true when not 0
  EXPECT_EQ(run("x > 1 && true"), ScriptValue::of_real(1.0));
}

TEST_F(ScriptTest, ChainedAssignmentAssignsRightToLeft) {
  EXPECT_EQ(run("r := y := 3"), ScriptValue::of_int(3));
  EXPECT_EQ(*bb_.get("r"), ScriptValue::of_int(3));
  EXPECT_EQ(*bb_.get("y"), ScriptValue::of_int(3));
  run("r = y = 5");
  EXPECT_EQ(*bb_.get("r"), ScriptValue::of_int(5));
  EXPECT_EQ(*bb_.get("y"), ScriptValue::of_int(5));
}

TEST_F(ScriptTest, ResultTypesFollowTheFirstValue) {
  bb_.set("x", ScriptValue::of_int(3));
  run("r := x + 1; r := 2.5");  // r is a double from its first value on
  EXPECT_EQ(*bb_.get("r"), ScriptValue::of_real(2.5));
  run("c := x > 1; c := c + 1");
  EXPECT_EQ(*bb_.get("c"), ScriptValue::of_real(2.0));
  run("t := true; t := 5");
  EXPECT_EQ(*bb_.get("t"), ScriptValue::of_real(5.0));
}

TEST_F(ScriptTest, AnIntegerIntoABooleanEntryIsKept) {
  // BT.CPP's Any keeps bool and int alike as int64: the entry holds the integer, and stays
  // typed bool (a later 1 is the boolean true again).
  bb_.set("b0", ScriptValue::of_bool(true));
  bb_.set("x", ScriptValue::of_int(3));
  run("b0 := x");
  ScriptValue three_in_bool = ScriptValue::of_int(3);
  three_in_bool.bool_entry = true;
  EXPECT_EQ(*bb_.get("b0"), three_in_bool);
  EXPECT_EQ(bb_.get("b0")->to_string(), "3");
  run("b0 := 1");
  EXPECT_EQ(*bb_.get("b0"), ScriptValue::of_bool(true));
  bb_.set("b1", ScriptValue::of_bool(true));
  run("b1 := 0");
  EXPECT_EQ(*bb_.get("b1"), ScriptValue::of_bool(false));
  run("b1 := x > 1");  // the double 1.0 is the boolean true
  EXPECT_EQ(*bb_.get("b1"), ScriptValue::of_bool(true));
  EXPECT_NE(error_of("b1 := 2.5").find("cannot assign 2.5 (real) to 'b1', which holds a bool"),
            std::string::npos);
}

}  // namespace
}  // namespace uabt::runtime::script
