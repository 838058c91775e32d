// The manager's trace (ARCHITECTURE §8): JSON lines for tools, a short text summary for a terminal,
// and the observer that adds every node status change and condition read at `--trace-level
// nodes`.
#pragma once
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/finding.hpp"
#include "runtime/engine.hpp"
#include "runtime/status.hpp"

namespace uabt::runtime {

// One line of the trace, with tick, event and what it concerns.
struct TraceEvent {
  std::uint64_t tick = 0;
  // select | uplink | status | node | condition | error | violation | pending | done
  std::string event;
  std::string adaptable, alternative, requirement;
  std::string verdict;  // uplink: accepted | rejected; done: success | failure | timeout | error
  std::string uplink;   // the package, for uplink events
  std::vector<std::string> swapped;  // uplink accepted: trees replaced or added
  std::vector<Finding> findings;     // uplink rejected: why
  std::uint64_t halted = 0;          // uplink accepted: running instances halted by the swap
  double latency_ms = 0.0;           // uplink: from receipt to the new tree being in place
  std::string status;    // status: the root's result after the tick; condition: its result
  std::string node;      // node, condition, error: the node's instance path
  std::string from, to;  // node: the status change
  std::vector<std::pair<std::string, ScriptValue>> reads;  // condition: what it read
  std::string message, script;                             // error: what BT.CPP would throw
  // violation: the property (requirement), its role and the values it read at `tick`
  std::string role;
  std::vector<std::pair<std::string, Value>> values;
  // pending (at the end of a run): the property held only because the run ended before its
  // deadline; `message` says what is still due, `since` the tick that triggered it.
  std::optional<std::uint64_t> since;
};

// Records, into a trace, every status change of every node ("node" events, BT.CPP's
// StatusChangeLogger order) and every tick of a condition with the values it read
// ("condition" events).
class NodeTracer : public Observer {
 public:
  NodeTracer(const Engine& engine, std::vector<TraceEvent>& trace);
  void on_status_change(NodeId node, NodeStatus previous, NodeStatus next) override;
  void on_node_ticked(NodeId node, NodeStatus result) override;

 private:
  const std::string& path(NodeId node);
  bool is_condition(NodeId node);

  const Engine& engine_;
  std::vector<TraceEvent>& trace_;
  std::vector<std::string> paths_;       // per node, "" until first needed
  std::vector<std::uint8_t> condition_;  // per node: 0 unknown, 1 condition, 2 not
};

std::string trace_json_lines(const std::vector<TraceEvent>& trace);
// A state value as it appears in the trace and in scenarios: uabt::value_json's JSON boolean,
// number (a whole real as an integer) or string; null when unset.
nlohmann::ordered_json value_json(const ScriptValue& value);
// One line per event; a completed root's status is left to the final "mission <verdict>"
// line, so that the outcome is printed once. Uplink packages and the files of a rejected one's
// findings are relative to the mission directory; `path_prefix` (path_prefix_for) makes them
// open from where uabt runs.
std::string trace_summary(const std::vector<TraceEvent>& trace,
                          const std::string& path_prefix = "");

}  // namespace uabt::runtime
