// Repeat (num_cycles, -1 = forever): each time the child succeeds it is reset and, while
// cycles remain, run again. A child that was IDLE and succeeded at once yields (wake-up
// signal, RUNNING: the root is ticked again within the same tick); one that had been RUNNING
// is ticked again at once (BT.CPP 4.10). FAILURE ends it; a SKIPPED child skips the
// decorator, keeping the count.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_repeat(Core& core, NodeId id) {
  const std::int64_t cycles =
      core.read_int(id, core.params[core.nodes[id].params].in0, "num_cycles");
  RtNode& n = core.nodes[id];
  bool again = n.repeat_count() < cycles || cycles == -1;
  core.set_status(id, NodeStatus::running);

  // At most two rounds: after the first the child is IDLE, so a second success yields.
  while (again) {
    const NodeId child = core.child(id, 0);
    const NodeStatus before = core.nodes[child].status;
    const NodeStatus s = core.execute_tick(child);
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::failure) {
      n.repeat_count() = 0;
      core.halt_child(id, 0);
      return s;
    }
    core.halt_child(id, 0);
    if (s == NodeStatus::skipped) return s;
    if (n.repeat_count() < INT32_MAX) ++n.repeat_count();
    again = n.repeat_count() < cycles || cycles == -1;
    if (again && before == NodeStatus::idle) {
      core.emit_wake_up(id);
      return NodeStatus::running;
    }
  }
  n.repeat_count() = 0;
  return NodeStatus::success;
}

}  // namespace uabt::runtime::detail
