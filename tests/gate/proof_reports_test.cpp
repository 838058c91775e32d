// The gate's reports say what `uabt prove` said: one model of the proofs, one JSON shape.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gate/gate.hpp"
#include "gate/proof_report.hpp"
#include "gate/proofs.hpp"
#include "report/reports.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::gate {
namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// sample_drilling states CoolBit (violated at tick 1) and OneTool (proved).
Outcome gate_with_engine(const std::string& engine) {
  std::string error;
  auto mission = load::load_mission(uabt::testing::mission_dir("sample_drilling"), {}, error);
  EXPECT_TRUE(mission) << error;
  Options options;
  options.prove.engine = engine;
  return run_gate(std::move(*mission), options, "test");
}

TEST(GateProofReports, ASymbolicProofIsReportedInTheSymbolicEnginesTerms) {
  const Outcome outcome = gate_with_engine("symbolic");
  ASSERT_TRUE(outcome.report.proofs);
  uabt::testing::TempMission out({});
  report::write_reports(outcome.report, out.dir(), outcome.compiled_xml);
  const std::string said = "symbolic engine: BMC to depth 2, k-induction up to k = 2.";
  for (const char* file : {"summary.md", "report.html"}) {
    const std::string text = read(out.dir() / file);
    EXPECT_NE(text.find(said), std::string::npos) << file;
    EXPECT_EQ(text.find("0 states, 0 transitions"), std::string::npos) << file;
  }
  const auto findings = nlohmann::json::parse(read(out.dir() / "findings.json"));
  const auto& proofs = findings["proofs"];
  EXPECT_EQ(proofs["engine"], "symbolic");
  EXPECT_EQ(proofs["bmc_depth"], 2);
  EXPECT_EQ(proofs["induction_k"], 2);
  EXPECT_FALSE(proofs.contains("states"));
  EXPECT_EQ(proofs["summary"], said);
}

// `uabt prove --format json` is the gate's `proofs` member with the tool, mission and verdict
// around it, for either engine.
TEST(GateProofReports, ProveJsonAndFindingsJsonHaveOneShape) {
  for (const std::string engine : {"explicit", "symbolic"}) {
    const Outcome outcome = gate_with_engine(engine);
    ASSERT_TRUE(outcome.report.proofs) << engine;
    uabt::testing::TempMission out({});
    report::write_reports(outcome.report, out.dir(), outcome.compiled_xml);
    const auto gate_json = nlohmann::json::parse(read(out.dir() / "findings.json"))["proofs"];

    prove::Options options;
    options.engine = engine;
    const prove::Result result = prove_checked(outcome, *outcome.mission, options);
    auto prove_json = nlohmann::json::parse(
        result_json(result, report_proofs(result), "sample_drilling", "test"));
    EXPECT_EQ(prove_json["verdict"], "fail");
    for (const char* key : {"tool", "version", "mission", "verdict"}) prove_json.erase(key);
    EXPECT_EQ(prove_json, gate_json) << engine;
    EXPECT_EQ(gate_json["properties"][0]["counterexample"]["trace"][0]["actions"][0],
              "Drill started")
        << engine;
  }
}

}  // namespace
}  // namespace uabt::gate
