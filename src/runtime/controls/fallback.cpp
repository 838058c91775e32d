// Fallback (BT.CPP FallbackNode): the mirror of Sequence; the first child that succeeds ends
// it, FAILURE moves on to the next child.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_fallback(Core& core, NodeId id) {
  RtNode& n = core.nodes[id];
  const auto count = static_cast<std::int32_t>(n.child_count);
  if (n.status == NodeStatus::idle) n.skipped_count() = 0;
  core.set_status(id, NodeStatus::running);

  while (n.current_child_idx() < count) {
    const NodeStatus s = core.execute_tick(core.child(id, n.current_child_idx()));
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::success) {
      core.reset_children(id);
      n.current_child_idx() = 0;
      return s;
    }
    if (s == NodeStatus::skipped) ++n.skipped_count();
    ++n.current_child_idx();  // FAILURE or SKIPPED: next child
  }
  const bool all_skipped = n.skipped_count() == count;
  core.reset_children(id);
  n.current_child_idx() = 0;
  n.skipped_count() = 0;
  return all_skipped ? NodeStatus::skipped : NodeStatus::failure;
}

}  // namespace uabt::runtime::detail
