#include "gate/contract.hpp"

#include <algorithm>
#include <map>

#include "base/suggest.hpp"
#include "gate/proof_report.hpp"
#include "gate/proofs.hpp"
#include "monitor/property_set.hpp"
#include "report/reports.hpp"

namespace uabt::gate {

namespace {

using Requirements = std::vector<fretish::Requirement>;

Requirements guarantees_of(const load::Mission& m) {
  Requirements out;
  for (const auto& r : m.properties)
    if (!fretish::is_assumption(r)) out.push_back(r);
  return out;
}

const fretish::Requirement* find(const Requirements& in, const std::string& id) {
  for (const auto& r : in)
    if (r.id == id) return &r;
  return nullptr;
}

// `checked`'s mission proving `guarantees` on its compiled tree in its own world: its assumptions
// and Environment requirements stay, its guarantees are replaced. Verdicts by requirement id.
// `engine`, when given, is set to the engine that decided.
std::map<std::string, prove::Answer> prove_on(const Outcome& checked,
                                              const Requirements& guarantees,
                                              const prove::Options& options,
                                              std::string* engine = nullptr) {
  std::map<std::string, prove::Answer> out;
  load::Mission probe = *checked.mission;
  probe.properties.erase(
      std::remove_if(probe.properties.begin(), probe.properties.end(),
                     [](const fretish::Requirement& r) { return !fretish::is_assumption(r); }),
      probe.properties.end());
  probe.properties.insert(probe.properties.end(), guarantees.begin(), guarantees.end());
  try {
    const prove::Result result = prove_checked(checked, probe, options);
    for (const prove::Answer& a : result.answers) out[a.requirement] = a;
    if (engine != nullptr) *engine = result.engine;
  } catch (const std::exception& e) {
    for (const auto& g : guarantees) {
      prove::Answer& a = out[g.id];
      a.requirement = g.id;
      a.text = g.text;
      a.location = g.location;
      a.verdict = prove::Verdict::unsupported;
      a.reason = e.what();
    }
  }
  return out;
}

std::string status_of(const std::map<std::string, prove::Answer>& answers, const std::string& id) {
  const auto it = answers.find(id);
  if (it == answers.end()) return "";
  const prove::Answer& a = it->second;
  report::ProofAnswer shown;
  shown.verdict = prove::verdict_name(a.verdict);
  shown.depth = a.depth;
  std::string text = report::proof_verdict_text(shown);
  if (!a.reason.empty()) text += " (" + a.reason + ")";
  return text;
}

// Where a removal was said: its uplink.json entry, or the requirement that now holds the id
// (a selection requirement or an assumption), else the package.
SourceLocation removal_location(const load::Mission& merged, const std::string& id) {
  for (const auto& record : merged.merges)
    if (record.requirement == id && record.rule == "removed") return record.location;
  for (const auto& r : merged.requirements)
    if (r.id == id) return r.location;
  return {merged.uplinks.empty() ? std::string() : merged.uplinks.back(), 0, 0};
}

}  // namespace

void check_contract(const load::Mission& running, Outcome& merged, const Options& options) {
  if (!merged.mission || !merged.report.uplink) return;
  const load::Mission& now = *merged.mission;
  const Requirements before = guarantees_of(running), after = guarantees_of(now);

  // What the package changes: restated (same id, other text) or no longer stated.
  Requirements changed;
  for (const auto& g : before) {
    const fretish::Requirement* kept = find(after, g.id);
    if (kept == nullptr || kept->text != g.text) changed.push_back(g);
  }
  std::map<std::string, const load::GuaranteeConsent*> consent;
  for (const auto& c : now.consents) consent[c.requirement] = &c;

  std::vector<Finding> found;
  std::vector<std::string> old_ids;
  for (const auto& g : before) old_ids.push_back(g.id);
  for (const auto& c : now.consents) {
    if (find(before, c.requirement) != nullptr) continue;
    Finding f = make_finding("uplink-invalid",
                             "uplink.json may " + c.kind + " '" + c.requirement +
                                 "', which is not a guarantee of the mission on board",
                             c.location);
    if (const std::string hint = did_you_mean(c.requirement, old_ids); !hint.empty())
      f.notes.push_back(hint);
    found.push_back(std::move(f));
  }

  // The old statements on both versions; the new ones come from the gate's own proof step.
  std::map<std::string, prove::Answer> on_board, on_merged;
  std::string merged_engine;
  if (!changed.empty() && !merged.compiled_xml.empty()) {
    on_merged = prove_on(merged, changed, options.prove, &merged_engine);
    Outcome board;  // the version on board, compiled and read back as the gate does
    board.mission = std::make_unique<load::Mission>(running);
    std::vector<Finding> ignored;
    compile_and_read_back(running, options.compile, board, ignored);
    if (board.compiled_tree) on_board = prove_on(board, changed, options.prove);
  }
  std::map<std::string, std::string> new_status;
  if (merged.report.proofs)
    for (const auto& a : merged.report.proofs->answers)
      new_status[a.requirement] = report::proof_verdict_text(a);

  std::vector<report::ContractChange> contract;
  for (const auto& g : after)
    if (find(before, g.id) == nullptr)
      contract.push_back(
          {g.id, "added", "", g.text, "", "", new_status[g.id], "", "", false, std::nullopt});
  for (const auto& g : changed) {
    const fretish::Requirement* restated = find(after, g.id);
    const auto answer = on_merged.find(g.id);
    const bool holds =
        answer != on_merged.end() && answer->second.verdict == prove::Verdict::proved;
    const load::GuaranteeConsent* given = consent.count(g.id) ? consent[g.id] : nullptr;
    // "retire" gives the guarantee up altogether, so it also covers a weaker restatement;
    // "weaken" agrees to a weaker statement, not to none: it does not cover a removal.
    const bool covers = given && (given->kind == "retire" || restated);
    const load::GuaranteeConsent* agreed = covers ? given : nullptr;
    report::ContractChange change{g.id,
                                  restated ? (holds ? "restated" : "weakened") : "removed",
                                  g.text,
                                  restated ? restated->text : "",
                                  status_of(on_board, g.id),
                                  status_of(on_merged, g.id),
                                  restated ? new_status[g.id] : "",
                                  agreed ? agreed->kind : "",
                                  agreed ? agreed->reason : "",
                                  holds,
                                  std::nullopt};
    const SourceLocation at = restated ? restated->location : removal_location(now, g.id);
    const std::string old_on_merged = change.old_after.empty() ? "not checked" : change.old_after;
    Finding f;
    if (holds) {
      f = make_finding(restated ? "uplink-guarantee-restated" : "uplink-guarantee-removed",
                       restated ? "guarantee '" + g.id +
                                      "' is restated, and the merged mission still satisfies "
                                      "what it said before: " +
                                      g.text
                                : "guarantee '" + g.id +
                                      "' is no longer stated, and the merged mission still "
                                      "satisfies it: " +
                                      g.text,
                       at);
      f.severity = Severity::note;
    } else {
      f = make_finding(restated ? "uplink-guarantee-weakened" : "uplink-guarantee-removed",
                       "guarantee '" + g.id + "' " +
                           (restated ? "is restated in a weaker form" : "is no longer stated") +
                           ": the merged mission does not satisfy what it said before (" +
                           old_on_merged + "): " + g.text,
                       at);
      f.severity = agreed ? Severity::warning : Severity::error;
      // Said so that a guarantee broken before the uplink is not read as broken by it.
      if (!change.before.empty() && change.before != "proved")
        f.notes.push_back("the version on board does not satisfy it either (" + change.before +
                          ")");
      if (agreed)
        f.notes.push_back("uplink.json may " + agreed->kind + " it: " + agreed->reason);
      else if (given)
        f.notes.push_back(
            "uplink.json may weaken it, but the package removes it: to give it "
            "up, say so with {\"retire\": {\"" +
            g.id + "\": \"why\"}}");
      else
        f.notes.push_back(
            "if the mission may give it up, say so in the package's uplink.json: "
            "{\"" +
            std::string(restated ? "weaken" : "retire") + "\": {\"" + g.id + "\": \"why\"}}");
      if (answer != on_merged.end() && answer->second.counterexample) {
        for (const std::string& line : table_lines(*answer->second.counterexample))
          f.notes.push_back(line);
        for (const std::string& note : answer->second.counterexample->notes)
          f.notes.push_back(note);
        change.old_on_merged = report_answer(answer->second, merged_engine);
      }
    }
    f.requirements = {g.id};
    found.push_back(std::move(f));
    if (holds && agreed) {
      Finding unneeded =
          make_finding("uplink-consent-unneeded",
                       "uplink.json may " + agreed->kind + " '" + g.id +
                           "', but the merged mission still satisfies it: not needed",
                       agreed->location);
      unneeded.requirements = {g.id};
      found.push_back(std::move(unneeded));
    }
    contract.push_back(std::move(change));
  }
  // A consent for a guarantee the package leaves as it is.
  for (const auto& c : now.consents) {
    if (find(before, c.requirement) == nullptr) continue;
    if (std::any_of(changed.begin(), changed.end(),
                    [&](const fretish::Requirement& g) { return g.id == c.requirement; }))
      continue;
    Finding f = make_finding("uplink-consent-unneeded",
                             "uplink.json may " + c.kind + " '" + c.requirement +
                                 "', but the package leaves it as it is: not needed",
                             c.location);
    f.requirements = {c.requirement};
    found.push_back(std::move(f));
  }
  // Contract changes first: added, restated, weakened, removed.
  const auto rank = [](const std::string& change) {
    return change == "added" ? 0 : change == "restated" ? 1 : change == "weakened" ? 2 : 3;
  };
  std::stable_sort(contract.begin(), contract.end(),
                   [&](const report::ContractChange& a, const report::ContractChange& b) {
                     return rank(a.change) < rank(b.change);
                   });
  merged.report.uplink->contract = std::move(contract);
  auto& findings = merged.report.findings;
  findings.insert(findings.end(), found.begin(), found.end());
  keep_rejected_candidate(merged);
  sort_findings(findings);
}

}  // namespace uabt::gate
