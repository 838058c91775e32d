#pragma once
#include <string>
#include <vector>

#include "bt/tree.hpp"

namespace uabt::bt {

// An XML Schema (XSD 1.0) of the trees a robot with these registered nodes can load: one
// element per node ID (compact form) with an attribute per port, required when the port has
// no default, typed where the port's C++ type maps to an XSD type; the explicit form
// (<Action ID="…"/>) with the IDs of that family; BehaviorTree.CPP 4.10's built-in nodes and
// common attributes (name, _skipIf, …), <SubTree>, <include>, <TreeNodesModel> and uabt's
// <Adaptable>. Deterministic bytes: nodes by ID, ports by name.
std::string write_schema(const std::vector<NodeModel>& models);

}  // namespace uabt::bt
