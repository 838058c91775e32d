#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "compile/compile.hpp"
#include "gate/gate.hpp"
#include "monitor/property_set.hpp"
#include "runtime/scenario.hpp"
#include "runtime/status.hpp"
#include "runtime/trace.hpp"

namespace uabt::manager {

using runtime::NodeStatus;
using runtime::Scenario;
using runtime::TickError;
using runtime::TraceEvent;

struct ManagerOptions {
  gate::Options gate;          // also chooses the selector style of every compiled version
  std::int64_t max_ticks = 0;  // 0: the scenario's
  bool trace_nodes = false;    // --trace-level nodes: every node status change, condition read
  // --smart-selection: EngineOptions::smart_selection (not BT.CPP's tick; same selections).
  bool smart_selection = false;
  // --monitor-trace: record what the properties read, tick by tick (ManagerRun::monitor_trace).
  bool monitor_trace = false;
};

struct ManagerRun {
  NodeStatus status = NodeStatus::idle;  // what the root returned in the last tick
  std::uint64_t ticks = 0;
  bool finished = false;  // the root completed
  // success | failure | skipped | timeout (max_ticks reached) | error (a tick threw)
  std::string verdict;
  std::optional<TickError> error;
  std::vector<TraceEvent> trace;
  std::vector<std::string> accepted_uplinks;
  std::vector<monitor::PropertyResult> properties;  // the mission properties' verdicts
  bool guarantees_failed = false;                   // a guarantee violated or not monitored
  std::uint64_t condition_ticks = 0;                // ConditionCounter over the whole run
  // With ManagerOptions::monitor_trace: a `uabt monitor` trace (JSON lines {"tick": t,
  // "state": {…}}) of every name the mission properties read, one line per tick.
  std::string monitor_trace;
  // A counterexample of `uabt prove` (Scenario::counterexample_of) replayed on a mission that
  // does not pass the gate's checks: the checks' errors. Empty for a verified mission.
  std::vector<Finding> unverified;
};

// The paper's Behavior Tree Manager: runs the gated, compiled mission in the scenario's
// simulated world. An uplink (a scenario event or an extra one) is merged onto the running
// version and goes through the whole gate; rejected, nothing changes and its findings are
// traced; accepted, only the trees that changed are swapped in between two ticks (a running
// alternative inside a changed selection tree is halted first), so branches that did not
// change keep running.
// The mission a run would start from does not pass the gate's checks: only a verified version
// runs. Carries the findings (mission-relative), for the caller to print as its user opens them.
struct NotAdmitted : std::runtime_error {
  explicit NotAdmitted(std::vector<Finding> why)
      : std::runtime_error(
            "the mission does not pass the gate's checks; only a verified version "
            "runs"),
        findings(std::move(why)) {}
  std::vector<Finding> findings;
};

class BehaviorTreeManager {
 public:
  BehaviorTreeManager(std::filesystem::path mission_dir, Scenario scenario,
                      ManagerOptions options = {});

  // Extra uplinks: (tick, package directory) as given on the command line.
  void add_uplink(std::int64_t tick, const std::string& package);

  // Throws NotAdmitted when the mission itself does not pass the gate's checks (unless the
  // scenario is a counterexample `uabt prove` wrote and the mission compiles: it then runs
  // unverified, for replay only), ScenarioError when the scenario does not fit the mission.
  ManagerRun run();

 private:
  // Types the scenario's numbers by the mission's declarations (those of the uplinks it
  // receives too), then throws ScenarioError ("file:line:col: error: …" lines) when its names
  // or values do not fit the mission (scenario_check.hpp).
  void fit_to_mission(const load::Mission& mission);

  std::filesystem::path dir_;
  Scenario scenario_;
  ManagerOptions options_;
};

// The trace as a short text summary for a terminal (trace.hpp has the JSON lines).
std::string trace_summary(const ManagerRun& run, const std::string& path_prefix = "");
// One line per mission property: its verdict at the end of the run.
std::string property_summary(const ManagerRun& run);

}  // namespace uabt::manager
