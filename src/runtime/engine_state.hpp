#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/engine.hpp"

namespace uabt::runtime {

// Everything a tick can change in an engine, taken between two ticks: node statuses and
// counters, Parallel completion flags, every blackboard entry and the wake-up signal that
// carries into the next tick. A model checker saves it, explores one tick, and restores it to
// explore the next choice. Only valid for the engine it was taken from, with no hot swap in
// between.
struct EngineState {
  std::vector<NodeStatus> status;
  std::vector<std::int32_t> counters;  // a, b, c per node
  std::vector<std::uint8_t> child_done;
  std::vector<ScriptValue> values;  // by blackboard slot
  bool wake_up = false;
  NodeId wake_up_node = kNoNode;
  std::uint64_t tick = 0;
  NodeStatus last_result = NodeStatus::idle;

  static EngineState save(const Engine& engine);
  // Observers are not told about the statuses this puts back.
  void restore(Engine& engine) const;
  // The state as bytes, the tick number left out (two states that differ only in when they
  // were reached behave alike).
  void append_key(std::string& out) const;
  // The same bytes as save(engine).append_key(out), without the copy.
  static void append_key(const Engine& engine, std::string& out);
};

namespace detail {
struct Trail;
}

// Checkpoints within a tick, for a model checker that explores every sequence of choices a
// tick can make (prove's explicit engine). Instead of ticking again from the state before
// the tick up to the choice it changes, it restores the checkpoint taken at that choice and
// resumes the tick there (Engine::resume_tick). Restoring costs what changed since the
// checkpoint: the engine logs the state of each node it changes, once per checkpoint.
// Attached to the engine while it lives; the engine is slower by a test per node tick.
class TickTrail {
 public:
  explicit TickTrail(Engine& engine);
  ~TickTrail();
  TickTrail(const TickTrail&) = delete;
  TickTrail& operator=(const TickTrail&) = delete;

  // Before Engine::tick(): forgets every checkpoint and what changed.
  void begin();
  // Whether the tick, stopped where it is now, can be resumed by Engine::resume_tick(): it is
  // in a robot leaf without pre- or post-conditions (which has changed nothing yet: the caller
  // knows), not in a wake-up re-tick, and every node above it is one that goes on with the
  // very child it ticks when ticked again while RUNNING (Sequence, Fallback, Inverter,
  // ForceSuccess, ForceFailure, KeepRunningUntilFailure, RunOnce, SubTree) and has no
  // `_while`.
  bool resumable() const;
  // A checkpoint of the engine's state now (nodes, Parallel flags, blackboard, wake-up).
  void push();
  // Back to the last checkpoint, which stays.
  void restore();
  void pop();
  std::size_t size() const { return count_; }
  // The same bytes as EngineState::append_key(engine, out), at the cost of what changed since
  // the last checkpoint (or begin()) instead of a pass over every node.
  void append_key(std::string& out) const;

 private:
  struct Checkpoint {
    std::size_t entries = 0;
    std::vector<NodeId> path;
    std::vector<NodeId> busy;  // every node not IDLE with zero counters, ascending
    std::vector<std::uint8_t> child_done;
    std::vector<ScriptValue> values;
    bool wake_up = false;
    NodeId wake_up_node = kNoNode;
    std::uint64_t tick = 0;
    NodeStatus last_result = NodeStatus::idle;
  };
  Engine& engine_;
  std::unique_ptr<detail::Trail> trail_;
  std::vector<Checkpoint> stack_;  // the first count_ are in use (the rest keep their memory)
  std::size_t count_ = 0;
  std::vector<NodeId> busy_;  // at begin()
  bool parallel_ = true;      // the tree has a Parallel (at begin())
  mutable std::vector<NodeId> scratch_;
  // The nodes not IDLE with zero counters now, ascending.
  void busy_now(std::vector<NodeId>& out) const;
};

}  // namespace uabt::runtime
