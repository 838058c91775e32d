#pragma once
#include <cstdint>
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

}  // namespace uabt::runtime
