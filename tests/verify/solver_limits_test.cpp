// Nonlinear guards: the verdict is correct or verification-inconclusive, never wrong.
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

TEST(SolverLimits, NonlinearContradictionIsUnsatisfiableOrInconclusive) {
  const load::Mission m = make_mission(
      "R1: In arm if x * y > 2 & x * x < 0 Mission shall satisfy selected_alt = a\n"
      "Safe: In arm Mission shall satisfy selected_alt = b\n",
      "integer x, y\n");
  verify::Options options;
  options.timeout_ms = 2000;
  const verify::Result r = verify_checked(m, options);
  ASSERT_EQ(r.findings.size(), 1u) << r.findings.front().message;
  const std::string check = r.findings[0].check;
  EXPECT_TRUE(check == "guard-unsatisfiable" || check == "verification-inconclusive") << check;
  EXPECT_EQ(r.findings[0].severity, Severity::error);
  EXPECT_FALSE(r.coverage.at(0).alternatives.at(0).reachable);
}

TEST(SolverLimits, NonlinearOverlapWitnessIsChecked) {
  const load::Mission m = make_mission(
      "R1: In arm if x * y = 12 & x > y Mission shall satisfy selected_alt = a\n"
      "R2: In arm if y > 2 Mission shall satisfy selected_alt = b\n"
      "Safe: In arm Mission shall satisfy selected_alt = c\n",
      "integer x in [-20, 20]\ninteger y in [-20, 20]\n");
  const verify::Result r = verify_checked(m);  // validates the witness with the evaluator
  const auto overlaps = findings_of(r, "guard-overlap");
  const auto unknown = findings_of(r, "verification-inconclusive");
  ASSERT_EQ(overlaps.size() + unknown.size(), 1u);
  if (!overlaps.empty()) {
    EXPECT_EQ(find_value(overlaps[0]->witness, "x")->integer *
                  find_value(overlaps[0]->witness, "y")->integer,
              12);
  }
  EXPECT_TRUE(r.coverage.at(0).counted);
  EXPECT_EQ(r.coverage.at(0).overlap_states, 1u);  // x * y = 12, x > y > 2: only (4, 3)
}

TEST(SolverLimits, RealNonlinearWitnessesAreValidatedApproximately) {
  const load::Mission m = make_mission(
      "R1: In arm if r * r = 2 Mission shall satisfy selected_alt = a\n"
      "R2: In arm if r > 1 Mission shall satisfy selected_alt = b\n"
      "Safe: In arm Mission shall satisfy selected_alt = c\n",
      "real r in [0, 10]\n");
  const verify::Result r = verify::verify_mission(m, {});
  const auto overlaps = findings_of(r, "guard-overlap");
  const auto unknown = findings_of(r, "verification-inconclusive");
  ASSERT_EQ(overlaps.size() + unknown.size(), 1u);
  if (!overlaps.empty()) {
    const Value* v = find_value(overlaps[0]->witness, "r");
    ASSERT_NE(v, nullptr);
    EXPECT_NEAR(v->real, 1.41421356, 1e-6);
    EXPECT_EQ(v->text.back(), '?');  // an irrational root is shown as an approximation
  }
}

TEST(SolverLimits, TinyTimeoutNeverProducesAWrongVerdict) {
  // Whatever the solver manages within 1 ms, every finding it does produce is checked.
  const load::Mission m = make_mission(
      "R1: In arm if x * x * y - 3 * x * y * y > 17 & x + y < 40 Mission shall satisfy "
      "selected_alt = a\n"
      "R2: In arm if x * y * y > 5 * x + 3 Mission shall satisfy selected_alt = b\n",
      "integer x in [-1000, 1000]\ninteger y in [-1000, 1000]\n");
  verify::Options options;
  options.timeout_ms = 1;
  const verify::Result r = verify_checked(m, options);
  for (const auto& f : r.findings)
    EXPECT_TRUE(f.check == "guard-overlap" || f.check == "guard-gap" ||
                f.check == "verification-inconclusive" || f.check == "guard-shadowed")
        << f.check;
}

}  // namespace
}  // namespace uabt::testing
