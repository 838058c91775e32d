// KeepRunningUntilFailure: a child's SUCCESS becomes RUNNING (it is restarted next tick);
// only FAILURE ends it.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_keep_running_until_failure(Core& core, NodeId id) {
  core.set_status(id, NodeStatus::running);
  const NodeStatus s = core.execute_tick(core.child(id, 0));
  if (s == NodeStatus::failure) {
    core.halt_child(id, 0);
    return s;
  }
  if (s == NodeStatus::success) core.halt_child(id, 0);
  // SUCCESS, RUNNING, and (as BT.CPP returns its own status then) SKIPPED.
  return NodeStatus::running;
}

}  // namespace uabt::runtime::detail
