#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "compile/compile.hpp"
#include "gate/gate.hpp"
#include "monitor/property_set.hpp"
#include "runtime/scenario.hpp"
#include "runtime/status.hpp"

namespace uabt::runtime {

// One line of the manager's trace (DESIGN §8): JSON lines with tick, event and what it
// concerns.
struct TraceEvent {
  std::uint64_t tick = 0;
  std::string event;  // select | uplink | status | done
  std::string adaptable, alternative, requirement;
  std::string verdict;  // uplink: accepted | rejected; done: success | failure | timeout
  std::string uplink;   // the package, for uplink events
  std::vector<std::string> swapped;  // uplink accepted: trees replaced or added
  std::vector<Finding> findings;     // uplink rejected: why
  std::uint64_t halted = 0;          // uplink accepted: running instances halted by the swap
  double latency_ms = 0.0;           // uplink: from receipt to the new tree being in place
  std::string status;                // status: the root's status after the tick
  // violation: the property (requirement), its role and the values it read at `tick`
  std::string role;
  std::vector<std::pair<std::string, std::string>> values;
};

struct ManagerOptions {
  gate::Options gate;          // also chooses the selector style of every compiled version
  std::int64_t max_ticks = 0;  // 0: the scenario's
};

struct ManagerRun {
  NodeStatus status = NodeStatus::idle;
  std::uint64_t ticks = 0;
  bool finished = false;
  std::vector<TraceEvent> trace;
  std::vector<std::string> accepted_uplinks;
  std::vector<monitor::PropertyResult> properties;  // the mission properties' verdicts
  bool guarantees_failed = false;                   // a guarantee violated or not monitored
};

// The paper's Behavior Tree Manager: runs the gated, compiled mission in the scenario's
// simulated world. An uplink (a scenario event or an extra one) is merged onto the running
// version and goes through the whole gate; rejected, nothing changes and its findings are
// traced; accepted, only the trees that changed are swapped in between two ticks (a running
// alternative inside a changed selection tree is halted first), so branches that did not
// change keep running.
class BehaviorTreeManager {
 public:
  // Throws std::runtime_error when the mission itself does not pass the gate: only a
  // verified version may run.
  BehaviorTreeManager(std::filesystem::path mission_dir, Scenario scenario,
                      ManagerOptions options = {});

  // Extra uplinks: (tick, package directory) as given on the command line.
  void add_uplink(std::int64_t tick, const std::string& package);

  ManagerRun run();

 private:
  std::filesystem::path dir_;
  Scenario scenario_;
  ManagerOptions options_;
};

// The trace as JSON lines, and as a short text summary for a terminal.
std::string trace_json_lines(const std::vector<TraceEvent>& trace);
std::string trace_summary(const ManagerRun& run);
// One line per mission property: its verdict at the end of the run.
std::string property_summary(const ManagerRun& run);

}  // namespace uabt::runtime
