// ReactiveSequence: every tick starts again at child 0; a RUNNING child halts all the
// others, so a condition that turns false pre-empts the running action.
#include "runtime/core.hpp"
#include "runtime/smart_selection.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_reactive_sequence(Core& core, NodeId id) {
  const std::uint32_t count = core.nodes[id].child_count;
  // Smart re-selection: the enclosing selector may vouch that the guards hold (then the tick
  // starts at the last child, as if they had just succeeded).
  const std::uint32_t start = smart_sequence_start(core, id);
  bool all_skipped = start == 0;
  core.set_status(id, NodeStatus::running);

  for (std::uint32_t i = start; i < count; ++i) {
    const NodeStatus s = core.execute_tick(core.child(id, i));
    all_skipped = all_skipped && s == NodeStatus::skipped;
    if (s == NodeStatus::running) {
      for (std::uint32_t j = 0; j < count; ++j)
        if (j != i) core.halt_child(id, j);
      return s;
    }
    if (s == NodeStatus::failure) {
      core.reset_children(id);
      if (core.smart) core.smart->failed_in_body = i + 1 == count;
      return s;
    }
    if (s == NodeStatus::skipped) core.halt_child(id, i);  // so that it can be skipped again
  }
  core.reset_children(id);
  return all_skipped ? NodeStatus::skipped : NodeStatus::success;
}

}  // namespace uabt::runtime::detail
