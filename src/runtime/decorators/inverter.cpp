// Inverter: SUCCESS and FAILURE swapped; RUNNING and SKIPPED passed through.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_inverter(Core& core, NodeId id) {
  core.set_status(id, NodeStatus::running);
  const NodeStatus s = core.execute_tick(core.child(id, 0));
  if (!is_completed(s)) return s;
  core.halt_child(id, 0);
  return s == NodeStatus::success ? NodeStatus::failure : NodeStatus::success;
}

}  // namespace uabt::runtime::detail
