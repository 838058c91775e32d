// RunOnce (then_skip, default true): ticks its child until it completes once; afterwards
// returns SKIPPED, or with then_skip="false" the status it completed with. Halting does not
// make it forget.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_run_once(Core& core, NodeId id) {
  bool then_skip = true;  // also when the port does not read as a boolean, as in BT.CPP
  core.try_read_bool(core.params[core.nodes[id].params].in0, then_skip);
  RtNode& n = core.nodes[id];
  if (n.already_ticked() != 0)
    return then_skip ? NodeStatus::skipped : static_cast<NodeStatus>(n.returned_status());

  core.set_status(id, NodeStatus::running);
  const NodeStatus s = core.execute_tick(core.child(id, 0));
  if (is_completed(s)) {
    n.already_ticked() = 1;
    n.returned_status() = static_cast<std::int32_t>(s);
    core.halt_child(id, 0);
  }
  return s;
}

}  // namespace uabt::runtime::detail
