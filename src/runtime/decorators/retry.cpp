// RetryUntilSuccessful (num_attempts, -1 = forever; v3 spelling RetryUntilSuccesful): the
// mirror of Repeat. Each failure of the child resets it; while attempts remain, a child
// that was IDLE yields (wake-up signal, RUNNING), one that had been RUNNING is ticked again
// at once (BT.CPP 4.10). SUCCESS ends it.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_retry_until_successful(Core& core, NodeId id) {
  const Input& input = core.params[core.nodes[id].params].in0;
  std::int64_t attempts = core.read_int(id, input, "num_attempts");
  RtNode& n = core.nodes[id];
  bool again = n.try_count() < attempts || attempts == -1;
  core.set_status(id, NodeStatus::running);

  while (again) {
    const NodeId child = core.child(id, 0);
    const NodeStatus before = core.nodes[child].status;
    const NodeStatus s = core.execute_tick(child);
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::success) {
      n.try_count() = 0;
      core.halt_child(id, 0);
      return s;
    }
    if (s == NodeStatus::skipped) {
      core.halt_child(id, 0);
      return s;
    }
    if (n.try_count() < INT32_MAX) ++n.try_count();
    // BT.CPP reads num_attempts again here (the child may have changed it) and keeps the old
    // value when that read fails.
    core.try_read_int(input, attempts);
    again = n.try_count() < attempts || attempts == -1;
    core.halt_child(id, 0);
    if (again && before == NodeStatus::idle) {
      core.emit_wake_up(id);
      return NodeStatus::running;
    }
  }
  n.try_count() = 0;
  return NodeStatus::failure;
}

}  // namespace uabt::runtime::detail
