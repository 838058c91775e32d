// A robot leaf (any leaf that is not a BT.CPP built-in): the World ticks and halts it.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_world_leaf(Core& core, NodeId id) {
  return core.world->tick_leaf(core.leaf_context(id));
}

void halt_world_leaf(Core& core, NodeId id) {
  core.world->halt_leaf(core.leaf_context(id));
}

}  // namespace uabt::runtime::detail
