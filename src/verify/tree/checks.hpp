#pragma once
// One function per whole-tree check, each in its own file; tree_checks.cpp walks the trees and
// calls them on every node.
#include <vector>

#include "base/finding.hpp"
#include "verify/tree/outcomes.hpp"
#include "verify/tree/walk.hpp"

namespace uabt::verify::tree {

// tree-output-literal, tree-output-unbound (output_ports.cpp)
void check_output_ports(const Site& site, const Registry& registry, std::vector<Finding>& out);
// tree-dead-branch (dead_branches.cpp)
void check_dead_branches(const Site& site, Outcomes& outcomes, std::vector<Finding>& out);
// tree-async-reactive (async_reactive.cpp)
void check_async_reactive(const Site& site, Outcomes& outcomes, std::vector<Finding>& out);
// tree-kind-mismatch at an explicit <Action|Condition|Control|Decorator ID=…> (kind_mismatch.cpp)
void check_node_kind(const Site& site, const Registry& registry, std::vector<Finding>& out);
// tree-kind-mismatch at a guard's condition that the robot registers as another kind
void check_guard_kinds(const Registry& registry, std::vector<Finding>& out);

}  // namespace uabt::verify::tree
