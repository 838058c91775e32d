#include "monitor/trace.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "base/json_input.hpp"

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

}  // namespace

std::optional<Trace> read_trace(const std::string& content, const std::string& file,
                                std::vector<Finding>& findings) {
  LineReader reader{file, findings};
  Trace trace;
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
    if (!trace.ticks.empty() && tick.tick != trace.ticks.back().tick + 1) {
      reader.error(line, 1,
                   "tick " + std::to_string(tick.tick) + " follows tick " +
                       std::to_string(trace.ticks.back().tick) +
                       ": a trace has one line per tick, in order");
      return std::nullopt;
    }
    for (const auto& [name, v] : j["state"].items()) {
      TraceValue value;
      if (v.is_boolean()) {
        value.boolean = v.get<bool>();
      } else if (v.is_number()) {
        value.kind = TraceValue::Kind::number;
        value.number = v.get<double>();
        value.integer = v.is_number_integer();
        if (!std::isfinite(value.number)) {
          reader.error(line, 1, "'" + name + "' is not a finite number");
          continue;
        }
      } else if (v.is_string()) {
        value.kind = TraceValue::Kind::text;
        value.text = v.get<std::string>();
        trace.strings.insert(value.text);
      } else {
        reader.error(line, 1,
                     "'" + name + "' at tick " + std::to_string(tick.tick) +
                         " is not a boolean, a number or a name");
        continue;
      }
      trace.names.insert(name);
      tick.state.emplace_back(name, std::move(value));
    }
    trace.ticks.push_back(std::move(tick));
  }
  if (!reader.ok) return std::nullopt;
  return trace;
}

}  // namespace uabt::monitor
