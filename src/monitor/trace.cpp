#include "monitor/trace.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "base/json_input.hpp"
#include "fretish/parse.hpp"

namespace uabt::monitor {

namespace {

using nlohmann::json;

struct LineReader {
  const std::string& file;
  std::vector<Finding>& findings;
  bool ok = true;

  void error(int line, int column, std::string message) {
    findings.push_back(make_finding("trace-invalid", std::move(message), {file, line, column}));
    ok = false;
  }
};

bool blank(std::string_view s) {
  for (char c : s)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

bool read_value(const std::string& name, const json& v, std::uint64_t tick, int line,
                LineReader& reader, Trace& trace, TraceValue& value) {
  if (v.is_boolean()) {
    value.boolean = v.get<bool>();
  } else if (v.is_number()) {
    value.kind = TraceValue::Kind::number;
    value.number = v.get<double>();
    value.integer =
        v.is_number_integer() && !(v.is_number_unsigned() && v.get<std::uint64_t>() > INT64_MAX);
    if (!std::isfinite(value.number)) {
      reader.error(line, 1, "'" + name + "' is not a finite number");
      return false;
    }
  } else if (v.is_string()) {
    value.kind = TraceValue::Kind::text;
    value.text = v.get<std::string>();
    trace.strings.insert(value.text);
  } else if (v.is_null()) {
    value.kind = TraceValue::Kind::none;
  } else {
    reader.error(line, 1,
                 "'" + name + "' at tick " + std::to_string(tick) +
                     " is not a boolean, a number, a name or null (no value)");
    return false;
  }
  return true;
}

bool string_list(const json& j, std::vector<std::string>& out) {
  if (!j.is_array()) return false;
  for (const json& s : j) {
    if (!s.is_string()) return false;
    out.push_back(s.get<std::string>());
  }
  return true;
}

// "sentences": {"<id>": {"text": FRETISH, "file": f, "line": l, "column": c}}: the selection
// requirements of adaptable `a` as the run stated them, parsed at the place they came from.
bool read_sentences(const json& j, int line, LineReader& reader, TraceAdaptable& a) {
  const auto shape = [&](const std::string& id) {
    reader.error(line, 1,
                 "\"sentences\" of '" + a.id +
                     "' is {\"<id>\": {\"text\": sentence, \"file\": "
                     "name, \"line\": N, \"column\": N}}" +
                     (id.empty() ? std::string() : " ('" + id + "' is not)"));
    return false;
  };
  if (!j.is_object()) return shape("");
  for (const auto& [id, s] : j.items()) {
    if (!s.is_object() || !s.contains("text") || !s["text"].is_string() || !s.contains("file") ||
        !s["file"].is_string() || !s.contains("line") || !s["line"].is_number_unsigned() ||
        !s.contains("column") || !s["column"].is_number_unsigned())
      return shape(id);
    const fretish::TextOrigin origin{s["file"].get<std::string>(),
                                     static_cast<int>(s["line"].get<std::uint32_t>()),
                                     static_cast<int>(s["column"].get<std::uint32_t>())};
    std::vector<Finding> problems;
    std::optional<fretish::Requirement> parsed =
        fretish::parse_requirement(s["text"].get<std::string>(), origin, problems);
    std::vector<fretish::SelectionRequirement> selection;
    if (parsed) {
      parsed->id = id;
      selection = fretish::classify_selection({*parsed}, problems);
    }
    if (selection.size() != 1 || selection.front().adaptable != a.id) {
      std::string why = problems.empty() ? "it is not a selection requirement of '" + a.id + "'"
                                         : problems.front().message;
      reader.error(line, 1, "requirement '" + id + "' of '" + a.id + "': " + why);
      return false;
    }
    a.stated.push_back(std::move(selection.front()));
  }
  return true;
}

// {"<adaptable>": {"alternatives": [names], "requirements": [ids], "sentences": {…}}}
bool read_adaptables(const json& j, int line, LineReader& reader,
                     std::vector<TraceAdaptable>& out) {
  static const char* kShape =
      "a selection line is {\"selection\": {\"<adaptable>\": {\"alternatives\": [names], "
      "\"requirements\": [ids]}}}";
  if (!j.is_object()) {
    reader.error(line, 1, kShape);
    return false;
  }
  for (const auto& [id, node] : j.items()) {
    TraceAdaptable a;
    a.id = id;
    if (!node.is_object() ||
        !string_list(node.value("alternatives", json::array()), a.alternatives) ||
        !string_list(node.value("requirements", json::array()), a.requirements)) {
      reader.error(line, 1, kShape + std::string(" ('") + id + "' is not)");
      return false;
    }
    if (node.contains("sentences") && !read_sentences(node["sentences"], line, reader, a))
      return false;
    out.push_back(std::move(a));
  }
  return true;
}

// "select": {"<adaptable>": [{"alternative": name, "read": {…}, "after": id}]}
bool read_selections(const json& j, TraceTick& tick, int line, LineReader& reader, Trace& trace) {
  static const char* kShape =
      "\"select\" is {\"<adaptable>\": [{\"alternative\": name, \"read\": {\"name\": value, "
      "...}, \"after\": requirement}]}";
  if (!j.is_object()) {
    reader.error(line, 1, kShape);
    return false;
  }
  for (const auto& [id, list] : j.items()) {
    if (!list.is_array()) {
      reader.error(line, 1, kShape + std::string(" ('") + id + "' is not a list)");
      return false;
    }
    for (const json& s : list) {
      if (!s.is_object() || !s.contains("alternative") || !s["alternative"].is_string() ||
          (s.contains("read") && !s["read"].is_object()) ||
          (s.contains("after") && !s["after"].is_string())) {
        reader.error(line, 1, kShape + std::string(" (a selection of '") + id + "' is not)");
        return false;
      }
      TraceSelection selection;
      selection.adaptable = id;
      selection.alternative = s["alternative"].get<std::string>();
      trace.strings.insert(selection.alternative);
      if (s.contains("after")) selection.after = s["after"].get<std::string>();
      if (s.contains("read"))
        for (const auto& [name, v] : s["read"].items()) {
          TraceValue value;
          if (read_value(name, v, tick.tick, line, reader, trace, value))
            selection.read.emplace_back(name, std::move(value));
        }
      tick.selections.push_back(std::move(selection));
    }
  }
  return true;
}

}  // namespace

std::optional<Trace> read_trace(const std::string& content, const std::string& file,
                                std::vector<Finding>& findings) {
  LineReader reader{file, findings};
  Trace trace;
  std::vector<TraceAdaptable> pending;  // "selection" lines for the next tick
  std::size_t begin = 0;
  int line = 0;
  while (begin < content.size()) {
    std::size_t end = content.find('\n', begin);
    if (end == std::string::npos) end = content.size();
    const std::string_view text(content.data() + begin, end - begin);
    begin = end + 1;
    ++line;
    if (blank(text)) continue;
    JsonInputError error;
    std::optional<json> parsed = parse_json_input(text, error);
    if (!parsed) {
      reader.error(line, error.column, "not a trace line: " + error.message);
      return std::nullopt;
    }
    json j = std::move(*parsed);
    if (j.is_object() && !j.contains("tick") && j.contains("selection")) {
      if (!read_adaptables(j["selection"], line, reader, pending)) return std::nullopt;
      trace.records_selections = true;
      for (const TraceAdaptable& a : pending)
        trace.strings.insert(a.alternatives.begin(), a.alternatives.end());
      continue;
    }
    if (!j.is_object() || !j.contains("tick") || !j["tick"].is_number_unsigned() ||
        !j.contains("state") || !j["state"].is_object()) {
      reader.error(line, 1,
                   "a trace line is {\"tick\": N, \"state\": {\"name\": value, ...}} with N a "
                   "whole number");
      return std::nullopt;
    }
    TraceTick tick;
    tick.tick = j["tick"].get<std::uint64_t>();
    tick.line = line;
    tick.adaptables = std::move(pending);
    pending.clear();
    if (!trace.ticks.empty() && tick.tick != trace.ticks.back().tick + 1) {
      reader.error(line, 1,
                   "tick " + std::to_string(tick.tick) + " follows tick " +
                       std::to_string(trace.ticks.back().tick) +
                       ": a trace has one line per tick, in order");
      return std::nullopt;
    }
    for (const auto& [name, v] : j["state"].items()) {
      TraceValue value;
      if (!read_value(name, v, tick.tick, line, reader, trace, value)) continue;
      trace.names.insert(name);
      tick.state.emplace_back(name, std::move(value));
    }
    if (j.contains("select")) {
      if (!read_selections(j["select"], tick, line, reader, trace)) return std::nullopt;
      trace.records_selections = true;
    }
    trace.ticks.push_back(std::move(tick));
  }
  if (!reader.ok) return std::nullopt;
  return trace;
}

}  // namespace uabt::monitor
