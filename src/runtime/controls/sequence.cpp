// Sequence (BT.CPP SequenceNode): resumes at the current child; earlier children are not
// re-ticked while a later one runs.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_sequence(Core& core, NodeId id) {
  RtNode& n = core.nodes[id];
  const auto count = static_cast<std::int32_t>(n.child_count);
  if (n.status == NodeStatus::idle) n.b = 0;  // a new run: forget skipped children
  core.set_status(id, NodeStatus::running);

  while (n.a < count) {
    const NodeStatus s = core.execute_tick(core.child(id, n.a));
    if (s == NodeStatus::running) return s;
    if (s == NodeStatus::failure) {
      core.reset_children(id);
      n.a = 0;
      return s;
    }
    if (s == NodeStatus::skipped) ++n.b;
    ++n.a;  // SUCCESS or SKIPPED: next child
  }
  const bool all_skipped = n.b == count;
  core.reset_children(id);
  n.a = 0;
  n.b = 0;
  return all_skipped ? NodeStatus::skipped : NodeStatus::success;
}

}  // namespace uabt::runtime::detail
