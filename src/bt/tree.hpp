#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/location.hpp"

namespace uabt::bt {

// One XML element of a behavior tree, as written (compact or explicit syntax).
struct Node {
  std::string tag;  // element name: Sequence, MoveForward, Action (explicit), SubTree, Adaptable
  std::vector<std::pair<std::string, std::string>> attributes;  // document order
  std::vector<Node> children;
  int line = 0;  // 1-based position of '<' in the file
  int column = 0;
  // Where each attribute's name starts (line, column), parallel to `attributes` as read from
  // a file; shorter (or empty) for nodes built in memory.
  std::vector<std::pair<int, int>> attribute_positions;

  const std::string* attribute(const std::string& name) const;
  // Where `name="…"` stands; the element's own position when unknown.
  std::pair<int, int> attribute_position(const std::string& name) const;
  void set_attribute(const std::string& name, std::string value);
  // The node's registered name: ID="X" for explicit <Action|Condition|Control|Decorator ID="X">,
  // otherwise the tag.
  std::string kind() const;
  bool operator==(const Node& other) const;  // tag, attributes, children; not positions
};

// The path of child `index` of the node at `parent`, as compile's trace, conform and the
// engine's tree_path write a node: `<tree>/<RootTag>/<Tag>[i]/…`.
inline std::string child_path(const std::string& parent, const Node& child, std::size_t index) {
  return parent + "/" + child.tag + "[" + std::to_string(index) + "]";
}

// A port value that names a blackboard entry, as BT.CPP 4 reads it: `{key}` → key, and `{=}`
// → the entry named like the port; nullopt for a literal.
std::optional<std::string> blackboard_key(const std::string& port, const std::string& value);

struct TreeDef {
  std::string id;
  Node root;     // the single child of <BehaviorTree>
  int line = 0;  // of <BehaviorTree>
  int column = 0;
  std::string file;  // displayed path of the file that defined it (after <include>)
};

struct Port {
  std::string direction;  // input_port | output_port | inout_port
  std::string name, type, default_value, description;
};

// An entry of <TreeNodesModel>: a node the robot registers.
struct NodeModel {
  std::string family;  // Action | Condition | Control | Decorator | SubTree
  std::string id;
  std::vector<Port> ports;
  int line = 0;
  int column = 0;    // of the entry's '<' (0 when generated, not read)
  std::string file;  // displayed path of the file that holds the entry ("" when generated)
};

struct Document {
  std::string file;            // displayed path
  int format = 4;              // 3 or 4 (BTCPP_format; v3 files have none)
  std::string main_tree;       // main_tree_to_execute as written ("" if none)
  std::vector<TreeDef> trees;  // document order, includes resolved
  std::vector<NodeModel> node_models;
  int root_line = 0;

  const TreeDef* find_tree(const std::string& id) const;
  // main_tree_to_execute when it names a tree here, else the only tree, else nullptr.
  const TreeDef* main() const;
};

}  // namespace uabt::bt
