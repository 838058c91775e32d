#pragma once
#include "load/mission.hpp"

namespace uabt::load {

// With a nodes.xml, every node of the mission and of every alternative that BehaviorTree.CPP
// does not build in must be registered there, with its ports: an unknown node or port makes
// BT.CPP refuse the tree at load (`ref-unknown-node`, `ref-unknown-port`); an input port with
// no default that the tree leaves unset fails when the node reads it (`ref-missing-port`).
void check_registered_nodes(Mission& m);

}  // namespace uabt::load
