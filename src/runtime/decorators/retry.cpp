// RetryUntilSuccessful (num_attempts, -1 = forever; v3 spelling RetryUntilSuccesful): ticks
// the child again, within the same tick, each time it fails; SUCCESS ends it.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_retry_until_successful(Core& core, NodeId id) {
  const Input& input = core.params[core.nodes[id].params].in0;
  std::int64_t attempts = 0;
  if (!core.read_int(id, input, "num_attempts", attempts)) return NodeStatus::failure;
  RtNode& n = core.nodes[id];
  bool again = n.a < attempts || attempts == -1;
  core.set_status(id, NodeStatus::running);

  std::uint32_t rounds = 0;
  while (again) {
    const NodeStatus s = core.execute_tick(core.child(id, 0));
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::success) {
      n.a = 0;
      core.halt_child(id, 0);
      return s;
    }
    core.halt_child(id, 0);
    if (s == NodeStatus::skipped) return s;
    if (n.a < INT32_MAX) ++n.a;
    // BT.CPP reads num_attempts again here: the child may have changed it.
    if (!core.read_int(id, input, "num_attempts", attempts)) return NodeStatus::failure;
    again = n.a < attempts || attempts == -1;
    if (again && ++rounds >= core.options.max_loop_rounds_per_tick) return NodeStatus::running;
  }
  n.a = 0;
  return NodeStatus::failure;
}

}  // namespace uabt::runtime::detail
