#include <gtest/gtest.h>

#include "base/finding.hpp"

namespace uabt {
namespace {

Finding at_line(const std::string& file, const std::string& check, int line) {
  Finding f;
  f.check = check;
  f.message = "finding on line " + std::to_string(line);
  f.location = {file, line, 1};
  return f;
}

TEST(FindingSummary, AFileListsTwentyFindingsOfACheckAndCountsTheRest) {
  std::vector<Finding> findings;
  for (int line = 25000; line >= 1; --line) findings.push_back(at_line("r.fret", "syntax", line));
  findings.push_back(at_line("r.fret", "other", 3));
  findings.push_back(at_line("d.fret", "syntax", 1));
  sort_findings(findings);
  ASSERT_EQ(findings.size(), 22u);
  EXPECT_EQ(findings_count(findings), 25002u);
  EXPECT_EQ(findings[0].location.file, "d.fret");
  // The first twenty lines stay, in order; the twentieth counts the 24,980 after it.
  std::vector<int> syntax_lines;
  for (const auto& f : findings)
    if (f.location.file == "r.fret" && f.check == "syntax") syntax_lines.push_back(f.location.line);
  ASSERT_EQ(syntax_lines.size(), 20u);
  EXPECT_EQ(syntax_lines.front(), 1);
  EXPECT_EQ(syntax_lines.back(), 20);
  const Finding& last = findings.back();
  EXPECT_EQ(last.location.line, 20);
  EXPECT_EQ(last.more_like_it, 24980u);
  ASSERT_FALSE(last.notes.empty());
  EXPECT_EQ(last.notes.back(),
            "and 24,980 more like it in this file, not listed: uabt lists the first 20 findings "
            "of a check in a file");
}

TEST(FindingSummary, SortingASummaryAgainKeepsItsCount) {
  std::vector<Finding> findings;
  for (int line = 1; line <= 30; ++line) findings.push_back(at_line("r.fret", "syntax", line));
  sort_findings(findings);
  const std::vector<Finding> once = findings;
  sort_findings(findings);
  ASSERT_EQ(findings.size(), once.size());
  EXPECT_EQ(findings.back().notes, once.back().notes);
  EXPECT_EQ(findings_count(findings), 30u);
  // Findings of the same check added later are counted on top.
  for (int line = 31; line <= 35; ++line) findings.push_back(at_line("r.fret", "syntax", line));
  sort_findings(findings);
  EXPECT_EQ(findings_count(findings), 35u);
  EXPECT_EQ(findings.back().more_like_it, 15u);
  EXPECT_EQ(findings.back().notes.size(), 1u);
}

TEST(FindingSummary, TwentyFindingsAreAllListed) {
  std::vector<Finding> findings;
  for (int line = 1; line <= 20; ++line) findings.push_back(at_line("r.fret", "syntax", line));
  sort_findings(findings);
  EXPECT_EQ(findings.size(), 20u);
  EXPECT_TRUE(findings.back().notes.empty());
}

}  // namespace
}  // namespace uabt
