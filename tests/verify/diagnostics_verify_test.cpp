// Where verify's findings point and what they say beyond the witness: the gap at the node's
// requirements, the overlap with the other requirement and its region, lone always-true
// guards, and nodes a broken input leaves unverified.
#include <gtest/gtest.h>

#include <algorithm>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

TEST(VerifyDiagnostics, GapSpansTheNodesRequirements) {
  const load::Mission m = make_mission(
      "# comment\n"
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n");
  const verify::Result r = verify_checked(m);
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(gaps[0]->location.line, 2) << "the node's first requirement";
  EXPECT_EQ(gaps[0]->location.end_line, 3) << "to its last";
}

TEST(VerifyDiagnostics, OverlapNamesTheOtherRequirementAndItsRegion) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 30 Mission shall satisfy selected_alt = base\n"
      "Steep: In exploration if slope > 10 & battery < 50 Mission shall satisfy "
      "selected_alt = slow\n"
      "Safe: In exploration Mission shall satisfy selected_alt = slow\n",
      "integer battery in [0, 100]\ninteger slope in [0, 30]\n");
  const verify::Result r = verify_checked(m);
  const auto overlaps = findings_of(r, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u);
  const Finding& f = *overlaps[0];
  EXPECT_EQ(f.location.line, 2);
  ASSERT_EQ(f.related.size(), 1u);
  EXPECT_EQ(f.related[0].location.line, 1);
  EXPECT_EQ(f.related[0].message, "the other requirement, Low (base)");
  std::vector<std::string> region;
  for (const auto& note : f.notes)
    if (note.rfind("both hold: ", 0) == 0) region.push_back(note);
  ASSERT_EQ(region.size(), 1u) << ::testing::PrintToString(f.notes);
  EXPECT_NE(region[0].find("battery"), std::string::npos) << region[0];
  EXPECT_NE(region[0].find("slope"), std::string::npos) << region[0];
}

TEST(VerifyDiagnostics, AlwaysTrueLoneAtomIsVacuous) {
  const load::Mission m = make_mission(
      "R1: In n if !(x = 1) Mission shall satisfy selected_alt = a\n"
      "R2: In n if x = -2 Mission shall satisfy selected_alt = b\n"
      "Safe: In n Mission shall satisfy selected_alt = c\n",
      "integer x in [-3, 0]\n");
  const verify::Result r = verify_checked(m);
  const auto vacuous = findings_of(r, "guard-vacuous-atom");
  ASSERT_EQ(vacuous.size(), 1u);
  EXPECT_EQ(vacuous[0]->requirements, std::vector<std::string>{"R1"});
  EXPECT_NE(vacuous[0]->message.find("'x = 1'"), std::string::npos) << vacuous[0]->message;
  EXPECT_NE(std::find(vacuous[0]->notes.begin(), vacuous[0]->notes.end(),
                      "the guard always holds under the domain: R1 (a) acts as a default"),
            vacuous[0]->notes.end())
      << ::testing::PrintToString(vacuous[0]->notes);
}

TEST(VerifyDiagnostics, LoneAtomThatCanFailIsNotVacuous) {
  const load::Mission m = make_mission(
      "R1: In n if !(x = 0) Mission shall satisfy selected_alt = a\n"
      "Safe: In n Mission shall satisfy selected_alt = c\n",
      "integer x in [-3, 0]\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(findings_of(r, "guard-vacuous-atom").empty());
}

TEST(VerifyDiagnostics, NotVerifiedNodeIsReportedOnceAndNothingElse) {
  load::Mission m = make_mission(
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n");
  m.adaptables[0].location = {"mission.xml", 6, 9};
  m.not_verified["navigation"] = "the requirement at requirements.fret:3 does not parse";
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(r.findings.size(), 1u);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.check, "verification-skipped");
  EXPECT_EQ(f.severity, Severity::warning);
  EXPECT_EQ(f.message,
            "navigation is not verified because the requirement at requirements.fret:3 does not "
            "parse");
  EXPECT_EQ(f.location.file, "mission.xml");
  ASSERT_EQ(r.coverage.size(), 1u);
  EXPECT_FALSE(r.coverage[0].counted);
  EXPECT_EQ(r.coverage[0].not_counted_reason,
            "not verified: the requirement at requirements.fret:3 does not parse");
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

// A divisor that can be zero leaves the quotient without a value: Z3 picks any, so a verdict
// about the guard says nothing. The witness is a state of the domain with a zero divisor.
TEST(VerifyDiagnostics, DivisionByAPossiblyZeroDivisorIsAnErrorWithAWitness) {
  const load::Mission m = make_mission(
      "Calm: In navigation if wind / (battery - battery) < 8 Mission shall satisfy "
      "selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold\n",
      "integer wind in [0, 15]\ninteger battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  const auto zero = findings_of(r, "guard-division-by-zero");
  ASSERT_EQ(zero.size(), 1u);
  const Finding& f = *zero[0];
  EXPECT_EQ(f.severity, Severity::error);
  EXPECT_EQ(f.location.file, "requirements.fret");
  EXPECT_EQ(f.location.line, 1);
  EXPECT_EQ(f.location.column, 24);
  EXPECT_EQ(f.message.rfind("'wind / (battery - battery)' in the guard of Calm divides by zero "
                            "when battery - battery = 0, which the domain allows (",
                            0),
            0u)
      << f.message;
  ASSERT_FALSE(f.witness.empty());
  EXPECT_TRUE(smt::satisfies_domain(m.domain, f.witness));
}

// The division's own context, the domain's ranges and its assumptions keep the divisor
// non-zero: no finding.
TEST(VerifyDiagnostics, DivisionGuardedByItsContextOrTheDomainIsFine) {
  for (const auto& [guard, domain] : std::vector<std::pair<std::string, std::string>>{
           {"battery != 0 & 10 / battery > 2", "integer battery in [0, 9]\n"},
           {"battery > 0 => 10 / battery > 2", "integer battery in [0, 9]\n"},
           {"ite(battery = 0, false, 10 mod battery = 1)", "integer battery in [0, 9]\n"},
           {"10 / battery > 2", "integer battery in [1, 9]\n"},
           {"10 / battery > 2", "integer battery in [0, 9]\nassume charged: battery >= 3\n"},
           {"10 / 0 > 2", "integer battery in [0, 9]\n"}}) {
    const load::Mission m =
        make_mission("R1: In nav if " + guard + " Mission shall satisfy selected_alt = a\n" +
                         "Safe: In nav Mission shall satisfy selected_alt = b\n",
                     domain);
    const verify::Result r = verify_checked(m);
    EXPECT_TRUE(findings_of(r, "guard-division-by-zero").empty()) << guard << " / " << domain;
  }
}

// Properties (guarantees and Environment assumptions) and domain assumptions too.
TEST(VerifyDiagnostics, DivisionInPropertiesAndAssumptions) {
  load::Mission m = make_mission("Safe: In nav Mission shall satisfy selected_alt = b\n",
                                 "integer speed in [0, 9]\ninteger load in [0, 9]\n"
                                 "assume light: 100 / load > 5\n");
  auto parsed = fretish::parse_requirements_file(
      "Slow: the rover shall always satisfy 30 / speed < 10\n"
      "Env: the Environment shall always satisfy speed mod load = 0\n",
      "requirements.fret");
  m.properties = parsed.requirements;
  // Not verify_checked: a witness with load = 0 gives the assumption itself no value.
  const verify::Result r = verify::verify_mission(m, {});
  const auto zero = findings_of(r, "guard-division-by-zero");
  ASSERT_EQ(zero.size(), 3u) << r.findings.size();
  std::vector<std::string> messages;
  for (const auto* f : zero) messages.push_back(f->message.substr(0, f->message.find(" divides")));
  std::sort(messages.begin(), messages.end());
  EXPECT_EQ(messages, (std::vector<std::string>{"'100 / load' in assumption light",
                                                "'30 / speed' in guarantee Slow",
                                                "'speed mod load' in assumption Env"}));
}

}  // namespace
}  // namespace uabt::testing
