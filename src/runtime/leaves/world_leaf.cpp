// A robot leaf (any leaf that is not a BT.CPP built-in): the World ticks and halts it.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

// BT.CPP's getInput() of an input port `{key}` whose entry nothing has written fails ("unable
// to find the key"), and the robot's node throws on it: the tick stops at the node. A pending
// entry (prove's environment) always has a value, so it is not resolved for this.
NodeStatus tick_world_leaf(Core& core, NodeId id) {
  const LeafContext context = core.leaf_context(id);
  for (const LeafPort& port : context.ports)
    if (port.reads_entry() && !core.bb.pending(port.slot) && core.bb.value(port.slot).empty())
      core.fail(id, "input port '" + port.name + "' reads {" + port.key +
                        "}, which nothing has written: getInput() failed because it was unable "
                        "to find the key [" +
                        port.name + "] remapped to [" + port.key + "]");
  return core.world->tick_leaf(context);
}

void halt_world_leaf(Core& core, NodeId id) {
  core.world->halt_leaf(core.leaf_context(id));
}

}  // namespace uabt::runtime::detail
