#include "gate/gate.hpp"

#include "gate/proofs.hpp"
#include "gate/properties.hpp"
#include "gate/realizability.hpp"
#include "report/reports.hpp"

namespace uabt::gate {

Outcome check_mission(load::Mission mission, const Options& options,
                      const std::string& tool_version) {
  Outcome out;
  out.mission = std::make_unique<load::Mission>(std::move(mission));
  const load::Mission& m = *out.mission;

  out.report = report::ReportInput::of(m, tool_version, {"load"});
  report::ReportInput& report = out.report;
  const std::vector<Finding> properties = check_mission_properties(m);
  report.findings.insert(report.findings.end(), properties.begin(), properties.end());

  out.verification = verify::verify_mission(m, options.verify);
  report.stages.push_back("verify");
  report.findings.insert(report.findings.end(), out.verification.findings.begin(),
                         out.verification.findings.end());
  report.coverage = out.verification.coverage;

  std::vector<Finding> read_findings;
  compile_and_read_back(m, options.compile, out, read_findings);
  report.findings.insert(report.findings.end(), out.compiled.findings.begin(),
                         out.compiled.findings.end());
  if (out.compiled.ok) {
    report.stages.push_back("compile");
    report.compiled_tree_file = "compiled.xml";
    report.findings.insert(report.findings.end(), read_findings.begin(), read_findings.end());
    if (out.compiled_tree) {
      out.conformance = conform::conform_tree(m, *out.compiled_tree, options.conform);
      report.stages.push_back("conform");
      report.findings.insert(report.findings.end(), out.conformance.findings.begin(),
                             out.conformance.findings.end());
    }
  }
  keep_rejected_candidate(out);
  sort_findings(report.findings);
  return out;
}

void compile_and_read_back(const load::Mission& mission, const compile::Options& options,
                           Outcome& out, std::vector<Finding>& read_findings) {
  out.compiled = compile::compile_mission(mission, options);
  if (!out.compiled.ok) return;
  // Read back from the bytes that will be uplinked, not taken from the in-memory document, so
  // that conform validates the writer too.
  compile::ReadBack written = compile::read_back(out.compiled, options);
  out.compiled_xml = std::move(written.xml);
  out.compiled_tree = std::move(written.tree);
  read_findings = std::move(written.findings);
}

void keep_rejected_candidate(Outcome& outcome) {
  report::ReportInput& report = outcome.report;
  if (!outcome.compiled.ok || report.passed()) return;
  report.compiled_tree_file = report::kRejectedTree;
  for (auto& f : report.findings)
    if (f.location.file == report::kCompiledTree) f.location.file = report::kRejectedTree;
}

Outcome run_gate(load::Mission mission, const Options& options, const std::string& tool_version) {
  Outcome out = check_mission(std::move(mission), options, tool_version);
  if (out.passed()) {
    add_proofs(out, options.prove, options.proof_reporting);
    add_realizability(out);
  } else
    add_proofs_not_run(out, "the gate failed before its proof step");
  return out;
}

}  // namespace uabt::gate
