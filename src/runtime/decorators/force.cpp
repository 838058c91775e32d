// ForceSuccess / ForceFailure: any completed result becomes SUCCESS / FAILURE; RUNNING and
// SKIPPED pass through.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

namespace {

NodeStatus force(Core& core, NodeId id, NodeStatus forced) {
  core.set_status(id, NodeStatus::running);
  const NodeStatus s = core.execute_tick(core.child(id, 0));
  if (!is_completed(s)) return s;
  core.halt_child(id, 0);
  return forced;
}

}  // namespace

NodeStatus tick_force_success(Core& core, NodeId id) {
  return force(core, id, NodeStatus::success);
}

NodeStatus tick_force_failure(Core& core, NodeId id) {
  return force(core, id, NodeStatus::failure);
}

}  // namespace uabt::runtime::detail
