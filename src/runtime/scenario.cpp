// Scenario JSON (ARCHITECTURE §8) → Scenario, with errors that point into the file.
#include "runtime/scenario.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "base/files.hpp"
#include "base/json_input.hpp"
#include "base/location.hpp"

namespace uabt::runtime {

namespace {

using Json = nlohmann::ordered_json;

// The start of every key and value of a JSON text (already known to be valid), by pointer.
class PositionScanner {
 public:
  PositionScanner(std::string_view text, Scenario& out) : t_(text), out_(out) {}
  void scan() { value(""); }

 private:
  void space() {
    while (i_ < t_.size() &&
           (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\r' || t_[i_] == '\n')) {
      if (t_[i_] == '\n') {
        ++line_;
        line_start_ = i_ + 1;
      }
      ++i_;
    }
  }
  std::pair<int, int> here() const { return {line_, static_cast<int>(i_ - line_start_) + 1}; }
  // A string token, decoded as the parser decodes it ("Dr\u0069ll" is the key Drill), so that
  // its pointer is the one the shape checks look up.
  std::string string() {
    const std::size_t start = i_;
    for (++i_; i_ < t_.size() && t_[i_] != '"'; ++i_)
      if (t_[i_] == '\\' && i_ + 1 < t_.size()) ++i_;
    ++i_;
    const auto token = t_.substr(start, i_ - start);
    const Json decoded = Json::parse(token.begin(), token.end(), nullptr, false);
    return decoded.is_string() ? decoded.get<std::string>() : std::string(token);
  }
  void value(const std::string& path) {
    space();
    if (i_ >= t_.size()) return;
    out_.value_positions[path] = here();
    const char c = t_[i_];
    if (c == '{' || c == '[') {
      ++i_;
      for (int index = 0;; ++index) {
        space();
        if (i_ >= t_.size() || t_[i_] == '}' || t_[i_] == ']') break;
        if (t_[i_] == ',') {
          ++i_;
          space();
        }
        std::string child = path + "/" + std::to_string(index);
        if (c == '{') {
          const auto at = here();
          child = path + "/" + string();
          out_.key_positions[child] = at;
          space();
          ++i_;  // ':'
        }
        value(child);
      }
      ++i_;
    } else if (c == '"') {
      string();
    } else {
      while (i_ < t_.size() &&
             std::string_view(",}] \t\r\n").find(t_[i_]) == std::string_view::npos)
        ++i_;
    }
  }

  std::string_view t_;
  Scenario& out_;
  std::size_t i_ = 0, line_start_ = 0;
  int line_ = 1;
};

[[noreturn]] void shape_error(const Scenario& s, const std::string& where,
                              const std::string& message) {
  throw ScenarioError(s.where(where, true) + ": error: " + (where.empty() ? "" : where + ": ") +
                      message);
}

ScriptValue state_value(const Json& j, const Scenario& file, const std::string& where) {
  switch (j.type()) {
    case Json::value_t::boolean: return ScriptValue::of_bool(j.get<bool>());
    case Json::value_t::number_integer: return ScriptValue::of_int(j.get<std::int64_t>());
    case Json::value_t::number_unsigned: {
      const auto u = j.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(INT64_MAX)) shape_error(file, where, "integer too large");
      return ScriptValue::of_int(static_cast<std::int64_t>(u));
    }
    case Json::value_t::number_float: return ScriptValue::of_real(j.get<double>());
    case Json::value_t::string: return ScriptValue::of_string(j.get<std::string>());
    default:
      shape_error(file, where,
                  std::string("a state value must be a boolean, a number or a string, not ") +
                      j.type_name());
  }
}

StateAssignment assignment(const Json& j, const Scenario& file, const std::string& where) {
  if (!j.is_object())
    shape_error(file, where,
                std::string("must be an object of state values, not ") + j.type_name());
  StateAssignment out;
  for (const auto& [key, value] : j.items()) {
    if (key.empty()) shape_error(file, where, "a state variable needs a name");
    out.emplace_back(key, state_value(value, file, where + "/" + key));
  }
  return out;
}

std::int64_t integer(const Json& j, const Scenario& file, const std::string& where,
                     std::int64_t minimum) {
  if (!j.is_number_integer() || (j.is_number_unsigned() && j.get<std::uint64_t>() > INT64_MAX))
    shape_error(file, where, std::string("must be an integer, not ") + j.dump());
  const auto v = j.get<std::int64_t>();
  if (v < minimum)
    shape_error(file, where,
                "must be at least " + std::to_string(minimum) + ", not " + std::to_string(v));
  return v;
}

void only_keys(const Json& j, std::initializer_list<std::string_view> allowed, const Scenario& file,
               const std::string& where) {
  for (const auto& [key, value] : j.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    throw ScenarioError(file.where(where + "/" + key) +
                        ": error: " + (where.empty() ? "" : where + ": ") + "unknown key '" + key +
                        "' (expected: " + list + ")");
  }
}

NodeStatus action_result(const Json& r, const Scenario& file, const std::string& where) {
  if (r == "success") return NodeStatus::success;
  if (r == "failure") return NodeStatus::failure;
  shape_error(file, where, "must be \"success\" or \"failure\", not " + r.dump());
}

ActionSpec action(const Json& j, const Scenario& file, const std::string& where) {
  if (!j.is_object())
    shape_error(file, where, std::string("an action must be an object, not ") + j.type_name());
  only_keys(j, {"ticks", "effects", "outputs", "result", "runs"}, file, where);
  ActionSpec spec;
  if (j.contains("ticks")) spec.ticks = integer(j["ticks"], file, where + "/ticks", 1);
  if (j.contains("effects")) spec.effects = assignment(j["effects"], file, where + "/effects");
  if (j.contains("outputs")) spec.outputs = assignment(j["outputs"], file, where + "/outputs");
  if (j.contains("result")) spec.result = action_result(j["result"], file, where + "/result");
  if (j.contains("runs")) {
    const Json& runs = j["runs"];
    if (!runs.is_array())
      shape_error(file, where + "/runs", std::string("must be an array, not ") + runs.type_name());
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const std::string at = where + "/runs/" + std::to_string(i);
      if (!runs[i].is_object())
        shape_error(file, at, std::string("a run must be an object, not ") + runs[i].type_name());
      only_keys(runs[i], {"ticks", "effects", "outputs", "result"}, file, at);
      ActionRun run;
      if (runs[i].contains("ticks")) run.ticks = integer(runs[i]["ticks"], file, at + "/ticks", 1);
      if (runs[i].contains("result"))
        run.result = action_result(runs[i]["result"], file, at + "/result");
      if (runs[i].contains("effects"))
        run.effects = assignment(runs[i]["effects"], file, at + "/effects");
      if (runs[i].contains("outputs"))
        run.outputs = assignment(runs[i]["outputs"], file, at + "/outputs");
      spec.runs.push_back(std::move(run));
    }
  }
  return spec;
}

}  // namespace

std::string Scenario::where(std::string_view pointer, bool value) const {
  const auto& map = value ? value_positions : key_positions;
  const auto it = map.find(pointer);
  if (it == map.end()) return file;
  return place_text(file, it->second.first, it->second.second);
}

bool Scenario::mentions_state(std::string_view key) const {
  auto in = [&](const StateAssignment& a) {
    return std::any_of(a.begin(), a.end(), [&](const auto& kv) { return kv.first == key; });
  };
  if (in(initial)) return true;
  for (const auto& e : events)
    if (in(e.set)) return true;
  for (const auto& [name, spec] : actions) {
    if (in(spec.effects)) return true;
    for (const ActionRun& run : spec.runs)
      if (in(run.effects)) return true;
  }
  return false;
}

Scenario parse_scenario(std::string_view text, const std::string& file) {
  JsonInputError error;
  std::optional<Json> parsed = parse_json_input<Json>(text, error);
  if (!parsed)
    throw ScenarioError(place_text(file, error.line, error.column) + ": error: " + error.message);
  Json root = std::move(*parsed);
  Scenario s;
  s.file = file;
  PositionScanner(text, s).scan();
  if (!root.is_object())
    shape_error(s, "", std::string("a scenario must be a JSON object, not ") + root.type_name());
  only_keys(
      root,
      {"max_ticks", "initial", "actions", "events", "description", "name", "counterexample_of"}, s,
      "");
  if (root.contains("counterexample_of")) {
    const Json& of = root["counterexample_of"];
    if (!of.is_string() || of.get<std::string>().empty())
      shape_error(s, "/counterexample_of", "must be the id of a guarantee, not " + of.dump());
    s.counterexample_of = of.get<std::string>();
  }

  if (root.contains("max_ticks")) s.max_ticks = integer(root["max_ticks"], s, "/max_ticks", 1);
  if (root.contains("initial")) s.initial = assignment(root["initial"], s, "/initial");
  if (root.contains("actions")) {
    const Json& actions = root["actions"];
    if (!actions.is_object())
      shape_error(s, "/actions", std::string("must be an object, not ") + actions.type_name());
    for (const auto& [name, spec] : actions.items())
      s.actions.emplace(name, action(spec, s, "/actions/" + name));
  }
  if (root.contains("events")) {
    const Json& events = root["events"];
    if (!events.is_array())
      shape_error(s, "/events", std::string("must be an array, not ") + events.type_name());
    int index = 0;
    for (const Json& e : events) {
      const std::string where = "/events/" + std::to_string(index);
      if (!e.is_object())
        shape_error(s, where, std::string("an event must be an object, not ") + e.type_name());
      only_keys(e, {"at", "set", "uplink"}, s, where);
      if (!e.contains("at")) shape_error(s, where, "an event needs \"at\" (a tick number)");
      ScenarioEvent event;
      event.index = index;
      event.at = integer(e["at"], s, where + "/at", 0);
      if (e.contains("set")) event.set = assignment(e["set"], s, where + "/set");
      if (e.contains("uplink")) {
        if (!e["uplink"].is_string() || e["uplink"].get<std::string>().empty())
          shape_error(s, where + "/uplink", "must be a non-empty path");
        event.uplink = e["uplink"].get<std::string>();
      }
      if (!e.contains("set") && !e.contains("uplink"))
        shape_error(s, where, "an event needs \"set\" or \"uplink\"");
      s.events.push_back(std::move(event));
      ++index;
    }
    std::stable_sort(s.events.begin(), s.events.end(),
                     [](const ScenarioEvent& a, const ScenarioEvent& b) { return a.at < b.at; });
  }
  return s;
}

Scenario load_scenario(const std::filesystem::path& path, const std::string& display) {
  const std::string shown = display.empty() ? path.generic_string() : display;
  std::string error;
  const auto text = read_text_file(path, error);
  if (!text) throw ScenarioError(shown + ": " + error);
  return parse_scenario(*text, shown);
}

}  // namespace uabt::runtime
