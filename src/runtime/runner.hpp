#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bt/tree.hpp"
#include "runtime/engine.hpp"
#include "runtime/engine_state.hpp"
#include "runtime/scenario.hpp"
#include "runtime/world.hpp"

namespace uabt::runtime {

struct RunOptions {
  std::int64_t max_ticks = 0;  // 0: the scenario's max_ticks
  std::string main_tree;       // "": the document's main tree
  bool log_conditions = true;
  EngineOptions engine;
};

struct RunResult {
  NodeStatus status = NodeStatus::idle;  // what the root returned in the last tick
  std::uint64_t ticks = 0;
  bool finished = false;  // the root completed (SUCCESS/FAILURE, or SKIPPED) within max_ticks
  // success | failure | skipped (the root's last result) | timeout (max_ticks reached while it
  // ran) | error (a tick threw, see `error`).
  std::string verdict;
  std::optional<TickError> error;  // what stopped the run, as BT.CPP's tickOnce() throws it
  std::vector<LeafLogEntry> log;   // what the world's leaves did, tick by tick
  std::vector<TickError> errors;
  std::vector<ScenarioEvent> unhandled_uplinks;  // due uplinks nobody took (no on_uplink)
  Stats stats;
};

// Runs a tree in a scenario's simulated world: before each tick the events due at it are
// applied (state changes; uplinks go to on_uplink), then the root is ticked, until it
// completes, max_ticks is reached (verdict timeout), or a tick throws (verdict error: the run
// stops there, as a BT.CPP program whose tickOnce() throws). Independent of the gate: the manager
// wires uplinks through on_uplink and swaps trees through engine().
class Runner {
 public:
  // Throws LoadError (tree) as Engine::build does.
  Runner(const bt::Document& doc, Scenario scenario, RunOptions options = {},
         std::vector<bt::NodeModel> robot_nodes = {});

  Engine& engine() { return *engine_; }
  SimWorld& world() { return *world_; }
  const Scenario& scenario() const { return world_->scenario(); }

  // Called between ticks for each due event that has an "uplink", after its "set" is
  // applied and before the tick.
  std::function<void(const ScenarioEvent&, Runner&)> on_uplink;

  // Applies the events due at the next tick, then ticks once. A TickException (from the tick,
  // or from a halt an uplink caused) ends the run: error() holds it, done() is true.
  NodeStatus step();
  bool done() const;  // completed, or stopped by an error
  const std::optional<TickError>& error() const { return error_; }
  // The verdict so far (see RunResult::verdict): "timeout" while the root runs.
  std::string verdict() const;
  std::uint64_t ticks() const { return engine_->tick_count(); }
  std::int64_t max_ticks() const { return max_ticks_; }
  // Steps until done() or max_ticks, then reports.
  RunResult run();
  // Starts over in another scenario on the same tree: exactly as a Runner constructed afresh
  // from the same document, options and robot nodes (Engine::reset), without instantiating the
  // tree again. For running many scenarios on one tree; not after a hot swap.
  void restart(Scenario scenario);

 private:
  std::unique_ptr<SimWorld> new_world(Scenario scenario) const;
  void start();  // the scenario's max_ticks and initial state

  RunOptions options_;
  std::vector<bt::NodeModel> models_;  // the document's, then the robot's
  std::unique_ptr<SimWorld> world_;    // before engine_: the engine calls it until destroyed
  std::unique_ptr<Engine> engine_;
  EngineState built_;  // the engine as built, for restart()
  std::int64_t max_ticks_ = 0;
  std::size_t next_event_ = 0;
  NodeStatus last_ = NodeStatus::idle;
  std::optional<TickError> error_;
  std::vector<ScenarioEvent> unhandled_;
};

}  // namespace uabt::runtime
