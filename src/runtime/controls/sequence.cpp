// Sequence and Fallback (BT.CPP SequenceNode, FallbackNode): resume at the current child;
// earlier children are not re-ticked while a later one runs. They are one loop with the two
// statuses swapped: the child status that ends the node (`stop`: FAILURE for Sequence, SUCCESS
// for Fallback) and the result when every child went past (`done`).
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

namespace {

NodeStatus tick_in_order(Core& core, NodeId id, NodeStatus stop, NodeStatus done) {
  RtNode& n = core.nodes[id];
  const auto count = static_cast<std::int32_t>(n.child_count);
  if (n.status == NodeStatus::idle) n.skipped_count() = 0;  // a new run: forget skipped children
  core.set_status(id, NodeStatus::running);

  while (n.current_child_idx() < count) {
    const NodeStatus s = core.execute_tick(core.child(id, n.current_child_idx()));
    if (s == NodeStatus::running) return s;
    if (s == stop) {
      core.reset_children(id);
      n.current_child_idx() = 0;
      return s;
    }
    if (s == NodeStatus::skipped) ++n.skipped_count();
    ++n.current_child_idx();  // `done` or SKIPPED: next child
  }
  const bool all_skipped = n.skipped_count() == count;
  core.reset_children(id);
  n.current_child_idx() = 0;
  n.skipped_count() = 0;
  return all_skipped ? NodeStatus::skipped : done;
}

}  // namespace

NodeStatus tick_sequence(Core& core, NodeId id) {
  return tick_in_order(core, id, NodeStatus::failure, NodeStatus::success);
}

NodeStatus tick_fallback(Core& core, NodeId id) {
  return tick_in_order(core, id, NodeStatus::success, NodeStatus::failure);
}

}  // namespace uabt::runtime::detail
