// IfThenElse: the condition (child 0) is ticked until it completes; the chosen branch then
// runs to completion without the condition being checked again. Without an else branch a
// failed condition is the result.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_if_then_else(Core& core, NodeId id) {
  RtNode& n = core.nodes[id];
  const std::uint32_t count = n.child_count;
  if (count != 2 && count != 3)
    core.fail(id, "IfThenElse must have 2 or 3 children, it has " + std::to_string(count));
  core.set_status(id, NodeStatus::running);

  if (n.child_idx() == 0) {
    const NodeStatus condition = core.execute_tick(core.child(id, 0));
    if (condition == NodeStatus::running) return condition;
    if (condition == NodeStatus::success) {
      n.child_idx() = 1;
    } else if (condition == NodeStatus::failure) {
      if (count != 3) return condition;
      n.child_idx() = 2;
    }
  }
  // BT.CPP throws "Something unexpected happened" here.
  if (n.child_idx() == 0) core.fail(id, "its condition was skipped: no branch to run");

  const NodeStatus s = core.execute_tick(core.child(id, static_cast<std::uint32_t>(n.child_idx())));
  if (s == NodeStatus::running) return s;
  core.reset_children(id);
  n.child_idx() = 0;
  return s;
}

}  // namespace uabt::runtime::detail
