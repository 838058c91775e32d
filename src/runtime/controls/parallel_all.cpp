// ParallelAll (BT.CPP ParallelAllNode): ticks every child until all completed, then FAILURE
// if at least `max_failures` failed (negative: N + 1 + value), else SUCCESS.
#include <algorithm>

#include "runtime/core.hpp"

namespace uabt::runtime::detail {

void halt_parallel_all(Core& core, NodeId id) {
  RtNode& n = core.nodes[id];
  std::fill_n(core.child_done.begin() + n.first_child, n.child_count, std::uint8_t{0});
  n.failure_count() = 0;
}

NodeStatus tick_parallel_all(Core& core, NodeId id) {
  const NodeParams& p = core.params[core.nodes[id].params];
  const std::int64_t max_failures = core.read_int(id, p.in0, "max_failures");

  RtNode& n = core.nodes[id];
  const std::uint32_t count = n.child_count;
  const std::int64_t failure_threshold =
      max_failures < 0 ? std::max<std::int64_t>(count + max_failures + 1, 0) : max_failures;
  if (count < failure_threshold)
    core.fail(id, "max_failures " + std::to_string(max_failures) + " needs " +
                      std::to_string(failure_threshold) + " children, it has " +
                      std::to_string(count) + ": it can never fail");

  core.set_status(id, NodeStatus::running);
  std::uint32_t skipped = 0;
  std::uint32_t completed = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    std::uint8_t& done = core.child_done[n.first_child + i];
    if (done) {
      ++completed;
      continue;
    }
    const NodeStatus s = core.execute_tick(core.child(id, i));
    if (s == NodeStatus::success || s == NodeStatus::failure) {
      done = 1;
      ++completed;
      if (s == NodeStatus::failure) ++n.failure_count();
    } else if (s == NodeStatus::skipped) {
      ++skipped;
    }
  }
  if (skipped == count) return NodeStatus::skipped;
  if (skipped + completed >= count) {
    core.reset_children(id);
    const NodeStatus result =
        n.failure_count() >= failure_threshold ? NodeStatus::failure : NodeStatus::success;
    halt_parallel_all(core, id);
    return result;
  }
  return NodeStatus::running;
}

}  // namespace uabt::runtime::detail
