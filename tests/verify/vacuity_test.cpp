// guard-vacuous-atom: atoms a constant can stand for under the domain.
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

const char* const kDefault = "Safe: In exploration Mission shall satisfy selected_alt = explore\n";

// One solver question per atom, each over the whole guard: beyond 1,000 atoms the guard's atoms
// are not checked one by one, and one warning says so (the guard's other checks are made).
TEST(Vacuity, AGuardOfMoreThanAThousandAtomsIsNotCheckedAtomByAtom) {
  const auto guard = [](int atoms) {
    std::string g = "depth >= 0";  // vacuous: the domain says so
    for (int k = 1; k < atoms; ++k) g += " & depth != " + std::to_string(100 + k);
    return "Deep: In exploration if " + g + " Mission shall satisfy selected_alt = nav_to_base\n";
  };
  const std::string domain = "integer depth in [0, 5000]\n";
  const verify::Result small = verify_checked(make_mission(guard(3) + kDefault, domain));
  EXPECT_EQ(findings_of(small, "guard-vacuous-atom").size(), 1u);
  EXPECT_TRUE(findings_of(small, "verification-skipped").empty());

  const verify::Result large = verify_checked(make_mission(guard(1001) + kDefault, domain));
  EXPECT_TRUE(findings_of(large, "guard-vacuous-atom").empty());
  const auto skipped = findings_of(large, "verification-skipped");
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0]->severity, Severity::warning);
  EXPECT_EQ(skipped[0]->message,
            "the atoms of the guard of Deep (nav_to_base) are not checked for vacuity: it has "
            "1001 atoms, more than the 1000 uabt checks one by one");
  EXPECT_EQ(skipped[0]->location.line, 1);
  EXPECT_EQ(skipped[0]->requirements, (std::vector<std::string>{"Deep"}));
  // The guard's other checks are made: Safe is shadowed nowhere, Deep is reachable.
  EXPECT_TRUE(findings_of(large, "guard-unsatisfiable").empty());
  EXPECT_TRUE(large.coverage.at(0).alternatives.at(0).reachable);
}

TEST(Vacuity, WeakerThresholdInAConjunctionIsVacuous) {
  const load::Mission m = make_mission(
      std::string("Low: In exploration if battery < 20 & battery < 30 Mission shall satisfy "
                  "selected_alt = nav_to_base\n") +
          kDefault,
      "integer battery in [0, 100]\n");
  const verify::Result r = verify_checked(m);
  const auto vacuous = findings_of(r, "guard-vacuous-atom");
  ASSERT_EQ(vacuous.size(), 1u);
  EXPECT_EQ(vacuous[0]->severity, Severity::warning);
  EXPECT_EQ(vacuous[0]->requirements, (std::vector<std::string>{"Low"}));
  EXPECT_NE(vacuous[0]->message.find("'battery < 30'"), std::string::npos);
  EXPECT_NE(vacuous[0]->message.find("replaced by true"), std::string::npos);
  EXPECT_EQ(vacuous[0]->location.line, 1);
  // The atom's own column: "Low: In exploration if battery < 20 & " is 38 characters.
  EXPECT_EQ(vacuous[0]->location.column, 39);
}

TEST(Vacuity, AssumptionMakesANegatedAtomVacuous) {
  const std::string reqs = std::string(
                               "R1: In exploration if OnDust & !OnRocks Mission shall satisfy "
                               "selected_alt = on_dust\n") +
                           kDefault;
  EXPECT_TRUE(findings_of(verify_checked(make_mission(reqs)), "guard-vacuous-atom").empty());
  const load::Mission m =
      make_mission(reqs, "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n");
  const verify::Result r = verify_checked(m);
  const auto vacuous = findings_of(r, "guard-vacuous-atom");
  ASSERT_EQ(vacuous.size(), 1u);
  EXPECT_NE(vacuous[0]->message.find("'OnRocks'"), std::string::npos);
  EXPECT_NE(vacuous[0]->message.find("replaced by false"), std::string::npos);
}

TEST(Vacuity, AbsorbedOccurrencesAreVacuousButTheFirstIsNot) {
  const load::Mission m = make_mission(
      std::string("R1: In exploration if A | (A & B) Mission shall satisfy selected_alt = a\n") +
      kDefault);
  const verify::Result r = verify_checked(m);
  const auto vacuous = findings_of(r, "guard-vacuous-atom");
  ASSERT_EQ(vacuous.size(), 2u);
  std::set<int> columns;
  for (const auto* f : vacuous) columns.insert(f->location.column);
  // "R1: In exploration if " is 22 characters: A at 23, the second A at 28, B at 32.
  EXPECT_EQ(columns, (std::set<int>{28, 32}));
}

TEST(Vacuity, IndependentBooleansNeedNoSolverCall) {
  const load::Mission m = make_mission(
      std::string("R1: In exploration if (A | B) & !C Mission shall satisfy selected_alt = a\n") +
      kDefault);
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(r.findings.empty());
  EXPECT_GE(r.statistics.prefiltered, 3u);
}

TEST(Vacuity, EveryAtomOfARealGuardMatters) {
  const load::Mission m = make_mission(
      std::string("R1: In exploration if slope > 10 & (battery < 20 | OnRocks) Mission shall "
                  "satisfy selected_alt = a\n") +
          kDefault,
      "real slope in [-45, 45]\ninteger battery in [0, 100]\nboolean OnRocks\n");
  EXPECT_TRUE(findings_of(verify_checked(m), "guard-vacuous-atom").empty());
}

}  // namespace
}  // namespace uabt::testing
