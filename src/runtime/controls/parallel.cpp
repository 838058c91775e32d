// Parallel (BT.CPP ParallelNode): ticks every child not yet completed; SUCCESS once
// `success_count` children succeeded, FAILURE once `failure_count` failed or success became
// impossible. Thresholds are read every tick; a negative one means N + 1 + value.
#include <algorithm>

#include "runtime/core.hpp"

namespace uabt::runtime::detail {

namespace {

std::int64_t threshold(std::int64_t value, std::uint32_t children) {
  return value < 0 ? std::max<std::int64_t>(children + value + 1, 0) : value;
}

void clear(Core& core, NodeId id) {
  RtNode& n = core.nodes[id];
  std::fill_n(core.child_done.begin() + n.first_child, n.child_count, std::uint8_t{0});
  n.success_count() = 0;
  n.failure_count() = 0;
}

}  // namespace

void halt_parallel(Core& core, NodeId id) {
  clear(core, id);
}

NodeStatus tick_parallel(Core& core, NodeId id) {
  const NodeParams& p = core.params[core.nodes[id].params];
  const std::int64_t success_value = core.read_int(id, p.in0, "success_count");
  const std::int64_t failure_value = core.read_int(id, p.in1, "failure_count");

  RtNode& n = core.nodes[id];
  const std::uint32_t count = n.child_count;
  const std::int64_t required_successes = threshold(success_value, count);
  const std::int64_t failure_threshold = threshold(failure_value, count);
  if (count < required_successes)
    core.fail(id, "success_count " + std::to_string(success_value) + " needs " +
                      std::to_string(required_successes) + " children, it has " +
                      std::to_string(count) + ": it can never succeed");
  if (count < failure_threshold)
    core.fail(id, "failure_count " + std::to_string(failure_value) + " needs " +
                      std::to_string(failure_threshold) + " children, it has " +
                      std::to_string(count) + ": it can never fail");

  core.set_status(id, NodeStatus::running);
  std::uint32_t skipped = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    std::uint8_t& done = core.child_done[n.first_child + i];
    if (!done) {
      const NodeStatus s = core.execute_tick(core.child(id, i));
      if (s == NodeStatus::skipped) {
        ++skipped;
      } else if (s == NodeStatus::success) {
        done = 1;
        ++n.success_count();
      } else if (s == NodeStatus::failure) {
        done = 1;
        ++n.failure_count();
      }
    }
    // Checked after every child, as BT.CPP does: a threshold reached stops the loop.
    if (n.success_count() >= required_successes ||
        (success_value < 0 && n.success_count() + skipped >= required_successes)) {
      clear(core, id);
      core.reset_children(id);
      return NodeStatus::success;
    }
    if (count - n.failure_count() < required_successes || n.failure_count() == failure_threshold) {
      clear(core, id);
      core.reset_children(id);
      return NodeStatus::failure;
    }
  }
  return skipped == count ? NodeStatus::skipped : NodeStatus::running;
}

}  // namespace uabt::runtime::detail
