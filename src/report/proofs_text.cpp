// The Proofs section of summary.md and the proofs in findings.json.
#include <nlohmann/json.hpp>

#include "base/number_text.hpp"
#include "report/common.hpp"
#include "report/proof_timeline.hpp"
#include "report/proofs.hpp"

namespace uabt::report {

namespace {

// Markdown shows at most this many ticks of a timeline (the last ones); report.html shows all.
constexpr std::size_t kMarkdownTicks = 30;

std::string markdown_cell(const detail::TimelineCell& c) {
  switch (c.kind) {
    case detail::CellKind::on: return "■";
    case detail::CellKind::off: return "□";
    case detail::CellKind::running:
      return c.text == "running" ? "▬" : detail::markdown_text(c.text);
    case detail::CellKind::idle:
    case detail::CellKind::text: break;
  }
  return detail::markdown_text(c.text);
}

void timeline_markdown(const ProofAnswer& a, const ProofCounterexample& cex, const Proofs& proofs,
                       std::string& out) {
  out += "\n#### " + detail::markdown_code(a.requirement) + " is violated at tick " +
         std::to_string(cex.tick) + "\n\n" +
         detail::markdown_code(detail::location_text(a.location)) + " " +
         detail::markdown_text(a.text) + "\n\n";
  const std::size_t first =
      cex.ticks.size() > kMarkdownTicks ? cex.ticks.size() - kMarkdownTicks : 0;
  if (first > 0)
    out += "Ticks 1 to " + std::to_string(cex.ticks[first - 1].tick) +
           " are left out here; report.html shows them.\n\n";
  out += "| tick |";
  std::string rule = "|---|";
  for (std::size_t i = first; i < cex.ticks.size(); ++i) {
    const std::string tick = std::to_string(cex.ticks[i].tick);
    out += " " + (cex.ticks[i].tick == cex.tick ? "**" + tick + " ✗**" : tick) + " |";
    rule += ":-:|";
  }
  out += "\n" + rule + "\n";
  for (const detail::TimelineRow& row : detail::timeline_of(cex)) {
    out += "| " +
           (row.kind == detail::RowKind::root ? detail::markdown_text(row.label)
                                              : detail::markdown_code(row.label)) +
           " |";
    for (std::size_t i = first; i < row.cells.size(); ++i)
      out += " " + markdown_cell(row.cells[i]) + " |";
    out += "\n";
  }
  out += "\n■ true, □ false, ▬ action running. Replay: " +
         detail::markdown_code(replay_command(proofs, cex.scenario_file)) + "\n";
  for (const std::string& note : cex.notes) out += "\nNote: " + detail::markdown_text(note) + "\n";
}

}  // namespace

std::string proofs_markdown(const Proofs& proofs) {
  if (proofs.answers.empty()) return "";
  std::string out = "\n### Proofs\n\n" + detail::markdown_text(proofs_summary(proofs)) + "\n\n";
  out += "| Guarantee | Verdict | Requirement | Location |\n|---|---|---|---|\n";
  for (const ProofAnswer& a : proofs.answers) {
    std::string verdict = proof_verdict_text(a);
    if (!a.reason.empty()) verdict += " (" + a.reason + ")";
    out += "| " + detail::markdown_code(a.requirement) + " | " +
           (a.verdict == "proved" ? detail::markdown_text(verdict)
                                  : "**" + detail::markdown_text(verdict) + "**") +
           " | " + detail::markdown_text(a.text) + " | " +
           detail::markdown_code(detail::location_text(a.location)) + " |\n";
  }
  for (const std::string& note : proofs.notes)
    out += "\nNote: " + detail::markdown_text(note) + "\n";
  for (const ProofAnswer& a : proofs.answers)
    if (a.counterexample) timeline_markdown(a, *a.counterexample, proofs, out);
  return out;
}

nlohmann::ordered_json proofs_json(const Proofs& proofs) {
  using Json = nlohmann::ordered_json;
  const auto location = [](const SourceLocation& at) {
    return Json{{"file", at.file}, {"line", at.line}, {"column", at.column}};
  };
  Json out = Json::object();
  if (!proofs.not_run.empty()) out["not_run"] = proofs.not_run;
  out["engine"] = proofs.engine;
  if (proofs.engine == "symbolic") {
    out["bmc_depth"] = proofs.depth;
    out["induction_k"] = proofs.induction_k;
  } else {
    out["states"] = proofs.states;
    out["transitions"] = proofs.transitions;
  }
  if (!proofs.engine_reason.empty()) out["engine_reason"] = proofs.engine_reason;
  out["depth"] = proofs.depth;
  out["complete"] = proofs.complete;
  out["summary"] = proofs_summary(proofs);
  if (proofs.vacuity)
    out["vacuity"] = {{"message", proofs.vacuity->message},
                      {"location", location(proofs.vacuity->location)}};
  Json answers = Json::array();
  for (const ProofAnswer& a : proofs.answers) {
    Json j = Json::object();
    j["id"] = a.requirement;
    j["verdict"] = a.verdict;
    j["location"] = location(a.location);
    j["depth"] = a.depth;
    if (!a.method.empty()) j["method"] = a.method;
    if (a.first_trigger) j["first_trigger"] = *a.first_trigger;
    if (!a.reason.empty()) j["reason"] = a.reason;
    if (a.counterexample) {
      const ProofCounterexample& cex = *a.counterexample;
      Json trace = Json::array();
      for (const ProofTick& t : cex.ticks) {
        Json values = state_json(t.values);
        Json actions = Json::array();
        for (const auto& [action, event] : t.actions)
          actions.push_back(event.empty() ? action : action + " " + event);
        trace.push_back(
            {{"tick", t.tick}, {"root", t.root}, {"values", values}, {"actions", actions}});
      }
      Json c = Json::object();
      c["tick"] = cex.tick;
      c["scenario"] = Json::parse(cex.scenario, nullptr, false);
      if (!cex.scenario_file.empty()) c["scenario_file"] = cex.scenario_file;
      c["replay"] = replay_command(proofs, cex.scenario_file);
      c["trace"] = std::move(trace);
      if (!cex.notes.empty()) c["notes"] = cex.notes;
      j["counterexample"] = std::move(c);
    }
    answers.push_back(std::move(j));
  }
  out["properties"] = std::move(answers);
  out["notes"] = proofs.notes;
  return out;
}

}  // namespace uabt::report
