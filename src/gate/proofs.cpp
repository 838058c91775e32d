#include "gate/proofs.hpp"

#include <stdexcept>

#include "gate/proof_report.hpp"
#include "monitor/property_set.hpp"
#include "prove/world_model.hpp"
#include "report/reports.hpp"
#include "runtime/source_map.hpp"

namespace uabt::gate {

void add_proofs_not_run(Outcome& outcome, const std::string& reason) {
  if (!outcome.mission || !prove::has_guarantees(*outcome.mission)) return;
  report::Proofs proofs;
  proofs.not_run = reason;
  for (const auto& r : outcome.mission->properties)
    if (!fretish::is_assumption(r)) {
      report::ProofAnswer answer;
      answer.requirement = r.id;
      answer.text = r.text;
      answer.location = r.location;
      answer.verdict = "unsupported";
      answer.reason = reason;
      proofs.answers.push_back(std::move(answer));
    }
  outcome.report.proofs = std::move(proofs);
}

prove::Result prove_checked(const Outcome& checked, const load::Mission& mission,
                            const prove::Options& options, std::vector<Finding>* warnings) {
  if (!checked.compiled_tree) throw std::runtime_error("the compiled tree does not read back");
  const auto at_source = [&](const std::string& text) {
    return runtime::with_source_places(text, *checked.compiled_tree, *checked.mission,
                                       checked.compiled.trace);
  };
  std::optional<prove::WorldModel> loaded;  // when the proof step has not read it
  const prove::WorldModel& world =
      checked.world ? *checked.world : loaded.emplace(prove::mission_world(mission));
  if (warnings) *warnings = world.warnings;
  prove::Result result;
  try {
    result = prove::prove(mission, *checked.compiled_tree, world, options);
  } catch (const prove::WorldError&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(at_source(e.what()));
  }
  for (std::string& note : result.notes) note = at_source(note);
  result.engine_reason = at_source(result.engine_reason);
  if (result.vacuity) result.vacuity->message = at_source(result.vacuity->message);
  for (prove::Answer& a : result.answers) a.reason = at_source(a.reason);
  return result;
}

void add_proofs(Outcome& outcome, const prove::Options& options, const ProofReporting& reporting) {
  // Conform reports a compiled tree that does not read back.
  if (!outcome.mission || !prove::has_guarantees(*outcome.mission) || !outcome.compiled_tree)
    return;
  report::Proofs replay;  // how findings and reports tell to replay a counterexample
  replay.mission_path = reporting.mission_path;
  replay.run_options = reporting.run_options;
  std::vector<Finding> found, warnings;
  try {
    outcome.world = prove::mission_world(*outcome.mission);
    const prove::Result result = prove_checked(outcome, *outcome.mission, options, &warnings);
    std::map<std::string, std::string> written;
    if (!reporting.counterexample_dir.empty())
      for (const prove::Answer& a : result.answers)
        if (a.counterexample)
          written[a.requirement] = (std::filesystem::path(reporting.counterexample_dir) /
                                    report::counterexample_file_name(a.requirement))
                                       .generic_string();
    found = findings_of(result, written, replay);
    found.insert(found.end(), warnings.begin(), warnings.end());
    outcome.report.proofs = report_proofs(result, written);
    outcome.report.proofs->mission_path = replay.mission_path;
    outcome.report.proofs->run_options = replay.run_options;
  } catch (const prove::WorldError& e) {
    found = {make_finding(e.check, e.text, e.location)};
    found.back().severity = Severity::error;  // world.json cannot be used: whatever the check
    add_proofs_not_run(outcome, "world.json cannot be read");
  } catch (const std::exception& e) {
    const std::string why = std::string("the mission cannot be proved: ") + e.what();
    found = {make_finding("prove-bounded", why, {outcome.mission->requirements_file, 0, 0})};
    add_proofs_not_run(outcome, why);
  }
  auto& findings = outcome.report.findings;
  findings.insert(findings.end(), found.begin(), found.end());
  keep_rejected_candidate(outcome);
  sort_findings(findings);
  outcome.report.stages.push_back("prove");
}

}  // namespace uabt::gate
