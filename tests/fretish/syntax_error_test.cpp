// Malformed input: a fretish-syntax finding at the exact line and column, a useful message.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fretish/parse.hpp"
#include "fretish_test_support.hpp"

namespace uabt::testing {
namespace {

struct ErrorCase {
  std::string text;
  int column;
  std::string message_part;
};

void expect_error(const std::string& text, int line, int column, const std::string& message_part,
                  const fretish::TextOrigin& origin = test_origin()) {
  std::vector<Finding> findings;
  EXPECT_FALSE(fretish::parse_requirement(text, origin, findings).has_value()) << text;
  ASSERT_EQ(findings.size(), 1u) << text;
  const Finding& f = findings[0];
  EXPECT_EQ(f.check, "fretish-syntax") << text;
  EXPECT_EQ(f.severity, Severity::error);
  EXPECT_EQ(f.location.file, origin.file);
  EXPECT_EQ(f.location.line, line) << text << ": " << f.message;
  EXPECT_EQ(f.location.column, column) << text << ": " << f.message;
  EXPECT_NE(f.message.find(message_part), std::string::npos)
      << text << ": got '" << f.message << "', wanted '" << message_part << "'";
}

TEST(FretishSyntaxError, ExactColumnAndMessage) {
  const std::vector<ErrorCase> cases = {
      // missing operand
      {"In navigation if OnDust & shall satisfy x", 27,
       "expected an expression after '&', found keyword 'shall'"},
      {"Mission shall satisfy selected_alt =", 37, "expected an expression after '='"},
      {"Mission shall satisfy", 22, "expected an expression after 'satisfy'"},
      // unbalanced parentheses
      {"Mission shall satisfy (a & (b | c)", 35, "expected an operator or ')'"},
      {"Mission shall satisfy a & b)", 28, "found ')'"},
      // keyword used as an identifier
      {"In navigation if then Mission shall satisfy x", 18,
       "expected an expression after 'if', found keyword 'then'"},
      {"In when Mission shall satisfy x", 4, "expected a mode name, found keyword 'when'"},
      // trailing garbage
      {"Mission shall satisfy x y", 25, "expected an operator or end of requirement, found 'y'"},
      {"Mission shall satisfy x = 1 2", 29, "found '2'"},
      // misplaced or missing shall
      {"In navigation Mission satisfy shall x", 23, "expected 'shall', found keyword 'satisfy'"},
      {"In navigation shall if a Mission satisfy x", 21,
       "expected a component name, found keyword 'if'"},
      // other fields
      {"Mission shall within 3 satisfy x", 24, "expected a time unit"},
      {"Mission shall within ticks satisfy x", 22, "expected a number"},
      {"Mission shall at the 3rd timepoint satisfy x", 22, "'first', 'same', 'next' or 'last'"},
      {"Mission shall x", 15, "expected a timing or 'satisfy', found 'x'"},
      {"if a is maybe Mission shall satisfy x", 9, "expected 'true' or 'false'"},
      {"Mission shall with probability 0.5 satisfy x", 32, "a comparison operator"},
      {"Mission shall satisfy if a b", 28, "expected an operator or 'then', found 'b'"},
      {"Mission shall satisfy f(a b)", 27, "expected an operator, ',' or ')'"},
      {"Mission shall satisfy \"unterminated", 36, "a closing '\"'"},
      {"Mission shall satisfy a < b < c", 29, "found '<'"},
      {"Mission shall satisfy a @ b", 25, "found '@'"},
      {"   ", 1, "empty requirement"},
  };
  for (const ErrorCase& c : cases) expect_error(c.text, 1, c.column, c.message_part);
}

TEST(FretishSyntaxError, PositionsUseTheOrigin) {
  // A sentence that starts at column 7 of line 12 (after a label).
  expect_error("Mission shall satisfy x &", 12, 7 + 25, "expected an expression",
               {"requirements.fret", 12, 7});
  // Multi-line text: the second line's columns start at 1.
  expect_error("Mission shall\n satisfy (x", 5, 12, "expected an operator or ')'",
               {"export.json", 4, 20});
}

TEST(FretishSyntaxError, ParseExpressionErrors) {
  std::vector<Finding> findings;
  EXPECT_EQ(fretish::parse_expression("a & (b | )", test_origin(2, 3), findings), nullptr);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].location.line, 2);
  EXPECT_EQ(findings[0].location.column, 3 + 9);
  EXPECT_NE(findings[0].message.find("expected an expression after '|'"), std::string::npos)
      << findings[0].message;

  findings.clear();
  EXPECT_EQ(fretish::parse_expression("a b", test_origin(), findings), nullptr);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_NE(findings[0].message.find("end of expression"), std::string::npos);
}

TEST(FretishRequirementsFile, LabelsCommentsAndIds) {
  const std::string content =
      "# selection requirements\r\n"
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust.\r\n"
      "\r\n"
      "   In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks  # rocky\r\n"
      "FSM-002 : Mission shall satisfy \"a # b\" = x\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position";
  fretish::ParseResult result = fretish::parse_requirements_file(content, "requirements.fret");
  EXPECT_TRUE(result.findings.empty()) << result.findings.front().message;
  ASSERT_EQ(result.requirements.size(), 4u);
  EXPECT_EQ(result.requirements[0].id, "Req1");
  EXPECT_EQ(result.requirements[0].location.line, 2);
  EXPECT_EQ(result.requirements[0].location.column, 7);
  EXPECT_EQ(result.requirements[0].text,
            "In navigation if OnDust Mission shall satisfy selected_alt = on_dust.");
  EXPECT_EQ(result.requirements[0].response->args[1]->text, "on_dust");
  EXPECT_EQ(result.requirements[1].id, "R4");
  EXPECT_EQ(result.requirements[1].location.column, 4);
  EXPECT_EQ(result.requirements[1].response->args[1]->text, "on_rocks");
  EXPECT_EQ(result.requirements[2].id, "FSM-002");
  EXPECT_EQ(result.requirements[2].response->args[0]->text, "a # b");
  EXPECT_EQ(result.requirements[3].id, "Safe");
  EXPECT_EQ(result.requirements[3].location.file, "requirements.fret");
  EXPECT_EQ(result.requirements[3].location.line, 6);
}

TEST(FretishRequirementsFile, MalformedLineInTheMiddle) {
  const std::string content =
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "# a comment\n"
      "\n"
      "Req2: In navigation if OnRocks | Mission shall satisfy selected_alt = on_rocks\n"
      "Req3: In navigation Mission shall satisfy selected_alt = hold\n";
  fretish::ParseResult result = fretish::parse_requirements_file(content, "requirements.fret");
  ASSERT_EQ(result.findings.size(), 1u);
  const Finding& f = result.findings[0];
  EXPECT_EQ(f.check, "fretish-syntax");
  EXPECT_EQ(f.location.file, "requirements.fret");
  EXPECT_EQ(f.location.line, 4);
  // "if OnRocks | Mission" is a valid condition, so "shall satisfy" reads as the
  // "shall <component>" form, and the component is missing where 'satisfy' stands.
  EXPECT_EQ(f.location.column, 48);
  EXPECT_NE(f.message.find("a component name"), std::string::npos) << f.message;
  // The other lines still parse.
  ASSERT_EQ(result.requirements.size(), 2u);
  EXPECT_EQ(result.requirements[0].id, "Req1");
  EXPECT_EQ(result.requirements[1].id, "Req3");
}

TEST(FretishRequirementsFile, LabelWithoutSentenceAndErrorColumnsAfterLabels) {
  fretish::ParseResult result =
      fretish::parse_requirements_file("Req9:   \nReq1:   Mission shall satisfy (x\n", "r.fret");
  ASSERT_EQ(result.findings.size(), 2u);
  EXPECT_EQ(result.findings[0].location.line, 1);
  EXPECT_NE(result.findings[0].message.find("after label 'Req9:'"), std::string::npos);
  EXPECT_EQ(result.findings[1].location.line, 2);
  EXPECT_EQ(result.findings[1].location.column, 33);
  EXPECT_TRUE(result.requirements.empty());
}

TEST(FretishRequirementsFile, EmptyAndCommentOnlyFiles) {
  EXPECT_TRUE(fretish::parse_requirements_file("", "r.fret").requirements.empty());
  fretish::ParseResult comments = fretish::parse_requirements_file("# x\n  # y\n\n", "r.fret");
  EXPECT_TRUE(comments.requirements.empty());
  EXPECT_TRUE(comments.findings.empty());
}

TEST(FretishRequirementsFile, GarbageNeverCrashes) {
  // Bytes that are not FRETISH at all: findings, no exception, no hang.
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 131 + 7) % 256);
  fretish::ParseResult result = fretish::parse_requirements_file(junk, "junk.fret");
  EXPECT_FALSE(result.findings.empty());
  for (const Finding& f : result.findings) EXPECT_EQ(f.check, "fretish-syntax");
}

}  // namespace
}  // namespace uabt::testing
