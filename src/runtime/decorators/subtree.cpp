// SubTree: ticks the root of the tree instance it calls (own blackboard scope, see
// blackboard.hpp).
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_subtree(Core& core, NodeId id) {
  if (core.nodes[id].status == NodeStatus::idle) core.set_status(id, NodeStatus::running);
  const NodeStatus s = core.execute_tick(core.child(id, 0));
  if (is_completed(s)) core.halt_child(id, 0);
  return s;
}

}  // namespace uabt::runtime::detail
