// domain.fret: declarations, assumptions, domain-invalid and fretish-syntax findings.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/parse.hpp"
#include "fretish_test_support.hpp"

namespace uabt::testing {
namespace {

using fretish::VarType;

TEST(FretishDomain, DesignExample) {
  const std::string content =
      "# terrain classifier outputs\r\n"
      "boolean OnDust, OnRocks, OnSand, OnMud\r\n"
      "integer battery in [0, 100]   # percent\r\n"
      "real slope in [-45, 45.5]\r\n"
      "\r\n"
      "enum terrain in {dust, rocks, sand, mud}\r\n"
      "integer n\r\n"
      "unsigned integer k\r\n"
      "double x in [-0.5, 1e3]\r\n"
      "assume one_terrain: !(OnDust & OnRocks)\r\n"
      "assume low-battery: battery >= 5 | terrain = dust\r\n";
  std::vector<Finding> findings;
  fretish::Domain d = fretish::parse_domain_file(content, "domain.fret", findings);
  EXPECT_TRUE(findings.empty()) << findings.front().message;
  ASSERT_EQ(d.variables.size(), 10u);
  EXPECT_EQ(d.variables[0].name, "OnDust");
  EXPECT_EQ(d.variables[3].name, "OnMud");
  EXPECT_EQ(d.variables[3].type, VarType::boolean);
  EXPECT_EQ(d.variables[3].location.line, 2);
  EXPECT_EQ(d.variables[3].location.column, 34);

  const fretish::Variable* battery = d.find("battery");
  ASSERT_NE(battery, nullptr);
  EXPECT_EQ(battery->type, VarType::integer);
  EXPECT_EQ(battery->lower, "0");
  EXPECT_EQ(battery->upper, "100");
  EXPECT_TRUE(battery->declared);

  const fretish::Variable* slope = d.find("slope");
  EXPECT_EQ(slope->type, VarType::real);
  EXPECT_EQ(slope->lower, "-45");
  EXPECT_EQ(slope->upper, "45.5");

  const fretish::Variable* terrain = d.find("terrain");
  EXPECT_EQ(terrain->type, VarType::enumeration);
  EXPECT_EQ(terrain->enum_values, (std::vector<std::string>{"dust", "rocks", "sand", "mud"}));
  EXPECT_EQ(d.enum_owning("rocks"), terrain);
  EXPECT_EQ(d.enum_owning("gravel"), nullptr);

  EXPECT_EQ(d.find("n")->lower, "");
  EXPECT_EQ(d.find("n")->upper, "");
  EXPECT_EQ(d.find("k")->lower, "0");
  EXPECT_EQ(d.find("k")->upper, "");
  EXPECT_EQ(d.find("x")->type, VarType::real);
  EXPECT_EQ(d.find("x")->upper, "1e3");
  EXPECT_EQ(d.find("nothing"), nullptr);

  ASSERT_EQ(d.assumptions.size(), 2u);
  EXPECT_EQ(d.assumptions[0].name, "one_terrain");
  EXPECT_EQ(fretish::to_fretish(*d.assumptions[0].expr), "!(OnDust & OnRocks)");
  EXPECT_EQ(d.assumptions[0].location.line, 10);
  EXPECT_EQ(d.assumptions[0].expr->range.begin_column, 21);
  EXPECT_EQ(d.assumptions[1].name, "low-battery");
  EXPECT_STREQ(fretish::var_type_name(VarType::enumeration), "enum");
  EXPECT_STREQ(fretish::var_type_name(VarType::real), "real");
}

TEST(FretishDomain, UnsignedWithDecimalExponentBoundIsInvalid) {
  std::vector<Finding> findings;
  fretish::Domain d =
      fretish::parse_domain_file("unsigned integer j in [+2, 1e1]\n", "domain.fret", findings);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].check, "domain-invalid");
  EXPECT_EQ(findings[0].location.column, 28);
  ASSERT_NE(d.find("j"), nullptr);
  EXPECT_EQ(d.find("j")->lower, "0");  // the invalid range is dropped; unsigned stays >= 0
}

struct InvalidCase {
  std::string content;
  int line;
  int column;
  std::string message_part;
};

TEST(FretishDomain, DomainInvalidFindings) {
  const std::vector<InvalidCase> cases = {
      {"boolean a, b\ninteger b in [0, 1]", 2, 9, "'b' is already declared at line 1"},
      {"boolean a, a", 1, 12, "'a' is already declared"},
      {"integer battery in [100, 0]", 1, 21, "lower bound 100 exceeds upper bound 0"},
      {"real r in [1.5, -1.5]", 1, 12, "lower bound 1.5 exceeds upper bound -1.5"},
      {"integer i in [0.5, 3]", 1, 15, "not a whole number"},
      {"unsigned integer u in [-1, 3]", 1, 24, "negative lower bound -1"},
      {"enum terrain in {}", 1, 6, "enum 'terrain' has no literals"},
      {"enum t in {a, b, a}", 1, 18, "'a' appears twice in 't'"},
      {"boolean rocks\nenum terrain in {dust, rocks}", 2, 24, "also the name of a variable"},
      {"enum terrain in {dust, rocks}\nboolean dust", 1, 18, "also the name of a variable"},
      {"enum terrain in {dust, rocks}\nenum surface in {rocks, ice}", 2, 18,
       "'rocks' of 'surface' is also a literal of 'terrain'"},
      {"assume a1: x\nassume a1: y", 2, 8, "assumption 'a1' is already declared at line 1"},
  };
  for (const InvalidCase& c : cases) {
    std::vector<Finding> findings;
    fretish::parse_domain_file(c.content, "domain.fret", findings);
    ASSERT_EQ(findings.size(), 1u) << c.content;
    EXPECT_EQ(findings[0].check, "domain-invalid") << c.content;
    EXPECT_EQ(findings[0].severity, Severity::error);
    EXPECT_EQ(findings[0].location.file, "domain.fret");
    EXPECT_EQ(findings[0].location.line, c.line) << c.content << ": " << findings[0].message;
    EXPECT_EQ(findings[0].location.column, c.column) << c.content << ": " << findings[0].message;
    EXPECT_NE(findings[0].message.find(c.message_part), std::string::npos)
        << c.content << ": " << findings[0].message;
  }
}

TEST(FretishDomain, SyntaxErrors) {
  const std::vector<InvalidCase> cases = {
      {"boolean a b", 1, 11, "expected ',' or end of line, found 'b'"},
      {"bool a", 1, 1, "expected a declaration or end of line, found 'bool'"},
      {"integer x in [0 100]", 1, 17, "expected ','"},
      {"integer x in [0, 100", 1, 21, "expected ']'"},
      {"integer x in 0, 100", 1, 14, "expected '['"},
      {"integer x 5", 1, 11, "expected ',', 'in' or end of line"},
      {"enum t {a, b}", 1, 8, "expected 'in'"},
      {"enum t in {a b}", 1, 14, "expected ',' or '}'"},
      {"boolean in", 1, 9, "expected a variable name, found keyword 'in'"},
      {"assume a: x &", 1, 14, "expected an expression after '&'"},
      {"assume : x", 1, 8, "expected an assumption name"},
      {"boolean ok\n\n  real r in [a, b]", 3, 14, "expected a number"},
  };
  for (const InvalidCase& c : cases) {
    std::vector<Finding> findings;
    fretish::parse_domain_file(c.content, "domain.fret", findings);
    ASSERT_EQ(findings.size(), 1u) << c.content;
    EXPECT_EQ(findings[0].check, "fretish-syntax") << c.content;
    EXPECT_EQ(findings[0].location.line, c.line) << c.content << ": " << findings[0].message;
    EXPECT_EQ(findings[0].location.column, c.column) << c.content << ": " << findings[0].message;
    EXPECT_NE(findings[0].message.find(c.message_part), std::string::npos)
        << c.content << ": " << findings[0].message;
  }
}

TEST(FretishDomain, ErrorsDoNotStopLaterLines) {
  std::vector<Finding> findings;
  fretish::Domain d = fretish::parse_domain_file(
      "boolean a\nthis is not a declaration\nboolean b # ok\n", "domain.fret", findings);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].location.line, 2);
  ASSERT_EQ(d.variables.size(), 2u);
  EXPECT_EQ(d.variables[1].name, "b");
}

// `tick 100 ms`: the tick period that turns durations in time units into ticks.
TEST(FretishDomain, TickPeriod) {
  const auto period = [](const std::string& content, std::vector<Finding>& findings) {
    return fretish::parse_domain_file(content, "domain.fret", findings).tick_seconds;
  };
  std::vector<Finding> ok;
  EXPECT_DOUBLE_EQ(period("boolean a\ntick 100 ms\n", ok).value_or(-1), 0.1);
  EXPECT_DOUBLE_EQ(period("tick 2 seconds", ok).value_or(-1), 2.0);
  EXPECT_DOUBLE_EQ(period("tick 0.5 min # half a minute", ok).value_or(-1), 30.0);
  EXPECT_DOUBLE_EQ(period("TICK 250 us", ok).value_or(-1), 250e-6);
  EXPECT_TRUE(ok.empty()) << ok.front().message;
  EXPECT_FALSE(period("boolean a", ok).has_value());

  for (const auto& [content, message] : std::vector<std::pair<std::string, std::string>>{
           {"tick 0 ms", "the tick period must be greater than zero"},
           {"tick 5 ticks", "the tick period needs a unit of time (e.g. 'tick 100 ms')"},
           {"tick 1 s\ntick 2 s", "the tick period is already declared at line 1"}}) {
    std::vector<Finding> findings;
    period(content, findings);
    ASSERT_EQ(findings.size(), 1u) << content;
    EXPECT_EQ(findings[0].check, "domain-invalid");
    EXPECT_EQ(findings[0].message, message);
  }
  std::vector<Finding> syntax;
  period("tick fast", syntax);
  ASSERT_EQ(syntax.size(), 1u);
  EXPECT_EQ(syntax[0].check, "fretish-syntax");
}

// Lookups go through an index built over the variables added since the last lookup; it must
// answer as a scan of the vector would, for names added later, in a copy that grows on its
// own, and from several threads at once (verify looks names up from its per-node threads).
TEST(FretishDomain, LookupsAnswerAsAScanAndSeeVariablesAddedLater) {
  fretish::Domain d;
  const auto add = [&](fretish::Domain& to, const std::string& name, VarType type,
                       std::vector<std::string> literals = {}) {
    fretish::Variable v;
    v.name = name;
    v.type = type;
    v.enum_values = std::move(literals);
    to.variables.push_back(std::move(v));
  };
  add(d, "terrain", VarType::enumeration, {"dust", "rocks"});
  add(d, "battery", VarType::integer);
  EXPECT_EQ(d.find("battery"), &d.variables[1]);
  EXPECT_EQ(d.find("wind"), nullptr);
  EXPECT_EQ(d.enum_owning("rocks"), &d.variables[0]);
  EXPECT_EQ(d.enum_owning("sand"), nullptr);

  // Added after a lookup: found; a second variable of the same name: the first still answers;
  // a literal two enums declare: no owner.
  add(d, "wind", VarType::real);
  add(d, "battery", VarType::real);
  add(d, "ground", VarType::enumeration, {"sand", "rocks"});
  EXPECT_EQ(d.find("wind"), &d.variables[2]);
  EXPECT_EQ(d.find("battery"), &d.variables[1]);
  EXPECT_EQ(d.enum_owning("sand"), &d.variables[4]);
  EXPECT_EQ(d.enum_owning("rocks"), nullptr);
  EXPECT_EQ(d.enum_owning("dust"), &d.variables[0]);

  // A copy answers with its own variables, and grows without changing the original.
  fretish::Domain copy = d;
  add(copy, "slope", VarType::real);
  EXPECT_EQ(copy.find("wind"), &copy.variables[2]);
  EXPECT_EQ(copy.find("slope"), &copy.variables[5]);
  EXPECT_EQ(d.find("slope"), nullptr);

  // 20,000 names, looked up from four threads at once.
  fretish::Domain big;
  for (int i = 0; i < 20000; ++i) add(big, "A" + std::to_string(i), VarType::boolean);
  std::vector<int> wrong(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&big, &wrong, t] {
      for (int i = t; i < 20000; i += 3)
        if (big.find("A" + std::to_string(i)) != &big.variables[static_cast<std::size_t>(i)])
          ++wrong[static_cast<std::size_t>(t)];
      if (big.find("B0") != nullptr) ++wrong[static_cast<std::size_t>(t)];
    });
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(wrong, std::vector<int>(4, 0));
}

}  // namespace
}  // namespace uabt::testing
