// Requirement sentences: every field of FRET's Requirement.g4 lands in the right place.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/diagnostics.hpp"
#include "fretish/parse.hpp"
#include "fretish_test_support.hpp"

namespace uabt::testing {
namespace {

using fretish::Requirement;

Requirement parse_ok(const std::string& text) {
  std::vector<Finding> findings;
  std::optional<Requirement> r = fretish::parse_requirement(text, test_origin(), findings);
  EXPECT_TRUE(r.has_value()) << text << ": " << (findings.empty() ? "" : findings.front().message);
  EXPECT_FALSE(has_errors(findings)) << text;
  return r.value_or(Requirement{});
}

std::string text_of(const fretish::ExprPtr& e) {
  return e ? grouped(*e) : "<none>";
}

TEST(FretishRequirement, ReplicationPackageSentence) {
  Requirement r = parse_ok("In navigation IF OnDust Mission SHALL SATISFY selected_alt=alt1");
  ASSERT_TRUE(r.scope);
  EXPECT_EQ(r.scope->keyword, "in");
  EXPECT_EQ(r.scope->mode, "navigation");
  EXPECT_FALSE(r.scope->negated);
  ASSERT_EQ(r.conditions.size(), 1u);
  EXPECT_EQ(r.conditions[0].qualifier, "if");
  EXPECT_EQ(text_of(r.conditions[0].expr), "OnDust");
  EXPECT_EQ(r.component, "Mission");
  EXPECT_TRUE(r.component_before_shall);
  EXPECT_EQ(r.timing.keyword, "");
  EXPECT_FALSE(r.probability);
  EXPECT_EQ(text_of(r.response), "(selected_alt = alt1)");
  EXPECT_FALSE(r.freeform);
  EXPECT_EQ(r.text, "In navigation IF OnDust Mission SHALL SATISFY selected_alt=alt1");
}

TEST(FretishRequirement, SourceRangesPointIntoTheFile) {
  std::vector<Finding> findings;
  auto r = fretish::parse_requirement("In nav if OnDust Mission shall satisfy selected_alt = a1",
                                      test_origin(7, 7), findings);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->location.file, "test.fret");
  EXPECT_EQ(r->location.line, 7);
  EXPECT_EQ(r->location.column, 7);
  EXPECT_EQ(r->scope->range.begin_column, 7);
  EXPECT_EQ(r->scope->range.end_column, 12);
  EXPECT_EQ(r->conditions[0].range.begin_column, 14);
  EXPECT_EQ(r->conditions[0].expr->range.begin_column, 17);
  EXPECT_EQ(r->conditions[0].expr->range.end_column, 22);
  EXPECT_EQ(r->component_range.begin_column, 24);
  EXPECT_EQ(r->component_range.end_column, 30);
  EXPECT_EQ(r->response_range.begin_column, 38);
  EXPECT_EQ(r->response->args[1]->range.begin_column, 61);
  EXPECT_EQ(r->response->args[1]->range.end_line, 7);
}

TEST(FretishRequirement, EveryScopeForm) {
  struct Case {
    std::string scope;
    std::string keyword;
    std::string mode;
    bool negated;
  };
  const std::vector<Case> cases = {
      {"in M", "in", "M", false},
      {"In mode M", "in", "M", false},
      {"in M mode", "in", "M", false},
      {"during M,", "during", "M", false},
      {"when in M", "when in", "M", false},
      {"if in M", "if in", "M", false},
      {"when not in M", "when not in", "M", true},
      {"If Not In M", "if not in", "M", true},
      {"unless in M", "unless in", "M", true},
      {"not in M", "not in", "M", true},
      {"after M", "after", "M", false},
      {"before mode M", "before", "M", false},
      {"only in M", "only in", "M", false},
      {"only during M", "only during", "M", false},
      {"only when in M", "only when in", "M", false},
      {"only if in M", "only if in", "M", false},
      {"only after M", "only after", "M", false},
      {"only before M mode", "only before", "M", false},
      {"except in M", "except in", "M", true},
      {"except during M", "except during", "M", true},
      {"except when in M", "except when in", "M", true},
      {"except if in M", "except if in", "M", true},
      {"in \"quoted mode\"", "in", "quoted mode", false},
  };
  for (const Case& c : cases) {
    Requirement r = parse_ok(c.scope + " the pump shall satisfy on");
    ASSERT_TRUE(r.scope) << c.scope;
    EXPECT_EQ(r.scope->keyword, c.keyword) << c.scope;
    EXPECT_EQ(r.scope->mode, c.mode) << c.scope;
    EXPECT_EQ(r.scope->negated, c.negated) << c.scope;
    EXPECT_EQ(r.scope->condition, nullptr) << c.scope;
    EXPECT_EQ(r.component, "pump") << c.scope;
  }
}

TEST(FretishRequirement, ConditionScopes) {
  struct Case {
    std::string scope;
    std::string keyword;
    std::string condition;
    bool negated;
  };
  const std::vector<Case> cases = {
      {"while x > 3", "while", "(x > 3)", false},
      {"only while a & b", "only while", "(a & b)", false},
      {"except while a", "except while", "a", true},
      {"after a | b,", "after", "(a | b)", false},
      {"before x = 2", "before", "(x = 2)", false},
      {"only after (a)", "only after", "a", false},
  };
  for (const Case& c : cases) {
    Requirement r = parse_ok(c.scope + " Mission shall satisfy on");
    ASSERT_TRUE(r.scope) << c.scope;
    EXPECT_EQ(r.scope->keyword, c.keyword) << c.scope;
    EXPECT_EQ(r.scope->mode, "") << c.scope;
    EXPECT_EQ(text_of(r.scope->condition), c.condition) << c.scope;
    EXPECT_EQ(r.scope->negated, c.negated) << c.scope;
  }
}

TEST(FretishRequirement, ConditionChains) {
  Requirement r = parse_ok(
      "in M, when a & b, and unless c or if d is false upon e is true whenever f where g "
      "Mission shall satisfy x");
  ASSERT_EQ(r.conditions.size(), 6u);
  EXPECT_EQ(r.conditions[0].qualifier, "when");
  EXPECT_EQ(r.conditions[0].connective, "");
  EXPECT_EQ(text_of(r.conditions[0].expr), "(a & b)");
  EXPECT_EQ(r.conditions[1].qualifier, "unless");
  EXPECT_EQ(r.conditions[1].connective, "and");
  EXPECT_EQ(r.conditions[2].qualifier, "if");
  EXPECT_EQ(r.conditions[2].connective, "or");
  EXPECT_TRUE(r.conditions[2].is_false_suffix);
  EXPECT_EQ(r.conditions[3].qualifier, "upon");
  EXPECT_EQ(r.conditions[3].connective, "");
  EXPECT_TRUE(r.conditions[3].is_true_suffix);
  EXPECT_EQ(r.conditions[4].qualifier, "whenever");
  EXPECT_EQ(r.conditions[5].qualifier, "where");
  EXPECT_EQ(text_of(r.conditions[5].expr), "g");
  // unless c → !c; "d is false" → !d; or → |; and / nothing → &; left to right.
  EXPECT_EQ(text_of(r.folded_condition()), "((((a & b) & (!c)) | (!d)) & e & f & g)");
}

TEST(FretishRequirement, FoldedConditionCases) {
  EXPECT_EQ(text_of(parse_ok("Mission shall satisfy x").folded_condition()), "<none>");
  EXPECT_EQ(text_of(parse_ok("if a Mission shall satisfy x").folded_condition()), "a");
  EXPECT_EQ(text_of(parse_ok("unless a Mission shall satisfy x").folded_condition()), "(!a)");
  EXPECT_EQ(text_of(parse_ok("if a is false Mission shall satisfy x").folded_condition()), "(!a)");
  EXPECT_EQ(text_of(parse_ok("unless a is false Mission shall satisfy x").folded_condition()), "a");
  EXPECT_EQ(text_of(parse_ok("if a is true Mission shall satisfy x").folded_condition()), "a");
  EXPECT_EQ(text_of(parse_ok("if a or if b or if c Mission shall satisfy x").folded_condition()),
            "(a | b | c)");
  EXPECT_EQ(text_of(parse_ok("if a if b or if c Mission shall satisfy x").folded_condition()),
            "((a & b) | c)");
  EXPECT_EQ(text_of(parse_ok("and if a, if b Mission shall satisfy x").folded_condition()),
            "(a & b)");
}

TEST(FretishRequirement, ComponentBeforeOrAfterShall) {
  Requirement before = parse_ok("The liquid_mixer shall satisfy x");
  EXPECT_EQ(before.component, "liquid_mixer");
  EXPECT_TRUE(before.component_before_shall);
  Requirement after = parse_ok("when a shall the pump satisfy x");
  EXPECT_EQ(after.component, "pump");
  EXPECT_FALSE(after.component_before_shall);
  Requirement quoted = parse_ok("\"flight software\" shall satisfy x");
  EXPECT_EQ(quoted.component, "flight software");
  EXPECT_FALSE(quoted.freeform);
}

TEST(FretishRequirement, EveryTiming) {
  struct Case {
    std::string timing;
    std::string keyword;
    std::string duration;
    std::string unit;
    std::string stop;
  };
  const std::vector<Case> cases = {
      {"", "", "", "", "<none>"},
      {"immediately", "immediately", "", "", "<none>"},
      {"Initially", "initially", "", "", "<none>"},
      {"at the first timepoint", "at the first timepoint", "", "", "<none>"},
      {"at the same timepoint", "at the same timepoint", "", "", "<none>"},
      {"AT THE NEXT TIMEPOINT", "at the next timepoint", "", "", "<none>"},
      {"at the last timepoint", "at the last timepoint", "", "", "<none>"},
      {"within 3 ticks", "within", "3", "ticks", "<none>"},
      {"for 5 tick", "for", "5", "tick", "<none>"},
      {"after 2.5 seconds", "after", "2.5", "seconds", "<none>"},
      {"within 10 millisecs", "within", "10", "millisecs", "<none>"},
      {"within 1 microsecond", "within", "1", "microsecond", "<none>"},
      {"for 1 minute", "for", "1", "minute", "<none>"},
      {"for 2 HOURS", "for", "2", "hours", "<none>"},
      {"within 4 sec", "within", "4", "sec", "<none>"},
      {"until a | b", "until", "", "", "(a | b)"},
      {"before stop", "before", "", "", "stop"},
      {"eventually", "eventually", "", "", "<none>"},
      {"finally", "finally", "", "", "<none>"},
      {"always", "always", "", "", "<none>"},
      {"never", "never", "", "", "<none>"},
      {", always,", "always", "", "", "<none>"},
  };
  for (const Case& c : cases) {
    Requirement r = parse_ok("in M Mission shall " + c.timing + " satisfy x");
    EXPECT_EQ(r.timing.keyword, c.keyword) << c.timing;
    EXPECT_EQ(r.timing.duration, c.duration) << c.timing;
    EXPECT_EQ(r.timing.unit, c.unit) << c.timing;
    EXPECT_EQ(text_of(r.timing.stop_condition), c.stop) << c.timing;
    EXPECT_EQ(text_of(r.response), "x") << c.timing;
  }
}

TEST(FretishRequirement, Probability) {
  Requirement r = parse_ok("Mission shall with probability >= 0.95 within 3 ticks satisfy x");
  ASSERT_TRUE(r.probability);
  EXPECT_EQ(r.probability->relop, ">=");
  EXPECT_EQ(r.probability->number, "0.95");
  EXPECT_EQ(r.timing.keyword, "within");
  Requirement eq = parse_ok("Mission shall WITH PROBABILITY == 1 satisfy x");
  ASSERT_TRUE(eq.probability);
  EXPECT_EQ(eq.probability->relop, "=");
}

TEST(FretishRequirement, CaseInsensitiveKeywordsAndTrailingPeriod) {
  Requirement r = parse_ok(
      "IN navigation WHEN OnDust IS TRUE MISSION SHALL IMMEDIATELY SATISFY "
      "selected_alt = alt1.");
  EXPECT_EQ(r.scope->keyword, "in");
  EXPECT_TRUE(r.conditions[0].is_true_suffix);
  EXPECT_EQ(r.timing.keyword, "immediately");
  // The final '.' ends the sentence; it is not part of the identifier alt1.
  EXPECT_EQ(r.response->args[1]->text, "alt1");
  Requirement dotted = parse_ok("Mission shall satisfy selected_alt = alt.v2 .");
  EXPECT_EQ(dotted.response->args[1]->text, "alt.v2");
}

TEST(FretishRequirement, Freeform) {
  Requirement r = parse_ok("\"The rover shall not tip over.\".");
  EXPECT_TRUE(r.freeform);
  EXPECT_FALSE(r.scope);
  EXPECT_EQ(r.response, nullptr);
}

TEST(FretishRequirement, ExpressionsInFields) {
  Requirement r = parse_ok(
      "when at the previous occurrence of a, b the liquid_mixer shall until "
      "(timer_60sec_expire | emergency_button) satisfy if ! liquid_level_2 then valve_1");
  EXPECT_EQ(text_of(r.conditions[0].expr), "prevOcc(a, b)");
  EXPECT_EQ(text_of(r.timing.stop_condition), "(timer_60sec_expire | emergency_button)");
  EXPECT_EQ(text_of(r.response), "((!liquid_level_2) -> valve_1)");
}

TEST(FretishRequirement, PrecedenceWarningInsideARequirement) {
  std::vector<Finding> findings;
  auto r = fretish::parse_requirement(
      "In navigation if OnSand xor OnDust | OnMud Mission shall satisfy selected_alt = a",
      test_origin(3, 7), findings);
  ASSERT_TRUE(r);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].check, "fretish-precedence");
  EXPECT_EQ(findings[0].location.line, 3);
  EXPECT_EQ(findings[0].location.column, 7 + 24);
}

// What uabt accepts and FRET's parser refuses is read as meant, with FRET's spelling as the fix.
TEST(FretishRequirement, SpellingsFretRefusesAreWarned) {
  std::vector<Finding> findings;
  fretish::TextOrigin origin{"requirements.fret", 1, 5};
  auto r = fretish::parse_requirement(
      "not in idle mode, when speed == 0 is true the rover shall always satisfy x-1 < TRUE_LIMIT",
      origin, findings);
  ASSERT_TRUE(r);
  EXPECT_EQ(format_text(findings),
            "requirements.fret:1:5: warning: FRET spells this scope 'when not in' or 'if not in', "
            "not 'not in' [fretish-not-fret]\n"
            "requirements.fret:1:34: warning: FRET has no '==': write '=' so that FRET can load "
            "the requirement [fretish-not-fret]\n"
            "requirements.fret:1:42: warning: FRET cannot parse a lower-case 'is true': write "
            "'is TRUE' [fretish-not-fret]\n"
            "requirements.fret:1:79: warning: FRET reads a '-' written against a number as its "
            "sign and cannot parse this subtraction: write a space after '-' "
            "[fretish-not-fret]\n");
  ASSERT_TRUE(r->scope);
  EXPECT_TRUE(r->scope->negated);
  EXPECT_EQ(text_of(r->response), "((x - 1) < TRUE_LIMIT)");
  EXPECT_TRUE(r->conditions[0].is_true_suffix);

  // FRET's own spellings are silent.
  findings.clear();
  ASSERT_TRUE(fretish::parse_requirement(
      "when not in idle mode, when speed = 0 is TRUE the rover shall always satisfy x - 1 < 2 "
      "& true & y > -1",
      origin, findings));
  EXPECT_TRUE(findings.empty()) << format_text(findings);

  findings.clear();
  ASSERT_TRUE(
      fretish::parse_requirement("the rover shall always satisfy TRUE | False", origin, findings));
  ASSERT_EQ(findings.size(), 2u);
  EXPECT_EQ(findings[0].message,
            "FRET reads only lower-case 'true' inside an expression: write 'true'");
  EXPECT_EQ(findings[1].check, "fretish-not-fret");
}

}  // namespace
}  // namespace uabt::testing
