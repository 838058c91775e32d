#include "report/impact.hpp"

#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"

namespace uabt::report {

namespace {

std::string shown(const std::string& alternative) {
  return alternative.empty() ? "(nothing: the node fails)" : alternative;
}

nlohmann::ordered_json value_json(const Value& v) {
  switch (v.kind) {
    case Value::Kind::boolean: return v.boolean;
    case Value::Kind::integer: return v.integer;
    case Value::Kind::real: return v.text;
    case Value::Kind::enumeration: return v.text;
  }
  return nullptr;
}

}  // namespace

std::string impact_text(const verify::Impact& impact) {
  std::string out;
  for (const auto& node : impact.nodes) {
    out += node.adaptable + ": " + node.status;
    if (node.counted)
      out += " (" + std::to_string(node.changed_states) + " of " + std::to_string(node.states) +
             " states change their alternative)";
    else if (!node.not_counted_reason.empty() && node.status == "changed")
      out += " (states not counted: " + node.not_counted_reason + ")";
    out += "\n";
    for (const auto& c : node.changes) {
      out += "  " + shown(c.from) + " -> " + shown(c.to);
      if (node.counted) out += ": " + std::to_string(c.states) + " states";
      out += "\n    e.g. " + format_state(c.example) + "\n";
    }
  }
  if (!impact.findings.empty()) out += format_text(impact.findings);
  return out;
}

std::string impact_json(const verify::Impact& impact) {
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (const auto& node : impact.nodes) {
    nlohmann::ordered_json changes = nlohmann::ordered_json::array();
    for (const auto& c : node.changes) {
      nlohmann::ordered_json example = nlohmann::ordered_json::object();
      for (const auto& [name, value] : c.example) example[name] = value_json(value);
      nlohmann::ordered_json j;
      j["from"] = c.from.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.from);
      j["to"] = c.to.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.to);
      j["from_requirement"] = c.from_requirement;
      j["to_requirement"] = c.to_requirement;
      if (node.counted) j["states"] = c.states;
      j["example"] = std::move(example);
      changes.push_back(std::move(j));
    }
    nlohmann::ordered_json j;
    j["adaptable"] = node.adaptable;
    j["status"] = node.status;
    j["counted"] = node.counted;
    if (node.counted) {
      j["states"] = node.states;
      j["changed_states"] = node.changed_states;
    } else if (!node.not_counted_reason.empty()) {
      j["not_counted_reason"] = node.not_counted_reason;
    }
    j["changes"] = std::move(changes);
    nodes.push_back(std::move(j));
  }
  nlohmann::ordered_json findings = nlohmann::ordered_json::array();
  for (const auto& f : impact.findings)
    findings.push_back({{"check", f.check}, {"message", f.message}, {"adaptable", f.adaptable}});
  nlohmann::ordered_json root;
  root["tool"] = "uabt";
  root["nodes"] = std::move(nodes);
  root["findings"] = std::move(findings);
  return root.dump(2) + "\n";
}

}  // namespace uabt::report
