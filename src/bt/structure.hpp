#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"

namespace uabt::bt {

inline constexpr int kMaxDepth = 256;

struct StructureOptions {
  // Node IDs the robot registers (nodes.xml), plus those of <TreeNodesModel>s. When
  // `known_nodes_given` is false, unknown leaves are assumed to be the robot's actions.
  std::vector<std::string> known_nodes;
  bool known_nodes_given = false;
  bool allow_adaptable = true;  // false for compiled trees: <Adaptable> is then an error
  // Families of the robot's nodes (nodes.xml, <TreeNodesModel>): a custom Control or
  // Decorator may have children. A node neither built in nor listed here is a leaf.
  std::vector<NodeModel> node_models;
};

// BehaviorTree.CPP's load rules over a set of trees (one mission with its alternatives):
// child counts per family, <BehaviorTree> one child, <SubTree> no children and an existing
// target, no SubTree cycles, depth <= 256, valid IDs, <Adaptable> a leaf with an ID.
// Findings are `bt-structure` at the offending node.
std::vector<Finding> check_structure(const std::vector<const TreeDef*>& trees,
                                     const StructureOptions& options);

}  // namespace uabt::bt
