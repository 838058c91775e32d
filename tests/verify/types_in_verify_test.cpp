// Ill-typed guards are reported and their node is not analysed (no verdict on a guess).
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

TEST(TypesInVerify, MismatchIsReportedAtTheGuardAndTheNodeIsSkipped) {
  const load::Mission m = make_mission(
      "R1: In navigation if terrain = 3 Mission shall satisfy selected_alt = on_dust\n"
      "R2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n",
      "enum terrain in {dust, rocks}\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].check, "ref-type-mismatch");
  EXPECT_EQ(r.findings[0].location.file, "requirements.fret");
  EXPECT_EQ(r.findings[0].location.line, 1);
  EXPECT_EQ(r.findings[0].location.column, 22);
  EXPECT_FALSE(r.coverage.at(0).counted);
  EXPECT_EQ(r.coverage.at(0).not_counted_reason, "a guard does not type-check");
}

TEST(TypesInVerify, IllTypedAssumptionIsReportedAndLeftOut) {
  const load::Mission m = make_mission(
      "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold\n",
      "boolean OnDust\nenum terrain in {dust, rocks}\nassume broken: terrain < 1\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "ref-type-mismatch").size(), 1u);
  EXPECT_EQ(r.findings.at(0).location.file, "domain.fret");
  EXPECT_EQ(r.findings.size(), 1u);
}

TEST(TypesInVerify, EveryAdaptableNodeIsAnalysedOnItsOwn) {
  const load::Mission m = make_mission(
      "N1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "N2: In navigation if !OnDust Mission shall satisfy selected_alt = on_rocks\n"
      "A1: In arm if OnDust Mission shall satisfy selected_alt = careful\n"
      "A2: In arm if Stowed Mission shall satisfy selected_alt = quick\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(r.coverage.size(), 2u);
  EXPECT_EQ(r.coverage[0].adaptable, "navigation");
  EXPECT_EQ(r.coverage[1].adaptable, "arm");
  for (const auto& f : r.findings) EXPECT_EQ(f.adaptable, "arm") << f.message;
  EXPECT_EQ(findings_of(r, "guard-overlap").size(), 1u);
  EXPECT_EQ(findings_of(r, "guard-gap").size(), 1u);
}

}  // namespace
}  // namespace uabt::testing
