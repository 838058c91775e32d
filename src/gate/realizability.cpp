#include "gate/realizability.hpp"

#include <algorithm>
#include <set>

#include "prove/prove.hpp"
#include "realize/realize.hpp"

namespace uabt::gate {

namespace {

// Whether the proof step showed the mission's tree meeting every guarantee.
bool tree_meets_guarantees(const report::ReportInput& report) {
  if (!report.proofs || !report.proofs->not_run.empty()) return false;
  return std::all_of(report.proofs->answers.begin(), report.proofs->answers.end(),
                     [](const report::ProofAnswer& a) { return a.verdict == "proved"; });
}

}  // namespace

void add_realizability(Outcome& outcome) {
  if (!outcome.mission || !prove::has_guarantees(*outcome.mission)) return;
  const load::Mission& m = *outcome.mission;
  if (!outcome.world) return;  // world.json cannot be used: the proof step reported it
  const prove::WorldModel& world = *outcome.world;
  const realize::Result result = realize::check_realizability(m, world);
  std::set<std::string> uplinked;
  for (const auto& merge : m.merges)
    if (merge.rule != "removed") uplinked.insert(merge.requirement);
  const bool met = tree_meets_guarantees(outcome.report);
  auto& findings = outcome.report.findings;
  for (Finding f : realize::findings_of(m, result, uplinked)) {
    if (f.check == "realizability-undecided") {
      f.severity = Severity::note;
      f.notes.push_back(
          "the gate admits a tree on its proofs; `uabt realizable` fails closed on "
          "this");
    } else if (met) {
      f.severity = Severity::note;
      f.notes.push_back(
          "the mission's tree meets them in the world " +
          (world.file.empty() ? std::string("the mission describes") : world.file + " describes") +
          ": they hold through what that world does beyond the stated assumptions (state it as "
          "an assumption to make the requirements realizable on their own)");
    }
    findings.push_back(std::move(f));
  }
  keep_rejected_candidate(outcome);
  sort_findings(findings);
  outcome.report.stages.push_back("realize");
}

}  // namespace uabt::gate
