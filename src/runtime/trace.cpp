#include "runtime/trace.hpp"

#include <cctype>
#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"
#include "base/number_text.hpp"
#include "base/text.hpp"
#include "bt/node_kinds.hpp"

namespace uabt::runtime {

namespace {

using Json = nlohmann::ordered_json;

std::string reads_text(const std::vector<std::pair<std::string, ScriptValue>>& reads) {
  std::string out;
  for (const auto& [key, value] : reads)
    out += (out.empty() ? "" : ", ") + key + "=" +
           (value.empty() ? "unset" : to_value(value).to_string());
  return out;
}

}  // namespace

NodeTracer::NodeTracer(const Engine& engine, std::vector<TraceEvent>& trace)
    : engine_(engine), trace_(trace) {}

const std::string& NodeTracer::path(NodeId node) {
  if (paths_.size() <= node) paths_.resize(engine_.node_count());
  if (paths_[node].empty()) paths_[node] = engine_.instance_path(node);
  return paths_[node];
}

bool NodeTracer::is_condition(NodeId node) {
  if (condition_.size() <= node) condition_.resize(engine_.node_count(), 0);
  if (condition_[node] == 0)
    condition_[node] = bt::node_kind(engine_.info(node).kind) == bt::NodeKind::script_condition ||
                               !engine_.condition_reads(node).empty()
                           ? 1
                           : 2;
  return condition_[node] == 1;
}

void NodeTracer::on_status_change(NodeId node, NodeStatus previous, NodeStatus next) {
  TraceEvent e;
  e.tick = engine_.tick_count();
  e.event = "node";
  e.node = path(node);
  e.from = status_name(previous);
  e.to = status_name(next);
  trace_.push_back(std::move(e));
}

void NodeTracer::on_node_ticked(NodeId node, NodeStatus result) {
  if (!is_condition(node)) return;
  TraceEvent e;
  e.tick = engine_.tick_count();
  e.event = "condition";
  e.node = path(node);
  e.status = lower_case(status_name(result));
  e.reads = engine_.condition_reads(node);
  trace_.push_back(std::move(e));
}

Json value_json(const ScriptValue& v) {
  if (v.empty()) return nullptr;
  return uabt::value_json(to_value(v));
}

std::string trace_json_lines(const std::vector<TraceEvent>& trace) {
  std::string out;
  for (const auto& e : trace) {
    Json j;
    j["tick"] = e.tick;
    j["event"] = e.event;
    if (!e.node.empty()) j["node"] = e.node;
    if (!e.from.empty()) j["from"] = e.from;
    if (!e.to.empty()) j["to"] = e.to;
    if (!e.adaptable.empty()) j["adaptable"] = e.adaptable;
    if (!e.alternative.empty()) j["alternative"] = e.alternative;
    if (!e.requirement.empty()) j["requirement"] = e.requirement;
    if (!e.uplink.empty()) j["uplink"] = e.uplink;
    if (!e.verdict.empty()) j["verdict"] = e.verdict;
    if (!e.status.empty()) j["status"] = e.status;
    if (e.event == "condition") {
      Json reads = Json::object();
      for (const auto& [key, value] : e.reads) reads[key] = value_json(value);
      j["reads"] = std::move(reads);
    }
    if (e.event == "pending") {
      j["role"] = e.role;
      j["obligation"] = e.message;
      j["since"] = e.since.value_or(0);
    }
    if (e.event == "violation") {
      j["role"] = e.role;
      j["values"] = uabt::state_json(e.values);
    }
    if (!e.message.empty() && e.event != "pending") j["message"] = e.message;
    if (!e.script.empty()) j["script"] = e.script;
    if (e.event == "uplink") {
      if (e.verdict == "accepted") {
        j["swapped"] = e.swapped;
        j["halted"] = e.halted;
      }
      j["latency_ms"] = number_json(e.latency_ms);
      Json findings = Json::array();
      for (const auto& f : e.findings)
        findings.push_back({{"check", f.check},
                            {"message", f.message},
                            {"file", f.location.file},
                            {"line", f.location.line}});
      if (!findings.empty()) j["findings"] = std::move(findings);
    }
    out += j.dump() + "\n";
  }
  return out;
}

std::string trace_summary(const std::vector<TraceEvent>& trace, const std::string& path_prefix) {
  std::string out;
  for (const auto& e : trace) {
    // The outcome is the "done" line's; the status event that completes the run repeats it.
    if (e.event == "status" && e.status != "running") continue;
    // The property summary says it: "held (pending at end: …)".
    if (e.event == "pending") continue;
    out += "tick " + std::to_string(e.tick) + ": ";
    if (e.event == "select") {
      out += e.adaptable + " selects " + e.alternative + " (" + e.requirement + ")";
    } else if (e.event == "uplink") {
      out += "uplink " + user_path(e.uplink, path_prefix) + " " + e.verdict;
      if (e.verdict == "accepted") {
        out += ", swapped";
        for (const auto& id : e.swapped) out += " " + id;
      } else {
        // GCC style, indented under the event: each file as it opens from where uabt runs.
        TextOptions options;
        options.path_prefix = path_prefix;
        const std::string why = format_text(e.findings, options);
        for (std::size_t at = 0; at < why.size();) {
          const std::size_t end = why.find('\n', at);
          out += "\n    " + why.substr(at, end - at);
          at = end == std::string::npos ? why.size() : end + 1;
        }
      }
    } else if (e.event == "violation") {
      out += e.role + " " + e.requirement + " violated";
      if (!e.values.empty()) out += " (" + format_state(e.values) + ")";
    } else if (e.event == "status") {
      out += "mission " + e.status;
    } else if (e.event == "node") {
      out += e.node + ": " + e.from + " -> " + e.to;
    } else if (e.event == "condition") {
      out +=
          e.node + " read " + (e.reads.empty() ? "nothing" : reads_text(e.reads)) + ": " + e.status;
    } else if (e.event == "error") {
      out += "error: " + with_user_path(e.message, path_prefix) + "\n    node: " + e.node;
      if (!e.script.empty()) out += "\n    script: " + e.script;
    } else if (e.event == "done") {
      out += "mission " + e.verdict;
    } else {
      out += e.event;
    }
    out += "\n";
  }
  return out;
}

}  // namespace uabt::runtime
