// SequenceWithMemory (v3: SequenceStar): a Sequence that keeps its index on FAILURE, and on
// halt (BT.CPP leaves current_child_idx_ alone there too), so children that succeeded are
// not ticked again. A child that was IDLE and succeeds at once yields: the wake-up signal,
// then RUNNING, so that the root is ticked again within the same tick (BT.CPP 4.10).
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_sequence_with_memory(Core& core, NodeId id) {
  RtNode& n = core.nodes[id];
  const auto count = static_cast<std::int32_t>(n.child_count);
  if (n.status == NodeStatus::idle) n.skipped_count() = 0;
  core.set_status(id, NodeStatus::running);

  while (n.current_child_idx() < count) {
    const NodeId child = core.child(id, static_cast<std::uint32_t>(n.current_child_idx()));
    const NodeStatus before = core.nodes[child].status;
    const NodeStatus s = core.execute_tick(child);
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::failure) {
      // Only the failed child and those after it are reset; the index stays.
      for (auto i = static_cast<std::uint32_t>(n.current_child_idx()); i < n.child_count; ++i)
        core.halt_child(id, i);
      return s;
    }
    ++n.current_child_idx();
    if (s == NodeStatus::skipped) {
      ++n.skipped_count();
    } else if (before == NodeStatus::idle && n.current_child_idx() < count) {
      core.emit_wake_up(id);
      return NodeStatus::running;
    }
  }
  const bool all_skipped = n.skipped_count() == count;
  core.reset_children(id);
  n.current_child_idx() = 0;
  n.skipped_count() = 0;
  return all_skipped ? NodeStatus::skipped : NodeStatus::success;
}

}  // namespace uabt::runtime::detail
