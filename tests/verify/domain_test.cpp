// domain-inconsistent and what happens to the rest of the analysis.
#include <gtest/gtest.h>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

const char* const kRequirements =
    "R1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
    "R2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n";

TEST(Domain, ContradictoryAssumptionsAreNamedAndNothingElseIsChecked) {
  const load::Mission m = make_mission(kRequirements,
                                       "boolean OnDust, OnRocks, OnSand\n"
                                       "assume one_terrain: !(OnDust & OnRocks)\n"
                                       "assume sandy: OnSand | OnDust\n"
                                       "assume dusty_rocks: OnDust & OnRocks\n");
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(r.findings.size(), 1u);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.check, "domain-inconsistent");
  EXPECT_NE(f.message.find("one_terrain"), std::string::npos);
  EXPECT_NE(f.message.find("dusty_rocks"), std::string::npos);
  EXPECT_EQ(f.message.find("sandy"), std::string::npos);  // the core is minimal
  EXPECT_EQ(f.location.file, "domain.fret");
  EXPECT_EQ(f.location.line, 4);
  ASSERT_EQ(r.coverage.size(), 1u);
  EXPECT_FALSE(r.coverage[0].counted);
  EXPECT_EQ(r.coverage[0].not_counted_reason, "the domain is inconsistent");
}

TEST(Domain, EmptyIntegerRangeIsInconsistent) {
  // domain.fret refuses such a range itself; a FRET export or a future loader might not.
  load::Mission m = make_mission(
      "Low: In exploration if battery < 20 Mission shall satisfy selected_alt = nav_to_base\n",
      "integer battery in [0, 100]\n");
  m.domain.variables.at(0).lower = "10";
  m.domain.variables.at(0).upper = "0";
  const verify::Result r = verify_checked(m);
  ASSERT_EQ(findings_of(r, "domain-inconsistent").size(), 1u);
  EXPECT_NE(r.findings[0].message.find("battery in [10, 0]"), std::string::npos);
}

TEST(Domain, ConsistentDomainIsSilent) {
  const load::Mission m =
      make_mission(std::string(kRequirements) +
                       "Safe: In navigation Mission shall satisfy selected_alt = hold\n",
                   "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n");
  EXPECT_TRUE(verify_checked(m).findings.empty());
}

TEST(Domain, AssumptionOverEnumsAndNumbersConstrainsWitnesses) {
  const load::Mission m = make_mission(
      "Low: In exploration if battery < 20 Mission shall satisfy selected_alt = nav_to_base\n"
      "Rocky: In exploration if terrain = rocks Mission shall satisfy selected_alt = careful\n",
      "integer battery in [0, 100]\nenum terrain in {dust, rocks}\n"
      "assume charged_on_rocks: terrain = rocks -> battery >= 50\n");
  const verify::Result r = verify_checked(m);
  EXPECT_TRUE(findings_of(r, "guard-overlap").empty());
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(*find_value(gaps[0]->witness, "terrain"), Value::of_enum("dust"));
  EXPECT_TRUE(r.coverage.at(0).counted);
  EXPECT_EQ(r.coverage.at(0).states, 101u + 51u);
}

}  // namespace
}  // namespace uabt::testing
