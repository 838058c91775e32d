// One mistake, one finding: what a broken input makes unknowable is not reported as if it were
// known, and no verdict is built on it.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

// How many findings of each check the gate reported.
std::map<std::string, int> checks_of(const GateRun& run) {
  std::map<std::string, int> out;
  if (run.outcome)
    for (const Finding& f : run.findings()) ++out[f.check];
  return out;
}

GateRun gate_on(const std::map<std::string, std::string>& files) {
  TempMission m(files);
  return run_real_gate(m.dir());
}

// The good mission without its default, so that a gap is possible.
std::map<std::string, std::string> without_default() {
  auto files = good_mission_files();
  files["requirements.fret"] =
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n";
  files.erase("alternatives/navigation/hold_position.xml");
  return files;
}

TEST(OneFinding, AnEmptyRangeStopsEveryGuardCheck) {
  auto files = without_default();
  files["domain.fret"] =
      "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n"
      "integer y in [4, 2]\nassume y_positive: y > 0\n";
  const GateRun run = gate_on(files);
  ASSERT_TRUE(run.outcome) << run.load_error;
  const auto checks = checks_of(run);
  EXPECT_EQ(checks.count("guard-gap"), 0u) << run.text();
  EXPECT_EQ(checks.count("domain-inconsistent"), 0u) << run.text();
  ASSERT_EQ(checks.count("domain-invalid"), 1u) << run.text();
  const Finding* skipped = run.first("verification-skipped");
  ASSERT_NE(skipped, nullptr) << run.text();
  EXPECT_EQ(skipped->message,
            "navigation is not verified because the declaration of 'y' is invalid "
            "(domain.fret:3: range of 'y' is empty: lower bound 4 exceeds upper bound 2)");
  EXPECT_FALSE(run.passed());
}

TEST(OneFinding, AnInvalidDeclarationNobodyReadsStillStopsTheGuardChecks) {
  auto files = without_default();
  files["domain.fret"] = "boolean OnDust, OnRocks\ninteger y in [4, 2]\n";
  const GateRun run = gate_on(files);
  ASSERT_TRUE(run.outcome) << run.load_error;
  EXPECT_EQ(checks_of(run).count("guard-gap"), 0u) << run.text();
  EXPECT_NE(run.first("verification-skipped"), nullptr) << run.text();
}

TEST(OneFinding, AnOversizedEnumIsOneDomainInvalid) {
  std::string values;
  for (int i = 0; i <= 4096; ++i) values += (i == 0 ? "v" : ", v") + std::to_string(i);
  auto files = good_mission_files();
  files["domain.fret"] = "boolean OnDust, OnRocks\nenum zone in {" + values + "}\n";
  files["requirements.fret"] =
      "Req1: In navigation if OnDust & zone = v1 Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  const GateRun run = gate_on(files);
  ASSERT_TRUE(run.outcome) << run.load_error;
  const auto checks = checks_of(run);
  EXPECT_EQ(checks.count("domain-inconsistent"), 0u) << run.text();
  EXPECT_EQ(checks.count("ref-undeclared"), 0u) << run.text();
  ASSERT_EQ(checks.count("domain-invalid"), 1u) << run.text();
  EXPECT_EQ(checks.at("domain-invalid"), 1) << run.text();
  EXPECT_NE(run.first("verification-skipped"), nullptr) << run.text();
  EXPECT_FALSE(run.passed());
}

TEST(OneFinding, AGuardThatDividesByZeroGetsNoOverlapOrGap) {
  auto files = without_default();
  files["domain.fret"] = "boolean OnDust, OnRocks\ninteger battery in [0, 100]\n";
  files["requirements.fret"] =
      "Req1: In navigation if OnDust & battery / (battery - battery) > 1 Mission shall "
      "satisfy selected_alt = on_dust\n"
      "Req2: In navigation if battery > 50 Mission shall satisfy selected_alt = on_rocks\n";
  const GateRun run = gate_on(files);
  ASSERT_TRUE(run.outcome) << run.load_error;
  const auto checks = checks_of(run);
  EXPECT_EQ(checks.count("guard-overlap"), 0u) << run.text();
  EXPECT_EQ(checks.count("guard-gap"), 0u) << run.text();
  ASSERT_EQ(checks.count("guard-division-by-zero"), 1u) << run.text();
  const Finding* skipped = run.first("verification-skipped");
  ASSERT_NE(skipped, nullptr) << run.text();
  EXPECT_EQ(skipped->message,
            "navigation is not verified because the guard of Req1 divides by zero in a state of "
            "the domain (requirements.fret:1)");
  EXPECT_FALSE(run.passed());
}

TEST(OneFinding, AMissionXmlThatDoesNotParseNamesNoRequirement) {
  auto files = good_mission_files();
  files["mission.xml"] = "<root\n";
  const GateRun run = gate_on(files);
  ASSERT_TRUE(run.outcome) << run.load_error;
  const auto checks = checks_of(run);
  EXPECT_EQ(checks.count("ref-unknown-adaptable"), 0u) << run.text();
  EXPECT_EQ(checks.count("bt-xml"), 1u) << run.text();
  EXPECT_FALSE(run.passed());
}

}  // namespace
}  // namespace uabt::testing
