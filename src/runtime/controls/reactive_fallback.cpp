// ReactiveFallback: every tick starts again at child 0; a RUNNING child halts all the
// others, so a higher-priority child that starts to succeed pre-empts the running one.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_reactive_fallback(Core& core, NodeId id) {
  const std::uint32_t count = core.nodes[id].child_count;
  bool all_skipped = true;
  core.set_status(id, NodeStatus::running);

  for (std::uint32_t i = 0; i < count; ++i) {
    const NodeStatus s = core.execute_tick(core.child(id, i));
    all_skipped = all_skipped && s == NodeStatus::skipped;
    if (s == NodeStatus::running) {
      for (std::uint32_t j = 0; j < count; ++j)
        if (j != i) core.halt_child(id, j);
      return s;
    }
    if (s == NodeStatus::success) {
      core.reset_children(id);
      return s;
    }
    if (s == NodeStatus::skipped) core.halt_child(id, i);
  }
  core.reset_children(id);
  return all_skipped ? NodeStatus::skipped : NodeStatus::failure;
}

}  // namespace uabt::runtime::detail
