#include <gtest/gtest.h>

#include "report/common.hpp"
#include "report/reports.hpp"
#include "report_fixtures.hpp"

namespace uabt::report {
namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(MarkdownReport, VerdictLine) {
  const std::string failing = to_markdown(testing::failing_input());
  EXPECT_TRUE(has(failing, "## uabt: msl\\_curiosity\\_paper") ||
              has(failing, "## uabt: msl_curiosity_paper"))
      << failing;
  EXPECT_TRUE(has(failing, "**Verdict: FAIL** | 4 errors, 1 warning, 0 notes | uabt 0.1.0"));
  EXPECT_TRUE(has(failing, "stages: load, verify, compile, conform"));
  const std::string passing = to_markdown(testing::passing_input());
  EXPECT_TRUE(has(passing, "**Verdict: PASS**"));
  EXPECT_TRUE(has(passing, "No findings."));
}

TEST(MarkdownReport, FindingsTable) {
  const std::string text = to_markdown(testing::failing_input());
  EXPECT_TRUE(has(text, "| Severity | Check | Location | Message |\n|---|---|---|---|\n"));
  EXPECT_TRUE(has(text,
                  "| error | `guard-overlap` | `requirements.fret:2:1` | the guards of Req1 and "
                  "Req2 both hold in some state (node `navigation`) |\n"));
  EXPECT_TRUE(has(text,
                  "| warning | `ref-orphan-alternative` | "
                  "`alternatives/navigation/spare.xml` |"));
  // A '|' in a message cannot split the cell; '<' cannot open an HTML tag.
  EXPECT_TRUE(has(text,
                  "| error | `fretish-syntax` | `requirements.fret:5:10` | expected 'shall' "
                  "after \\<Adaptable\\> \\| here |\n"));
}

TEST(MarkdownReport, Witnesses) {
  const std::string text = to_markdown(testing::failing_input());
  EXPECT_TRUE(
      has(text, "- `guard-overlap` at `requirements.fret:2:1`: OnDust = true, OnRocks = true\n"));
  EXPECT_TRUE(has(text, "slope = 1/3"));
}

TEST(MarkdownReport, ATableCellStaysOneCellWhateverItsTextHolds) {
  // Every table of summary.md escapes through these two: a '|' or a newline in a requirement,
  // a state or a package name would end the cell or the row.
  EXPECT_EQ(detail::markdown_text("a | b\nc"), "a \\| b c");
  EXPECT_EQ(detail::markdown_text("x < 1 & y > 2"), "x \\< 1 & y \\> 2");
  EXPECT_EQ(detail::markdown_text("&amp; &#38;"), "&amp;amp; &amp;#38;");
  EXPECT_EQ(detail::markdown_text("selected_alt _x *y* [z]"), "selected_alt \\_x \\*y\\* \\[z\\]");
  EXPECT_EQ(detail::markdown_code("on_dust"), "`on_dust`");
  EXPECT_EQ(detail::markdown_code("a|b"), "a\\|b");
  EXPECT_EQ(detail::markdown_code("two\nlines"), "two lines");
  EXPECT_EQ(detail::markdown_code(""), "");
}

TEST(MarkdownReport, CoverageTables) {
  const std::string text = to_markdown(testing::failing_input());
  EXPECT_TRUE(has(text, "### Coverage of `navigation`"));
  EXPECT_TRUE(has(text, "| on_dust | Req1 | 2 | 50.0% |\n")) << text;
  EXPECT_TRUE(has(text, "| on_rocks | Req2 | 1 | 25.0% |\n"));
  EXPECT_TRUE(has(text, "| *gap: none selected* | | 1 | 25.0% |\n"));
  EXPECT_TRUE(has(text, "Gap: 1 of 4 states (25.0%) select no alternative"));
  EXPECT_TRUE(has(text, "Overlap: 1 of 4 states (25.0%) are claimed by two or more guards."));
  // The decision table: the requirements, then the gap and overlap regions.
  EXPECT_TRUE(has(text, "| # | OnDust | OnRocks | selects | share |\n")) << text;
  EXPECT_TRUE(has(text, "| 1 Req1 | true | - | on_dust | 50.0% |\n"));
  EXPECT_TRUE(has(text, "| **gap** Req1 Req2 | false | false | none: the node fails | 25.0% |\n"));
  EXPECT_TRUE(
      has(text, "| **overlap** Req1 Req2 | true | true | the first in priority order | 25.0% |\n"));
  EXPECT_TRUE(has(text, "### Coverage of `arm`\n\nNot counted: slope is a real variable."));
  EXPECT_TRUE(has(text, "| retract | Arm2 | **no** |"));
}

TEST(MarkdownReport, PassingCoverageHasNoGap) {
  const std::string text = to_markdown(testing::passing_input());
  EXPECT_TRUE(has(text, "| hold_position | Safe | 1 | 33.3% |\n"));
  EXPECT_TRUE(has(text, "Gap: 0 of 3 states (0.0%).")) << text;
}

TEST(MarkdownReport, Deterministic) {
  EXPECT_EQ(to_markdown(testing::failing_input()), to_markdown(testing::failing_input()));
}

}  // namespace
}  // namespace uabt::report
