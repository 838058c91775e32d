#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "campaign/campaign.hpp"
#include "compile/compile.hpp"
#include "conform/conform.hpp"
#include "load/mission.hpp"
#include "prove/prove.hpp"
#include "report/model.hpp"
#include "verify/verify.hpp"

namespace uabt::gate {

// How the reports name what the proof step writes; presentation only, never the verdict.
struct ProofReporting {
  // Where the reports put each counterexample's scenario (counterexamples/<id>.json under it),
  // as the user sees that path; "" when none are written.
  std::string counterexample_dir;
  // The mission path and run options of the replay command the reports show.
  std::string mission_path;
  std::string run_options;
};

struct Options {
  verify::Options verify;
  compile::Options compile;
  conform::Options conform;
  prove::Options prove;
  ProofReporting proof_reporting;
};

// The outcome of the pre-uplink gate on one mission: load → verify guards → compile →
// conform the compiled tree → prove the guarantees. It passes only when no stage reported an
// error; anything inconclusive is an error (fail closed).
struct Outcome {
  std::unique_ptr<load::Mission> mission;  // owned here: `report.mission` points into it
  verify::Result verification;
  compile::Result compiled;
  std::string compiled_xml;  // "" when the mission did not compile
  // compiled_xml as read back (what conform checks and prove proves); none when it does not.
  std::optional<bt::Document> compiled_tree;
  conform::Result conformance;
  report::ReportInput report;
  std::optional<campaign::Campaign> campaign;  // set by add_test_campaign when it built one
  // world.json as the proof step read it, for the steps after it; none before it ran, or when
  // world.json cannot be used (the proof step reports it).
  std::optional<prove::WorldModel> world;

  bool passed() const { return report.passed(); }
};

// The gate's one admission decision (ARCHITECTURE §12), the same for `gate`, `gate --uplink`,
// `run --uplink` and a scenario's uplink event: every check of check_mission, then, when they
// pass, every guarantee proved on the compiled tree in the mission's world.json and the
// guarantees' realizability decided (a failed check leaves the proofs "not checked" in the
// report).
Outcome run_gate(load::Mission mission, const Options& options, const std::string& tool_version);

// The checks alone, without the proof step: load findings, mission properties, verify,
// compile, conform. `uabt prove` uses it to obtain the compiled tree it proves. Stages that
// cannot run (nothing compiled) are left out of `report.stages`; their absence is itself a
// failure because the load errors that stopped them are in the findings.
Outcome check_mission(load::Mission mission, const Options& options,
                      const std::string& tool_version);

// Compiles `mission` into `out.compiled` and, when it compiles, writes `out.compiled_xml` and
// reads it back into `out.compiled_tree` (what conform checks and prove proves); the read-back
// findings go to `read_findings`.
void compile_and_read_back(const load::Mission& mission, const compile::Options& options,
                           Outcome& out, std::vector<Finding>& read_findings);

// A failing gate keeps the candidate as compiled.rejected.xml: the report and what it says
// about the tree point there. Call after adding findings; nothing when the outcome passes.
void keep_rejected_candidate(Outcome& outcome);

// The test campaign of a gated mission (ARCHITECTURE §13), for the testbed: built when the gate
// passed, with one more scenario per behaviour change of an uplink (report.uplink), and
// summarised in report.campaign with its scenarios under `directory` (as the report names
// it). Information only: it adds no finding and never changes the verdict.
void add_test_campaign(Outcome& outcome, const Options& options, const std::string& directory);

// Writes the campaign's files (scenarios, campaign.json, junit.xml) to `dir`; files an earlier
// run left there and this one did not write are removed, so that the directory always
// describes one run (and goes when there is no campaign).
void write_test_campaign(const Outcome& outcome, const std::filesystem::path& dir);

}  // namespace uabt::gate
