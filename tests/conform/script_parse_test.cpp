// BT.CPP script conditions read back into FRETISH.
#include <gtest/gtest.h>

#include "conform/script_parse.hpp"

namespace uabt::conform {
namespace {

fretish::Domain exploration_domain() {
  fretish::Domain d;
  fretish::Variable battery{"battery", fretish::VarType::integer, "0", "100", {}, {}, true, ""};
  fretish::Variable slope{"slope", fretish::VarType::real, "-45", "45", {}, {}, true, ""};
  fretish::Variable terrain{
      "terrain", fretish::VarType::enumeration, "", "", {"sand", "rocks"}, {}, true, ""};
  d.variables = {battery, slope, terrain};
  return d;
}

std::string read(const std::string& code) {
  const ScriptReading r = parse_script_condition(code, exploration_domain());
  return r.expr ? fretish::to_fretish(*r.expr) : "error: " + r.error;
}

TEST(ScriptParse, CompilerOutputReadsBack) {
  EXPECT_EQ(read("battery < 20"), "battery < 20");
  EXPECT_EQ(read("terrain == 'rocks'"), "terrain = rocks");
  EXPECT_EQ(read("slope >= -15"), "slope >= -15");
  EXPECT_EQ(read("battery != 3"), "battery != 3");
  EXPECT_EQ(read("(battery + 1) * 2 <= slope / 4 - 1"), "(battery + 1) * 2 <= slope / 4 - 1");
}

TEST(ScriptParse, LogicalOperatorsShareOneLevelLeftToRight) {
  // BT.CPP's grammar: a || b && c is (a || b) && c.
  EXPECT_EQ(read("battery < 1 || battery > 5 && slope > 0"),
            "(battery < 1 | battery > 5) & slope > 0");
  // A negated relation keeps its parentheses when printed, for the reader's sake.
  EXPECT_EQ(read("!(battery < 20)"), "!(battery < 20)");
  EXPECT_EQ(read("true && battery<2"), "true & battery < 2");
}

TEST(ScriptParse, ComparisonChainsMeanEveryLink) {
  EXPECT_EQ(read("-15 <= slope <= 15"), "-15 <= slope & slope <= 15");
}

TEST(ScriptParse, AConditionalReadsAsIte) {
  EXPECT_EQ(read("(battery < 2 ? slope : 2 * slope) > 1"),
            "ite(battery < 2, slope, 2 * slope) > 1");
}

TEST(ScriptParse, RootBlackboardPrefixIsTheSameVariable) {
  const ScriptReading r =
      parse_script_condition("@battery < 20 && slope > 1", exploration_domain());
  ASSERT_TRUE(r.expr);
  EXPECT_EQ(fretish::to_fretish(*r.expr), "battery < 20 & slope > 1");
  EXPECT_EQ(r.local_reads, std::vector<std::string>{"slope"});
}

TEST(ScriptParse, SideEffectsAndUnsupportedOperatorsAreRefused) {
  for (const char* code : {"battery := 3", "battery = 3", "battery += 1", "a; b", "a .. b",
                           "battery & 1", "battery | 1", "~battery", "battery <", "(battery < 2",
                           "battery < 2)", "'unterminated", "battery # 2", "12abc > 1", ""}) {
    const ScriptReading r = parse_script_condition(code, exploration_domain());
    EXPECT_EQ(r.expr, nullptr) << code;
    EXPECT_FALSE(r.error.empty()) << code;
  }
}

TEST(ScriptParse, TheEnginesParserReadsTheCondition) {
  // One parser for the engine and for conform: what the engine reads, conform reads alike.
  EXPECT_EQ(read("battery < 0x10"), "battery < 16");
  EXPECT_EQ(read("!!(battery < 20)"), "!!(battery < 20)");
  // Its errors carry the column.
  EXPECT_EQ(read("battery <"), "error: expected an operand, found end of script (column 10)");
  EXPECT_EQ(read("battery < 2; slope > 1"),
            "error: ';' chains statements: a condition is one expression (column 14)");
  EXPECT_EQ(read("battery := 3"),
            "error: ':=' assigns to the blackboard: a condition must not (column 9)");
}

TEST(ScriptParse, EnumLiteralsAreQuotedStrings) {
  EXPECT_NE(read("terrain == rocks").find("in quotes"), std::string::npos);
  EXPECT_NE(read("terrain == 'gravel'").find("not a value"), std::string::npos);
  EXPECT_EQ(read("'sand' != terrain"), "sand != terrain");
}

}  // namespace
}  // namespace uabt::conform
