// classify_selection: the selection subset is accepted, everything else is refused with a
// fretish-unsupported error naming the field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fretish/parse.hpp"
#include "fretish/selection.hpp"
#include "fretish_test_support.hpp"

namespace uabt::testing {
namespace {

struct Classified {
  std::vector<fretish::SelectionRequirement> selections;
  std::vector<Finding> findings;
};

Classified classify(const std::string& file_content) {
  fretish::ParseResult parsed = fretish::parse_requirements_file(file_content, "requirements.fret");
  EXPECT_FALSE(has_errors(parsed.findings))
      << file_content << ": " << (parsed.findings.empty() ? "" : parsed.findings[0].message);
  Classified out;
  out.selections = fretish::classify_selection(parsed.requirements, out.findings);
  return out;
}

std::string guard_of(const fretish::SelectionRequirement& s) {
  return s.guard ? grouped(*s.guard) : "<default>";
}

TEST(FretishSelection, AcceptsTheSelectionForms) {
  const Classified c = classify(
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: during navigation, unless OnDust and when OnRocks Mission shall immediately "
      "satisfy selected_alt = on_rocks\n"
      "Req3: when in navigation when OnSand or if OnMud is false mission SHALL satisfy "
      "selected_alt = on_sand.\n"
      "Req4: if in navigation mode if battery < 20 & !charging MISSION shall satisfy "
      "selected_alt=\"low battery\"\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n"
      "In exploration when slope > 10 Mission shall satisfy selected_alt = rocks_alternative\n");
  EXPECT_TRUE(c.findings.empty()) << c.findings.front().message;
  ASSERT_EQ(c.selections.size(), 6u);
  const auto& s = c.selections;
  EXPECT_EQ(s[0].id, "Req1");
  EXPECT_EQ(s[0].adaptable, "navigation");
  EXPECT_EQ(s[0].alternative, "on_dust");
  EXPECT_EQ(guard_of(s[0]), "OnDust");
  EXPECT_EQ(s[0].location.line, 1);
  EXPECT_EQ(s[0].location.column, 7);
  EXPECT_EQ(s[0].guard_location.column, 21);
  EXPECT_EQ(s[0].alternative_location.line, 1);
  EXPECT_EQ(s[0].alternative_location.column, 68);
  EXPECT_EQ(s[0].source_index, 0);

  EXPECT_EQ(guard_of(s[1]), "((!OnDust) & OnRocks)");
  EXPECT_EQ(s[1].alternative, "on_rocks");
  EXPECT_EQ(guard_of(s[2]), "(OnSand | (!OnMud))");
  EXPECT_EQ(s[2].alternative, "on_sand");
  EXPECT_EQ(guard_of(s[3]), "((battery < 20) & (!charging))");
  EXPECT_EQ(s[3].alternative, "low battery");
  EXPECT_EQ(s[4].id, "Safe");
  EXPECT_EQ(guard_of(s[4]), "<default>");
  EXPECT_EQ(s[4].guard_location.line, 5);
  EXPECT_EQ(s[4].guard_location.column, 7);
  EXPECT_EQ(s[5].id, "R6");
  EXPECT_EQ(s[5].adaptable, "exploration");
  EXPECT_EQ(s[5].source_index, 5);
}

TEST(FretishSelection, ReplicationPackageSentences) {
  const Classified c = classify(
      "In navigation IF OnDust Mission SHALL SATISFY selected_alt=alt1\n"
      "In navigation IF OnRock Mission SHALL SATISFY selected_alt=alt2\n");
  EXPECT_TRUE(c.findings.empty());
  ASSERT_EQ(c.selections.size(), 2u);
  EXPECT_EQ(c.selections[1].alternative, "alt2");
  EXPECT_EQ(guard_of(c.selections[1]), "OnRock");
}

struct Rejected {
  std::string sentence;
  std::string message_part;
  int column;  // of the offending field, in "X: <sentence>"
};

TEST(FretishSelection, RejectsWithTheFieldNamed) {
  const std::vector<Rejected> cases = {
      {"In navigation if OnDust Mission shall within 3 ticks satisfy selected_alt = a",
       "timing 'within 3 ticks' is not supported in a selection requirement: only none or "
       "'immediately'",
       42},
      {"In navigation Mission shall always satisfy selected_alt = a", "timing 'always'", 32},
      {"In navigation Mission shall until x satisfy selected_alt = a", "timing 'until x'", 32},
      {"before navigation Mission shall satisfy selected_alt = a",
       "scope 'before navigation' is not supported", 4},
      {"when not in navigation Mission shall satisfy selected_alt = a",
       "scope 'when not in navigation'", 4},
      {"unless in navigation Mission shall satisfy selected_alt = a", "scope 'unless in", 4},
      {"only in navigation Mission shall satisfy selected_alt = a", "scope 'only in", 4},
      {"while OnDust Mission shall satisfy selected_alt = a", "scope 'while OnDust'", 4},
      {"Mission shall satisfy selected_alt = a", "scope missing", 4},
      {"In navigation Mission shall satisfy selected_alt = 3", "response 'selected_alt = 3'", 32},
      {"In navigation Mission shall satisfy selected_alt != a", "response 'selected_alt != a'", 32},
      {"In navigation Mission shall satisfy selected_alt = a & b", "response", 32},
      {"In navigation Rover shall satisfy selected_alt = a",
       "component 'Rover' is not supported in a selection requirement: only 'Mission'", 18},
      {"In navigation shall the rover satisfy selected_alt = a", "component 'rover'", 28},
      {"In navigation Mission shall with probability > 0.9 satisfy selected_alt = a",
       "probability 'with probability > 0.9'", 32},
      {"\"Select dust mode on dust.\"", "freeform requirement", 4},
  };
  for (const Rejected& r : cases) {
    const Classified c = classify("X: " + r.sentence + "\n");
    EXPECT_TRUE(c.selections.empty()) << r.sentence;
    ASSERT_GE(c.findings.size(), 1u) << r.sentence;
    const Finding& f = c.findings[0];
    EXPECT_EQ(f.check, "fretish-unsupported") << r.sentence;
    EXPECT_EQ(f.severity, Severity::error);
    EXPECT_NE(f.message.find(r.message_part), std::string::npos)
        << r.sentence << ": got '" << f.message << "'";
    EXPECT_EQ(f.location.line, 1);
    EXPECT_EQ(f.location.column, r.column) << r.sentence << ": " << f.message;
    EXPECT_EQ(f.requirements, std::vector<std::string>{"X"});
    // Only a selection scope names the adaptable node the finding belongs to.
    EXPECT_EQ(f.adaptable, r.sentence.rfind("In navigation", 0) == 0 ? "navigation" : "")
        << r.sentence;
  }
}

TEST(FretishSelection, EveryOffendingFieldIsReported) {
  const Classified c = classify(
      "X: before navigation Rover shall with probability > 0.5 within 2 ticks satisfy "
      "selected_alt != go\n"
      "Ok: In navigation Mission shall satisfy selected_alt = a\n");
  ASSERT_EQ(c.selections.size(), 1u);
  EXPECT_EQ(c.selections[0].id, "Ok");
  EXPECT_EQ(c.selections[0].source_index, 1);
  ASSERT_EQ(c.findings.size(), 5u);
  const std::vector<std::string> fields = {"probability", "scope", "component", "timing",
                                           "response"};
  for (std::size_t i = 0; i < fields.size(); ++i)
    EXPECT_EQ(c.findings[i].message.rfind(fields[i], 0), 0u) << c.findings[i].message;
}

// Requirements that do not read `selected_alt` are mission properties (ARCHITECTURE §10): no
// finding, kept in file order; only what has no meaning on a run is refused.
TEST(FretishSelection, OtherRequirementsAreMissionProperties) {
  fretish::ParseResult parsed = fretish::parse_requirements_file(
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "P1: if OnDust Mission shall satisfy x\n"
      "P2: In navigation Mission shall satisfy chosen = a\n"
      "P3: upon OnMud the rover shall within 1 tick satisfy hold_position.running\n"
      "A1: the Environment shall always satisfy !(OnDust & OnRocks)\n"
      "X: the rover shall with probability > 0.9 always satisfy safe\n",
      "requirements.fret");
  ASSERT_FALSE(has_errors(parsed.findings));
  std::vector<Finding> findings;
  const fretish::Classification c = fretish::classify_requirements(parsed.requirements, findings);
  ASSERT_EQ(c.selections.size(), 1u);
  ASSERT_EQ(c.properties.size(), 4u);
  EXPECT_EQ(c.properties[0].id, "P1");
  EXPECT_EQ(c.properties[2].id, "P3");
  EXPECT_EQ(c.properties[3].id, "A1");
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].check, "fretish-unsupported");
  EXPECT_EQ(findings[0].requirements, std::vector<std::string>{"X"});
  EXPECT_EQ(findings[0].message.rfind("probability 'with probability > 0.9' has no meaning", 0), 0u)
      << findings[0].message;
}

}  // namespace
}  // namespace uabt::testing
