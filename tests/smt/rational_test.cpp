#include <gtest/gtest.h>

#include "smt/rational.hpp"

namespace uabt::smt {
namespace {

TEST(Rational, IntegersAndDecimalsAreExact) {
  EXPECT_EQ(parse_rational("12")->text(), "12");
  EXPECT_EQ(parse_rational("007")->text(), "7");
  EXPECT_EQ(parse_rational("-3")->text(), "-3");
  EXPECT_EQ(parse_rational("0.5")->text(), "5/10");
  EXPECT_EQ(parse_rational("20.50")->text(), "205/10");
  EXPECT_EQ(parse_rational("0.0")->text(), "0");
  EXPECT_EQ(parse_rational("-0")->text(), "0");
}

TEST(Rational, ExponentsShiftTheDecimalPoint) {
  EXPECT_EQ(parse_rational("1e3")->text(), "1000");
  EXPECT_EQ(parse_rational("2.5E-2")->text(), "25/1000");
  EXPECT_EQ(parse_rational("1.5e1")->text(), "15");
  EXPECT_TRUE(parse_rational("1e3")->is_integer());
}

TEST(Rational, RejectsWhatIsNotANumber) {
  EXPECT_FALSE(parse_rational(""));
  EXPECT_FALSE(parse_rational("."));
  EXPECT_FALSE(parse_rational("1e"));
  EXPECT_FALSE(parse_rational("abc"));
  EXPECT_FALSE(parse_rational("1.2.3"));
  EXPECT_FALSE(parse_rational("1e99999"));
}

TEST(Rational, IntegerLiteralsAreDigitsOnly) {
  EXPECT_TRUE(is_integer_literal("12"));
  EXPECT_TRUE(is_integer_literal("-12"));
  EXPECT_FALSE(is_integer_literal("12.0"));
  EXPECT_FALSE(is_integer_literal("1e3"));
  EXPECT_FALSE(is_integer_literal("-"));
}

}  // namespace
}  // namespace uabt::smt
