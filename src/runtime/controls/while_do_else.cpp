// WhileDoElse: the condition (child 0) is checked on every tick; the branch it selects is
// ticked and the other one halted, so a running branch is pre-empted when the condition
// changes.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_while_do_else(Core& core, NodeId id) {
  const std::uint32_t count = core.nodes[id].child_count;
  if (count != 2 && count != 3)
    core.fail(id, "WhileDoElse must have 2 or 3 children, it has " + std::to_string(count));
  core.set_status(id, NodeStatus::running);

  const NodeStatus condition = core.execute_tick(core.child(id, 0));
  if (condition == NodeStatus::running) return condition;

  NodeStatus s = NodeStatus::idle;
  if (condition == NodeStatus::success) {
    if (count == 3) core.halt_child(id, 2);
    s = core.execute_tick(core.child(id, 1));
  } else if (condition == NodeStatus::failure) {
    if (count == 3) {
      core.halt_child(id, 1);
      s = core.execute_tick(core.child(id, 2));
    } else {
      s = NodeStatus::failure;
    }
  }
  if (s == NodeStatus::running) return s;
  core.reset_children(id);
  // BT.CPP returns IDLE here, and setting IDLE throws: the tick ends with an error.
  if (s == NodeStatus::idle)
    core.fail(id, "its condition was skipped: no branch to run (BT.CPP: the node returns IDLE)");
  return s;
}

}  // namespace uabt::runtime::detail
