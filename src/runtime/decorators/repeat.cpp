// Repeat (num_cycles, -1 = forever): ticks the child again, within the same tick, each time it
// succeeds; FAILURE ends it. A SKIPPED child skips the decorator, keeping the count.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_repeat(Core& core, NodeId id) {
  std::int64_t cycles = 0;
  if (!core.read_int(id, core.params[core.nodes[id].params].in0, "num_cycles", cycles))
    return NodeStatus::failure;
  RtNode& n = core.nodes[id];
  bool again = n.a < cycles || cycles == -1;
  core.set_status(id, NodeStatus::running);

  std::uint32_t rounds = 0;
  while (again) {
    const NodeStatus s = core.execute_tick(core.child(id, 0));
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::failure) {
      n.a = 0;
      core.halt_child(id, 0);
      return s;
    }
    core.halt_child(id, 0);
    if (s == NodeStatus::skipped) return s;
    if (n.a < INT32_MAX) ++n.a;
    again = n.a < cycles || cycles == -1;
    // uabt's bound on BT.CPP's in-tick loop (EngineOptions::max_loop_rounds_per_tick).
    if (again && ++rounds >= core.options.max_loop_rounds_per_tick) return NodeStatus::running;
  }
  n.a = 0;
  return NodeStatus::success;
}

}  // namespace uabt::runtime::detail
