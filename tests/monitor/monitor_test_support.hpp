#pragma once
// Shared by the monitor tests: reference data, random traces, and running a monitor on them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "monitor/formula.hpp"
#include "monitor/templates.hpp"
#include "pt_oracle.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {

// A requirements file parsed and lowered as `uabt monitor` lowers it: its durations in ticks,
// with the tick period `tick_seconds`; the lowering's findings join the parse's.
inline fretish::ParseResult parse_lowered(const std::string& text,
                                          std::optional<double> tick_seconds = {}) {
  fretish::ParseResult parsed = fretish::parse_requirements_file(text, "r.fret");
  fretish::lower_durations(parsed.requirements, tick_seconds, parsed.findings);
  return parsed;
}

inline std::filesystem::path fret_reference(const std::string& file) {
  return std::filesystem::path(UABT_SHARED_DIR) / "reference" / "fret" / file;
}

// Random boolean traces over the given names; each trace picks its own density per name, so
// both sparse events and long stretches occur.
inline std::vector<OracleState> random_boolean_trace(std::mt19937& rng,
                                                     const std::vector<std::string>& names,
                                                     std::size_t length) {
  std::vector<double> density;
  std::uniform_real_distribution<double> any(0.0, 1.0);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double r = any(rng);
    density.push_back(r < 0.2 ? 0.08 : r < 0.4 ? 0.92 : r);
  }
  std::vector<OracleState> trace(length);
  for (auto& state : trace)
    for (std::size_t i = 0; i < names.size(); ++i)
      state[names[i]] = OracleValue{false, any(rng) < density[i], 0, false};
  return trace;
}

inline std::string trace_text(const std::vector<OracleState>& trace) {
  std::string out;
  for (std::size_t t = 0; t < trace.size(); ++t) {
    out += std::to_string(t) + ":";
    for (const auto& [name, v] : trace[t])
      out += " " + name + "=" + (v.is_number ? std::to_string(v.number) : v.truth ? "1" : "0");
    out += "\n";
  }
  return out;
}

// semantics.json: key "scope,condition,timing,response" -> template fields.
inline nlohmann::json fret_semantics() {
  return nlohmann::json::parse(read_all(fret_reference("semantics.json")));
}

inline monitor::ScopeKind scope_from_key(const std::string& k) {
  using monitor::ScopeKind;
  for (ScopeKind s :
       {ScopeKind::null, ScopeKind::in, ScopeKind::notin, ScopeKind::only_in, ScopeKind::after,
        ScopeKind::before, ScopeKind::only_after, ScopeKind::only_before})
    if (k == monitor::scope_key(s)) return s;
  ADD_FAILURE() << "scope " << k;
  return ScopeKind::null;
}

inline monitor::ConditionKind condition_from_key(const std::string& k) {
  using monitor::ConditionKind;
  for (ConditionKind c : {ConditionKind::null, ConditionKind::regular, ConditionKind::holding})
    if (k == monitor::condition_key(c)) return c;
  ADD_FAILURE() << "condition " << k;
  return ConditionKind::null;
}

// FRET's "null" timing is its default, eventually.
inline monitor::TimingKind timing_from_key(const std::string& k) {
  using monitor::TimingKind;
  if (k == "null") return TimingKind::eventually;
  for (TimingKind t :
       {TimingKind::immediately, TimingKind::next, TimingKind::eventually, TimingKind::finally,
        TimingKind::always, TimingKind::never, TimingKind::within, TimingKind::for_ticks,
        TimingKind::after, TimingKind::until, TimingKind::before})
    if (k == monitor::timing_key(t)) return t;
  ADD_FAILURE() << "timing " << k;
  return TimingKind::eventually;
}

inline std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream s(key);
  std::string part;
  while (std::getline(s, part, ',')) parts.push_back(part);
  return parts;
}

// The shape a semantics.json key "scope,condition,timing,response" names (duration 0).
inline monitor::Shape shape_from_key(const std::string& key) {
  const auto parts = split_key(key);
  monitor::Shape shape;
  if (parts.size() < 3) {
    ADD_FAILURE() << "key " << key;
    return shape;
  }
  shape.scope = scope_from_key(parts[0]);
  shape.condition = condition_from_key(parts[1]);
  shape.timing = timing_from_key(parts[2]);
  return shape;
}

}  // namespace uabt::testing
