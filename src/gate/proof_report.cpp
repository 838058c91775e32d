#include "gate/proof_report.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "report/reports.hpp"

namespace uabt::gate {

using Json = nlohmann::ordered_json;

std::vector<std::string> table_lines(const prove::Counterexample& cex) {
  std::vector<std::string> header = {"tick", "root"};
  if (!cex.rows.empty())
    for (const auto& [name, value] : cex.rows.front().values) header.push_back(name);
  header.push_back("actions");
  std::vector<std::vector<std::string>> cells = {header};
  for (const prove::TickRow& r : cex.rows) {
    std::vector<std::string> row = {std::to_string(r.tick), r.root};
    for (const auto& [name, value] : r.values) row.push_back(value.to_string());
    std::string actions;
    for (const auto& a : r.actions) actions += (actions.empty() ? "" : ", ") + a;
    row.push_back(actions);
    cells.push_back(std::move(row));
  }
  std::vector<std::size_t> width(header.size(), 0);
  for (const auto& row : cells)
    for (std::size_t i = 0; i < row.size() && i < width.size(); ++i)
      width[i] = std::max(width[i], row[i].size());
  std::vector<std::string> out;
  for (const auto& row : cells) {
    std::string line;
    for (std::size_t i = 0; i < row.size(); ++i) {
      line += row[i];
      if (i + 1 < row.size()) line += std::string(width[i] - row[i].size() + 2, ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out.push_back(line);
  }
  return out;
}

std::vector<Finding> findings_of(const prove::Result& result,
                                 const std::map<std::string, std::string>& written,
                                 const report::Proofs& replay) {
  std::vector<Finding> out;
  if (result.vacuity) {
    Finding f =
        make_finding("prove-vacuous", "no guarantee can be proved: " + result.vacuity->message,
                     result.vacuity->location);
    for (const prove::Answer& a : result.answers)
      if (a.verdict == prove::Verdict::vacuous) f.requirements.push_back(a.requirement);
    f.notes.push_back(
        "a proof over runs that cannot happen, or cannot go on, would hold of any "
        "guarantee: fix the world model (domain assumptions, world.json) first");
    out.push_back(std::move(f));
  }
  for (const prove::Answer& a : result.answers) {
    if (a.verdict == prove::Verdict::vacuous) continue;
    if (a.verdict == prove::Verdict::proved) {
      if (a.has_trigger && a.trigger_decided && a.first_trigger == 0) {
        Finding f = make_finding("prove-trigger-unreachable",
                                 "guarantee '" + a.requirement +
                                     "' is proved, but its trigger (its mode and condition) "
                                     "holds on no run, so it never asks anything: " +
                                     a.text,
                                 a.location);
        f.notes.push_back(result.engine == "explicit"
                              ? "explored " + std::to_string(result.states) +
                                    " reachable states and " + std::to_string(result.transitions) +
                                    " transitions"
                              : "the symbolic engine proved that no run reaches it (BMC, "
                                "k-induction and IC3/PDR)");
        f.requirements = {a.requirement};
        out.push_back(std::move(f));
      }
      continue;
    }
    Finding f;
    if (a.verdict == prove::Verdict::violated) {
      f = make_finding("prove-violated",
                       "guarantee '" + a.requirement + "' is violated at tick " +
                           std::to_string(a.depth) + ": " + a.text,
                       a.location);
      const auto it = written.find(a.requirement);
      if (it != written.end())
        f.notes.push_back("counterexample scenario: " + it->second + " (replay it with `" +
                          report::replay_command(replay, it->second) + "`)");
      for (const std::string& line : table_lines(*a.counterexample)) f.notes.push_back(line);
      for (const std::string& note : a.counterexample->notes) f.notes.push_back(note);
    } else if (a.verdict == prove::Verdict::bounded) {
      f = make_finding("prove-bounded",
                       "guarantee '" + a.requirement + "' holds up to tick " +
                           std::to_string(a.depth) + " but is not proved: " + a.text,
                       a.location);
      f.notes.push_back(
          result.engine == "symbolic"
              ? "the symbolic engine checked every run up to tick " + std::to_string(a.depth) +
                    " but could not prove it for longer runs; try --engine explicit, or shrink "
                    "the world to decide it"
              : "the search stopped at depth " + std::to_string(a.depth) + " after " +
                    std::to_string(result.states) +
                    " states; raise --depth or shrink the world to decide it");
    } else {
      f = make_finding("fretish-unsupported",
                       "guarantee '" + a.requirement + "' cannot be proved: " + a.reason,
                       a.location);
    }
    f.requirements = {a.requirement};
    out.push_back(std::move(f));
  }
  return out;
}

std::string result_json(const prove::Result& result, const report::Proofs& proofs,
                        const std::string& mission, const std::string& version) {
  Json j = Json::object();
  j["tool"] = "uabt";
  j["version"] = version;
  j["mission"] = mission;
  j["verdict"] = result.passed() ? "pass" : "fail";
  Json body = report::proofs_json(proofs);
  for (auto& [key, value] : body.items()) j[key] = std::move(value);
  return j.dump(2) + "\n";
}

report::Proofs report_proofs(const prove::Result& result,
                             const std::map<std::string, std::string>& written) {
  report::Proofs out;
  out.engine = result.engine;
  out.states = result.states;
  out.transitions = result.transitions;
  out.induction_k = result.induction_k;
  out.depth = result.depth;
  out.complete = result.complete;
  out.engine_reason = result.engine_reason;
  if (result.vacuity)
    out.vacuity = report::ProofVacuity{result.vacuity->message, result.vacuity->location};
  out.notes = result.notes;
  for (const prove::Answer& a : result.answers) {
    const auto it = written.find(a.requirement);
    out.answers.push_back(
        report_answer(a, result.engine, it == written.end() ? std::string() : it->second));
  }
  return out;
}

report::ProofAnswer report_answer(const prove::Answer& a, const std::string& engine,
                                  const std::string& scenario_file) {
  report::ProofAnswer p;
  p.requirement = a.requirement;
  p.text = a.text;
  p.location = a.location;
  p.verdict = prove::verdict_name(a.verdict);
  p.reason = a.reason;
  p.depth = a.depth;
  if (engine == "symbolic" && a.verdict == prove::Verdict::proved)
    p.method = a.by_pdr ? "IC3/PDR" : "k-induction";
  if (a.has_trigger && a.trigger_decided) p.first_trigger = a.first_trigger;
  if (a.counterexample) {
    report::ProofCounterexample c;
    c.tick = a.counterexample->tick;
    c.scenario = a.counterexample->scenario;
    c.scenario_file = scenario_file;
    c.notes = a.counterexample->notes;
    for (const prove::TickRow& row : a.counterexample->rows) {
      report::ProofTick t{row.tick, row.root, row.values, {}};
      // "Drill started": the event is the last word (the leaf's label may hold spaces).
      for (const std::string& what : row.actions) {
        const auto space = what.rfind(' ');
        if (space == std::string::npos)
          t.actions.emplace_back(what, "");
        else
          t.actions.emplace_back(what.substr(0, space), what.substr(space + 1));
      }
      c.ticks.push_back(std::move(t));
    }
    p.counterexample = std::move(c);
  }
  return p;
}

}  // namespace uabt::gate
