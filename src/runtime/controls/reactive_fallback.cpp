// ReactiveFallback: every tick starts again at child 0; a RUNNING child halts all the
// others, so a higher-priority child that starts to succeed pre-empts the running one.
#include "runtime/core.hpp"
#include "runtime/smart_selection.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_reactive_fallback(Core& core, NodeId id) {
  const std::uint32_t count = core.nodes[id].child_count;
  bool all_skipped = true;
  // Smart re-selection (off by default): the branches before `first` are known to fail in a
  // guard, and the guards of branch `first` to hold, as when they last ran.
  SmartSelector* smart = smart_selector(core, id);
  Reads reads;
  const std::uint32_t first =
      smart ? smart_start(core, id, *smart, core.nodes[id].status == NodeStatus::running, reads)
            : 0;
  bool clean = true;  // no branch failed in its body
  if (first > 0) all_skipped = false;
  core.set_status(id, NodeStatus::running);

  for (std::uint32_t i = first; i < count; ++i) {
    const NodeStatus s = core.execute_tick(core.child(id, i));
    all_skipped = all_skipped && s == NodeStatus::skipped;
    if (s == NodeStatus::running) {
      for (std::uint32_t j = 0; j < count; ++j)
        if (j != i) core.halt_child(id, j);
      if (smart) smart_done(core, *smart, s, i, clean, std::move(reads));
      return s;
    }
    if (s == NodeStatus::success) {
      core.reset_children(id);
      if (smart) smart_done(core, *smart, s, i, clean, std::move(reads));
      return s;
    }
    if (s == NodeStatus::skipped) core.halt_child(id, i);
    if (smart && s == NodeStatus::failure && core.smart->failed_in_body) clean = false;
  }
  core.reset_children(id);
  const NodeStatus result = all_skipped ? NodeStatus::skipped : NodeStatus::failure;
  if (smart) smart_done(core, *smart, result, count, clean, std::move(reads));
  return result;
}

}  // namespace uabt::runtime::detail
