#include "report/proof_timeline.hpp"

#include <map>

namespace uabt::report {

std::string proof_verdict_text(const ProofAnswer& answer) {
  if (answer.verdict == "proved") return "proved";
  if (answer.verdict == "violated") return "violated at tick " + std::to_string(answer.depth);
  if (answer.verdict == "bounded")
    return "bounded: no violation up to tick " + std::to_string(answer.depth);
  return "not checked";
}

std::string counterexample_file_name(const std::string& requirement) {
  std::string out;
  for (char c : requirement) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_' || c == '.';
    out += keep ? c : '_';
  }
  // Never a hidden file nor "." / "..".
  if (out.empty() || out.front() == '.') out.insert(out.begin(), '_');
  return out + ".json";
}

namespace detail {

const char* row_kind_name(RowKind kind) {
  switch (kind) {
    case RowKind::root: return "root";
    case RowKind::value: return "value";
    case RowKind::action: return "action";
  }
  return "value";
}

std::vector<TimelineRow> timeline_of(const ProofCounterexample& cex) {
  std::vector<TimelineRow> rows;
  TimelineRow root{RowKind::root, "root", {}};
  for (const ProofTick& tick : cex.ticks) root.cells.push_back({CellKind::text, tick.root});
  rows.push_back(std::move(root));

  // Values: the names of the first tick, in the property's order (every tick reads the same).
  std::map<std::string, std::size_t> value_row;
  for (const ProofTick& tick : cex.ticks)
    for (const auto& [name, value] : tick.values)
      if (value_row.emplace(name, rows.size()).second)
        rows.push_back({RowKind::value, name, std::vector<TimelineCell>(cex.ticks.size())});
  std::map<std::string, std::size_t> action_row;
  for (const ProofTick& tick : cex.ticks)
    for (const auto& [action, event] : tick.actions)
      if (action_row.emplace(action, rows.size()).second)
        rows.push_back({RowKind::action, action,
                        std::vector<TimelineCell>(cex.ticks.size(), {CellKind::idle, ""})});

  // The replay names every action that runs in a tick (started, running, its result).
  for (std::size_t t = 0; t < cex.ticks.size(); ++t) {
    for (const auto& [name, value] : cex.ticks[t].values) {
      TimelineCell& cell = rows[value_row[name]].cells[t];
      cell.text = value.to_string();
      cell.kind = value.kind != Value::Kind::boolean ? CellKind::text
                  : value.boolean                    ? CellKind::on
                                                     : CellKind::off;
    }
    for (const auto& [action, event] : cex.ticks[t].actions) {
      TimelineCell& cell = rows[action_row[action]].cells[t];
      cell.kind = CellKind::running;
      cell.text += (cell.text.empty() ? "" : ", ") + event;
    }
  }
  return rows;
}

namespace {

std::string shell_word(const std::string& word) {
  bool plain = !word.empty();
  for (char c : word) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      std::string_view("_./:=@%+-").find(c) != std::string_view::npos;
    plain = plain && safe;
  }
  if (plain) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

}  // namespace detail

std::string engine_figures(const Proofs& proofs) {
  if (proofs.engine == "symbolic")
    return "symbolic engine: BMC to depth " + std::to_string(proofs.depth) +
           ", k-induction up to k = " + std::to_string(proofs.induction_k);
  return proofs.engine + (proofs.engine == "explicit" ? "-state" : "") +
         " engine: " + std::to_string(proofs.states) + " states, " +
         std::to_string(proofs.transitions) + " transitions, " +
         (proofs.complete ? std::string("every reachable state explored")
                          : "runs explored up to tick " + std::to_string(proofs.depth));
}

std::string proofs_summary(const Proofs& proofs) {
  if (!proofs.not_run.empty()) return "uabt prove did not run: " + proofs.not_run + ".";
  std::string out = engine_figures(proofs) + ".";
  if (!proofs.engine_reason.empty())
    out += " The symbolic engine was chosen: " + proofs.engine_reason + ".";
  if (proofs.vacuity) out += " No guarantee can be proved: " + proofs.vacuity->message + ".";
  return out;
}

std::string replay_command(const Proofs& proofs, const std::string& scenario_file) {
  std::string out =
      "uabt run " +
      (proofs.mission_path.empty() ? "MISSION" : detail::shell_word(proofs.mission_path));
  if (!proofs.run_options.empty()) out += " " + proofs.run_options;
  return out + " --scenario " +
         detail::shell_word(scenario_file.empty() ? "cex.json" : scenario_file);
}

}  // namespace uabt::report
