#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"

namespace uabt::bt {

// How deep elements nest in an XML file uabt reads (the document element <root> is depth 1):
// tinyxml2, the parser of BehaviorTree.CPP 4.10 and of uabt, refuses a file whose elements
// nest deeper than this (its TINYXML2_MAX_ELEMENT_DEPTH, 100, counts the document and the
// content of the innermost element too). uabt refuses it first, at the element's line and column.
inline constexpr int kMaxXmlDepth = 98;
// How deep the nodes of one tree nest (its root node is depth 1): <root> and <BehaviorTree>
// hold the rest of a file's kMaxXmlDepth.
inline constexpr int kMaxDepth = kMaxXmlDepth - 2;

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
// target, no SubTree cycles, depth <= kMaxDepth, valid IDs, <Adaptable> a leaf with an ID.
// Findings are `bt-structure` at the offending node.
std::vector<Finding> check_structure(const std::vector<const TreeDef*>& trees,
                                     const StructureOptions& options);

}  // namespace uabt::bt
