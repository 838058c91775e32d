#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "base/diagnostics.hpp"
#include "gate/gate.hpp"
#include "report/reports.hpp"
#include "smt/evaluate.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::gate {
namespace {

Outcome gate_on(const std::filesystem::path& dir, const Options& options = {}) {
  std::string error;
  auto m = load::load_mission(dir, {}, error);
  EXPECT_TRUE(m.has_value()) << error;
  return run_gate(std::move(*m), options, "test");
}

std::vector<const Finding*> errors_of(const Outcome& o, const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : o.report.findings)
    if (f.check == check && f.severity == Severity::error) out.push_back(&f);
  return out;
}

// Each witness must be a state of the domain in which the finding holds, checked without Z3.
void expect_witness_shows(const Outcome& o, const Finding& f, bool overlap) {
  const load::Mission& m = *o.mission;
  ASSERT_FALSE(f.witness.empty());
  EXPECT_TRUE(smt::satisfies_domain(m.domain, f.witness)) << format_state(f.witness);
  int holding = 0;
  for (const auto* s : m.selections_for(f.adaptable))
    if (s->guard && smt::evaluate(*s->guard, m.domain, f.witness)) ++holding;
  if (overlap)
    EXPECT_GE(holding, 2) << format_state(f.witness);
  else
    EXPECT_EQ(holding, 0) << format_state(f.witness);
}

TEST(Gate, CuriosityPasses) {
  Outcome o = gate_on(uabt::testing::mission_dir("msl_curiosity"));
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  EXPECT_FALSE(o.compiled_xml.empty());
  EXPECT_EQ(o.report.stages,
            (std::vector<std::string>{"load", "verify", "compile", "conform", "prove", "realize"}));
  ASSERT_EQ(o.report.coverage.size(), 1u);
  const auto& c = o.report.coverage[0];
  EXPECT_TRUE(c.counted);
  EXPECT_EQ(c.states, 3u) << "OnDust and OnRocks never both: 3 of 4 states";
  EXPECT_EQ(c.gap_states, 0u);
  EXPECT_EQ(c.overlap_states, 0u);
}

TEST(Gate, PaperMissionFailsWithOverlapAndGapOnTheRequirementLines) {
  Outcome o = gate_on(uabt::testing::mission_dir("msl_curiosity_paper"));
  EXPECT_FALSE(o.passed());
  auto overlaps = errors_of(o, "guard-overlap");
  auto gaps = errors_of(o, "guard-gap");
  ASSERT_EQ(overlaps.size(), 1u) << format_text(o.report.findings);
  ASSERT_EQ(gaps.size(), 1u) << format_text(o.report.findings);
  EXPECT_EQ(overlaps[0]->location.file, "requirements.fret");
  EXPECT_EQ(overlaps[0]->requirements, (std::vector<std::string>{"Req1", "Req2"}));
  EXPECT_GE(overlaps[0]->location.line, 4);
  expect_witness_shows(o, *overlaps[0], true);
  expect_witness_shows(o, *gaps[0], false);
  // The compiled tree still conforms: deciding what may fly is the verifier's job.
  EXPECT_TRUE(errors_of(o, "compiled-guard-mismatch").empty());
}

TEST(Gate, ExplorationPasses) {
  Outcome o = gate_on(uabt::testing::mission_dir("exploration"));
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  ASSERT_EQ(o.report.coverage.size(), 1u);
  EXPECT_FALSE(o.report.coverage[0].counted) << "slope is real: the space is not counted";
}

TEST(Gate, ReplicationPackageGetsTheSameTwoFindings) {
  const auto dir = uabt::testing::replication_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "replication package not present";
  Outcome o = gate_on(dir);
  EXPECT_FALSE(o.passed());
  EXPECT_EQ(errors_of(o, "guard-overlap").size(), 1u) << format_text(o.report.findings);
  EXPECT_EQ(errors_of(o, "guard-gap").size(), 1u);
  std::size_t errors = 0;
  for (const auto& f : o.report.findings) errors += f.severity == Severity::error;
  EXPECT_EQ(errors, 2u) << format_text(o.report.findings);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Gate, TwoRunsWriteIdenticalBytes) {
  uabt::testing::TempMission out({});
  for (const char* name : {"msl_curiosity", "msl_curiosity_paper", "exploration"}) {
    Outcome a = gate_on(uabt::testing::mission_dir(name));
    Outcome b = gate_on(uabt::testing::mission_dir(name));
    report::write_reports(a.report, out.dir() / "a", a.compiled_xml);
    report::write_reports(b.report, out.dir() / "b", b.compiled_xml);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out.dir() / "a")) {
      ++files;
      EXPECT_EQ(read(entry.path()), read(out.dir() / "b" / entry.path().filename()))
          << name << ": " << entry.path().filename();
      EXPECT_EQ(read(entry.path()).find(uabt::testing::source_dir().string()), std::string::npos)
          << "no absolute path in " << entry.path().filename();
    }
    EXPECT_GE(files, 6u);
  }
}

TEST(Gate, InconclusiveFailsClosed) {
  uabt::testing::TempMission t(
      {{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
       {"domain.fret", "integer x\ninteger y\ninteger z\n"},
       {"requirements.fret",
        // Fermat's cubes: beyond what the solver decides in a few milliseconds.
        "R: In nav if x*x*x + y*y*y = z*z*z & x > 1 & y > 1 Mission shall satisfy selected_alt = "
        "a\n"
        "D: In nav Mission shall satisfy selected_alt = a\n"},
       {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")}});
  Options options;
  options.verify.timeout_ms = 50;
  options.conform.timeout_ms = 50;
  Outcome o = gate_on(t.dir(), options);
  EXPECT_FALSE(o.passed()) << format_text(o.report.findings);
  EXPECT_FALSE(errors_of(o, "verification-inconclusive").empty()) << format_text(o.report.findings);
}

}  // namespace
}  // namespace uabt::gate
