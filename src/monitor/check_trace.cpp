#include "monitor/check_trace.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"
#include "base/number_text.hpp"
#include "monitor/selection_check.hpp"

namespace uabt::monitor {

namespace {

// The trace's value as the monitor reads it, or an error against the declared type.
std::optional<Val> to_val(const TraceValue& v, const fretish::Variable* declared, Symbols& symbols,
                          std::string& error) {
  using fretish::VarType;
  Val out;
  // The declared type decides what a number is (12 for a real variable is a real); an
  // undeclared number is what JSON writes.
  const bool integer = fretish::number_is_integer(declared, v.number, v.integer);
  switch (v.kind) {
    case TraceValue::Kind::boolean: out = Val::of_bool(v.boolean); break;
    case TraceValue::Kind::number:
      out = integer ? Val::of_integer(v.number) : Val::of_number(v.number);
      break;
    case TraceValue::Kind::text: out = Val::of_symbol(symbols.id(v.text)); break;
    case TraceValue::Kind::none: return out;  // no value, whatever the type
  }
  if (declared == nullptr) return out;
  const bool fits =
      (declared->type == VarType::boolean && v.kind == TraceValue::Kind::boolean) ||
      ((declared->type == VarType::integer || declared->type == VarType::real) &&
       v.kind == TraceValue::Kind::number && (declared->type == VarType::real || integer)) ||
      (declared->type == VarType::enumeration && v.kind == TraceValue::Kind::text &&
       std::find(declared->enum_values.begin(), declared->enum_values.end(), v.text) !=
           declared->enum_values.end());
  if (!fits) {
    error = std::string("the domain declares it ") + fretish::var_type_name(declared->type);
    return std::nullopt;
  }
  return out;
}

}  // namespace

TraceReport check_trace(const std::vector<fretish::Requirement>& requirements,
                        const fretish::Domain& domain, const Trace& trace,
                        const std::string& trace_file, std::vector<Finding>& findings) {
  Variables variables;
  Symbols symbols;
  for (const std::string& name : trace.names) variables.id(name);
  Vocabulary vocabulary{&variables, &symbols, trace.strings};
  for (const fretish::Variable& v : domain.variables)
    for (const std::string& literal : v.enum_values) vocabulary.literals.insert(literal);
  // Selection requirements are judged on the selections the trace records, the others are
  // mission properties.
  std::vector<Finding> ignored;  // a malformed selection requirement reads as a property
  const std::vector<fretish::SelectionRequirement> selections =
      fretish::classify_selection(requirements, ignored);
  const auto is_selection = [&](const fretish::Requirement& r) {
    return std::any_of(selections.begin(), selections.end(), [&](const auto& s) {
      return s.id == r.id && s.location.line == r.location.line &&
             s.location.column == r.location.column && s.location.file == r.location.file;
    });
  };
  std::vector<fretish::Requirement> properties_only;
  for (const fretish::Requirement& r : requirements)
    if (!is_selection(r)) properties_only.push_back(r);
  for (const fretish::SelectionRequirement& r : selections)
    vocabulary.literals.insert(r.alternative);
  PropertySet properties(properties_only, domain.assumptions, vocabulary);
  SelectionJudge judge(selections, symbols, vocabulary.literals);

  const auto to_frame_value = [&](const std::string& name, const TraceValue& value,
                                  const TraceTick& tick) -> std::optional<Val> {
    std::string error;
    const auto val = to_val(value, domain.find(name), symbols, error);
    if (!val)
      findings.push_back(make_finding("trace-invalid",
                                      "'" + name + "' at tick " + std::to_string(tick.tick) +
                                          " does not fit its type: " + error,
                                      {trace_file, tick.line, 1}));
    return val;
  };
  TraceReport report;
  std::vector<Val> frame(variables.size());
  // What the trace's selection lines stated so far, per adaptable node and requirement.
  std::map<std::string, std::map<std::string, fretish::SelectionRequirement>> stated;
  std::uint64_t last_tick = 0;
  for (const TraceTick& tick : trace.ticks) {
    for (const TraceAdaptable& a : tick.adaptables) {
      auto& before = stated[a.id];
      const bool first = before.empty();
      if (first) {
        // The run's own statement of a requirement these do not state is judged from here
        // on; one they state keeps theirs.
        judge.add(a.stated, vocabulary.literals);
      } else {
        // A later line: an uplink swapped a new version in. A requirement it restates (the
        // trace stated it otherwise before) is judged as restated, one it no longer lists
        // stops, as the run judged them.
        std::vector<fretish::SelectionRequirement> now;
        for (const std::string& id : a.requirements) {
          const auto says = std::find_if(a.stated.begin(), a.stated.end(),
                                         [&](const auto& r) { return r.id == id; });
          const auto said = before.find(id);
          const fretish::SelectionRequirement* kept = judge.current(a.id, id);
          const bool restated =
              says != a.stated.end() &&
              (kept == nullptr ||
               (said != before.end() && !SelectionJudge::same_meaning(said->second, *says)));
          if (restated)
            now.push_back(*says);
          else if (kept != nullptr)
            now.push_back(*kept);
        }
        judge.update(a.id, now, vocabulary.literals, last_tick);
      }
      for (const fretish::SelectionRequirement& r : a.stated) before.insert_or_assign(r.id, r);
      judge.set_order(a.id, a.requirements);
    }
    for (const auto& [name, value] : tick.state)
      if (const auto val = to_frame_value(name, value, tick))
        frame[static_cast<std::size_t>(*variables.find(name))] = *val;
    for (const TraceSelection& s : tick.selections) {
      SelectionRecord record{s.adaptable, s.alternative, s.after, {}};
      for (const auto& [name, value] : s.read)
        if (const auto val = to_frame_value(name, value, tick))
          record.read.emplace_back(name, *val);
      judge.observe(tick.tick, record);
    }
    properties.step(frame, tick.tick);
    last_tick = tick.tick;
    ++report.ticks;
  }
  // In the requirements' order, the assumptions last.
  const std::vector<PropertyResult> judged = judge.results(trace.records_selections);
  const std::vector<PropertyResult> monitored = properties.results();
  std::size_t next_selection = 0, next_property = 0;
  for (const fretish::Requirement& r : requirements)
    report.properties.push_back(is_selection(r) ? judged[next_selection++]
                                                : monitored[next_property++]);
  // Then the selection requirements only the trace states, as they came.
  report.properties.insert(report.properties.end(),
                           judged.begin() + static_cast<std::ptrdiff_t>(next_selection),
                           judged.end());
  report.properties.insert(report.properties.end(),
                           monitored.begin() + static_cast<std::ptrdiff_t>(next_property),
                           monitored.end());
  for (const PropertyResult& p : report.properties) {
    if (p.verdict == Verdict::not_monitored) report.pass = false;
    if (p.verdict == Verdict::violated && !p.assumption) report.failed = true;
  }
  if (has_errors(findings)) report.failed = true;
  if (report.failed) report.pass = false;
  return report;
}

std::string trace_report_json(const TraceReport& report) {
  nlohmann::ordered_json out;
  out["verdict"] = report.verdict();
  out["ticks"] = report.ticks;
  out["requirements"] = nlohmann::ordered_json::array();
  for (const PropertyResult& p : report.properties) {
    nlohmann::ordered_json r;
    r["id"] = p.id;
    r["role"] = p.assumption ? "assumption" : p.selection ? "selection" : "guarantee";
    r["verdict"] = verdict_name(p.verdict);
    r["first_violation"] = p.first_violation ? nlohmann::ordered_json(*p.first_violation)
                                             : nlohmann::ordered_json(nullptr);
    r["reason"] =
        p.reason.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(p.reason);
    r["pending"] = p.pending_since ? nlohmann::ordered_json{{"obligation", p.pending},
                                                            {"since", *p.pending_since}}
                                   : nlohmann::ordered_json(nullptr);
    if (!p.values.empty()) r["values"] = state_json(p.values);
    out["requirements"].push_back(r);
  }
  return out.dump(2) + "\n";
}

std::string trace_report_text(const TraceReport& report) {
  std::string out;
  int held = 0, violated = 0, unmonitored = 0;
  for (const PropertyResult& p : report.properties) {
    const std::string where =
        p.location.file.empty() ? std::string() : place_text(p.location) + ": ";
    const std::string role = p.assumption ? " (assumption)" : p.selection ? " (selection)" : "";
    switch (p.verdict) {
      case Verdict::held:
        ++held;
        out += where + p.id + role + ": " + held_text(p) + "\n";
        break;
      case Verdict::violated: {
        ++violated;
        out += where + p.id + role + ": violated from tick " + std::to_string(*p.first_violation);
        out += p.values.empty() ? "\n" : " (" + format_state(p.values) + ")\n";
        break;
      }
      case Verdict::not_monitored:
        ++unmonitored;
        out += where + p.id + role + ": not-monitored: " + p.reason + "\n";
        break;
    }
  }
  out += std::string("verdict: ") + report.verdict() + " (" + std::to_string(report.ticks) +
         " ticks; " + std::to_string(held) + " held, " + std::to_string(violated) + " violated, " +
         std::to_string(unmonitored) + " not monitored)\n";
  return out;
}

}  // namespace uabt::monitor
