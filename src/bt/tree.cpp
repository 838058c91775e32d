#include "bt/tree.hpp"

#include "bt/node_kinds.hpp"

namespace uabt::bt {

const std::string* Node::attribute(const std::string& name) const {
  for (const auto& [key, value] : attributes) {
    if (key == name) return &value;
  }
  return nullptr;
}

std::pair<int, int> Node::attribute_position(const std::string& name) const {
  for (std::size_t k = 0; k < attributes.size() && k < attribute_positions.size(); ++k)
    if (attributes[k].first == name) return attribute_positions[k];
  return {line, column};
}

void Node::set_attribute(const std::string& name, std::string value) {
  for (auto& [key, existing] : attributes) {
    if (key == name) {
      existing = std::move(value);
      return;
    }
  }
  attributes.emplace_back(name, std::move(value));
}

std::string Node::kind() const {
  if (is_explicit_family_tag(tag)) {
    if (const std::string* id = attribute("ID")) return *id;
  }
  return tag;
}

bool Node::operator==(const Node& other) const {
  return tag == other.tag && attributes == other.attributes && children == other.children;
}

const TreeDef* Document::find_tree(const std::string& id) const {
  for (const TreeDef& tree : trees) {
    if (tree.id == id) return &tree;
  }
  return nullptr;
}

const TreeDef* Document::main() const {
  if (!main_tree.empty()) {
    if (const TreeDef* named = find_tree(main_tree)) return named;
  }
  if (trees.size() == 1) return &trees.front();
  return nullptr;
}

std::optional<std::string> blackboard_key(const std::string& port, const std::string& value) {
  if (value.size() < 2 || value.front() != '{' || value.back() != '}') return std::nullopt;
  std::string key = value.substr(1, value.size() - 2);
  if (key == "=") key = port;
  return key;
}

}  // namespace uabt::bt
