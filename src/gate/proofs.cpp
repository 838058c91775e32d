#include "gate/proofs.hpp"

#include "bt/xml_io.hpp"
#include "monitor/property_set.hpp"
#include "prove/outcome.hpp"
#include "report/reports.hpp"
#include "runtime/source_map.hpp"

namespace uabt::gate {

void add_proofs_not_run(Outcome& outcome, const std::string& reason) {
  if (!outcome.mission || !prove::has_guarantees(*outcome.mission)) return;
  report::Proofs proofs;
  proofs.not_run = reason;
  for (const auto& r : outcome.mission->properties)
    if (!monitor::is_assumption(r)) {
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

std::string at_source(const std::string& text, const Outcome& outcome,
                      const bt::Document& compiled) {
  if (!outcome.mission) return text;
  return runtime::with_source_places(text, compiled, *outcome.mission, outcome.compiled.trace);
}

void name_sources(prove::Result& result, const Outcome& outcome, const bt::Document& compiled) {
  for (std::string& note : result.notes) note = at_source(note, outcome, compiled);
  result.engine_reason = at_source(result.engine_reason, outcome, compiled);
  if (result.vacuity)
    result.vacuity->message = at_source(result.vacuity->message, outcome, compiled);
  for (prove::Answer& a : result.answers) a.reason = at_source(a.reason, outcome, compiled);
}

void add_proofs(Outcome& outcome, const prove::Options& options, const ProofReporting& reporting) {
  if (!outcome.mission || !prove::has_guarantees(*outcome.mission) || outcome.compiled_xml.empty())
    return;
  report::Proofs replay;  // how findings and reports tell to replay a counterexample
  replay.mission_path = reporting.mission_path;
  replay.run_options = reporting.run_options;
  std::vector<Finding> found;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", found);
  if (!doc) return;  // conform reports a compiled tree that does not read back
  try {
    const prove::WorldModel world = prove::mission_world(*outcome.mission);
    prove::Result result = prove::prove(*outcome.mission, *doc, world, options);
    name_sources(result, outcome, *doc);
    std::map<std::string, std::string> written;
    if (!reporting.counterexample_dir.empty())
      for (const prove::Answer& a : result.answers)
        if (a.counterexample)
          written[a.requirement] = (std::filesystem::path(reporting.counterexample_dir) /
                                    report::counterexample_file_name(a.requirement))
                                       .generic_string();
    found = prove::findings_of(result, written, replay);
    found.insert(found.end(), world.warnings.begin(), world.warnings.end());
    outcome.report.proofs = prove::report_proofs(result, written);
    outcome.report.proofs->mission_path = replay.mission_path;
    outcome.report.proofs->run_options = replay.run_options;
  } catch (const prove::WorldError& e) {
    found = {make_finding(e.check, e.text, e.location)};
    found.back().severity = Severity::error;  // world.json cannot be used: whatever the check
    add_proofs_not_run(outcome, "world.json cannot be read");
  } catch (const std::exception& e) {
    const std::string why = "the mission cannot be proved: " + at_source(e.what(), outcome, *doc);
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
