// The scale families (tests/bench/verify_families.*) at small sizes: the generated missions load
// and verify with exactly the findings the families promise, so a benchmark at full size measures
// a right answer and the generator cannot rot.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "bench/verify_families.hpp"
#include "load/mission.hpp"
#include "temp_mission.hpp"
#include "verify/verify.hpp"

namespace uabt::testing {
namespace {

// Per check id, the findings verify lists for the family's mission; the mission must load.
std::map<std::string, std::size_t> verified(const bench::VerifyFamily& family) {
  std::string error;
  auto mission = load::load_mission(family.dir, {}, error);
  EXPECT_TRUE(mission) << error;
  if (!mission) return {{"load", 1}};
  std::map<std::string, std::size_t> counts;
  for (const Finding& f : verify::verify_mission(*mission, {}).findings) ++counts[f.check];
  return counts;
}

TEST(ScaleFamilies, APortedSequenceVerifiesWithoutFindings) {
  for (int actions : {1, 500}) {
    TempMission scratch({});
    const auto family = bench::generate_ported_sequence(scratch.dir() / "m", actions);
    EXPECT_EQ(verified(family), family.findings) << actions;
    EXPECT_TRUE(family.findings.empty());
  }
}

// Beyond 1,000 disjuncts the family expects one verification-skipped (BM_VerifyFamily/1/6000
// checks it): the limit itself is tested on a cheaper guard
// (Vacuity.AGuardOfMoreThanAThousandAtomsIsNotCheckedAtomByAtom), since 1,001 disjuncts over
// 100,001 values of depth cost 10^8 coverage evaluations, over 30 s under the sanitizers.
TEST(ScaleFamilies, ALongDisjunctionVerifiesWithoutFindings) {
  TempMission scratch({});
  const auto family = bench::generate_disjunct_guard(scratch.dir() / "m", 40);
  EXPECT_TRUE(family.findings.empty());
  EXPECT_EQ(verified(family), family.findings);
}

TEST(ScaleFamilies, ARealGridIsDisjointAndMeasuredExactly) {
  TempMission scratch({});
  const auto family = bench::generate_real_grid(scratch.dir() / "m", 130);  // 3 rows
  std::string error;
  auto mission = load::load_mission(family.dir, {}, error);
  ASSERT_TRUE(mission) << error;
  const verify::Result r = verify::verify_mission(*mission, {});
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().check << ": " << r.findings.front().message;
  const verify::Coverage& c = r.coverage.at(0);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  // wind in [0, 64] x battery in [0, 3]: each cell 1 x 1 of 192; the default takes the rest.
  EXPECT_EQ(c.measure.text, "192");
  EXPECT_EQ(c.alternatives.at(0).share.text, "1/192");
  EXPECT_EQ(c.alternatives.at(129).share.text, "1/192");
  EXPECT_EQ(c.alternatives.at(130).share.text, "31/96");  // 62 of the last row's cells
  EXPECT_EQ(c.overlap_share.text, "0");
  EXPECT_EQ(c.gap_share.text, "0");
}

// Per check id, the findings loading the family's mission gives.
std::map<std::string, std::size_t> loaded(const bench::VerifyFamily& family) {
  std::string error;
  auto mission = load::load_mission(family.dir, {}, error);
  EXPECT_TRUE(mission) << error;
  std::map<std::string, std::size_t> counts;
  if (mission)
    for (const Finding& f : mission->findings) ++counts[f.check];
  return counts;
}

// With nodes.xml declaring the vocabulary, each name of the guard is a typo until declared: one
// ref-undeclared a name (the formats list 20 a file and count the rest: RepeatedFindings).
TEST(ScaleFamilies, AGuardOfUndeclaredNamesHasOneFindingAName) {
  TempMission scratch({});
  const auto family = bench::generate_undeclared_guard(scratch.dir() / "m", 30);
  std::string error;
  auto mission = load::load_mission(family.dir, {}, error);
  ASSERT_TRUE(mission) << error;
  EXPECT_EQ(mission->findings.size(), 20u);
  EXPECT_EQ(findings_count(mission->findings), 30u);
  for (const Finding& f : mission->findings) EXPECT_EQ(f.check, "ref-undeclared");
}

// Noise is no requirements file: each stretch of it that is no requirement is a syntax error.
TEST(ScaleFamilies, NoiseAsRequirementsIsSyntaxErrors) {
  TempMission scratch({});
  const auto family = bench::generate_noise_requirements(scratch.dir() / "m", 3000);
  const auto counts = loaded(family);
  // OnDust, declared for the requirements the noise replaced, is now read by nothing.
  EXPECT_EQ(counts, (std::map<std::string, std::size_t>{{"domain-unused-variable", 1},
                                                        {"fretish-syntax", 7}}));
  // The same size writes the same bytes.
  const auto again = bench::generate_noise_requirements(scratch.dir() / "again", 3000);
  std::ifstream a(family.dir / "requirements.fret", std::ios::binary),
      b(again.dir / "requirements.fret", std::ios::binary);
  const std::string x((std::istreambuf_iterator<char>(a)), {}),
      y((std::istreambuf_iterator<char>(b)), {});
  EXPECT_EQ(x.size(), 3000u);
  EXPECT_EQ(x, y);
}

}  // namespace
}  // namespace uabt::testing
