#include "conform/context.hpp"

#include "conform/compare.hpp"

namespace uabt::conform {

std::string root_path(const bt::TreeDef& tree) {
  return tree.id + "/" + tree.root.tag;
}

bool is_remap_attribute(const std::string& name, int bt_format) {
  return bt_format == 3 ? name == "__shared_blackboard" : name == "_autoremap";
}

bool shares_blackboard(const bt::Node& call, int bt_format) {
  for (const auto& [key, value] : call.attributes)
    if (is_remap_attribute(key, bt_format) && value == "true") return true;
  return false;
}

std::vector<std::string> remapping_attributes(const bt::Node& call, int bt_format) {
  std::vector<std::string> out;
  for (const auto& [key, value] : call.attributes) {
    if (key == "ID" || key == "name") continue;
    if (is_remap_attribute(key, bt_format) && value == "true") continue;
    out.push_back(key + "=\"" + value + "\"");
  }
  return out;
}

std::optional<std::string> extra_attribute(const bt::Node& n) {
  for (const auto& [key, value] : n.attributes) {
    if (key == "name" || (key == "ID" && n.tag != n.kind())) continue;
    return key + "=\"" + value + "\"";
  }
  return std::nullopt;
}

std::vector<std::string> Context::alternatives_called(const std::string& adaptable,
                                                      const std::string& tree_id) const {
  std::vector<std::string> out;
  for (const auto& alt : mission_.alternatives)
    if (alt.adaptable == adaptable && alt.tree_id == tree_id) out.push_back(alt.name);
  const bt::TreeDef* tree = compiled_.find_tree(tree_id);
  if (!out.empty() || tree == nullptr) return out;
  for (const auto& alt : mission_.alternatives) {
    if (alt.adaptable != adaptable) continue;
    const bt::TreeDef* source = alt.document.find_tree(alt.tree_id);
    if (source != nullptr && same_tree(source->root, tree->root)) out.push_back(alt.name);
  }
  return out;
}

Context::Context(const load::Mission& mission, const bt::Document& compiled)
    : mission_(mission), compiled_(compiled) {
  // The robot's declarations win over what a file says about a node.
  for (const auto& model : compiled_.node_models) families_[model.id] = model.family;
  for (const auto& model : mission_.tree.node_models) families_[model.id] = model.family;
  if (mission_.nodes)
    for (const auto& model : *mission_.nodes) families_[model.id] = model.family;
}

Finding& Context::report(const std::string& check, std::string message, const bt::Node& node,
                         const std::string& path) {
  Finding f = make_finding(check, std::move(message), {compiled_.file, node.line, node.column});
  f.node_path = path;
  findings_.push_back(std::move(f));
  return findings_.back();
}

Finding& Context::report_at_tree(const std::string& check, std::string message,
                                 const bt::TreeDef* tree, const std::string& path) {
  SourceLocation at{compiled_.file, compiled_.root_line, 0};
  if (tree != nullptr) at = {compiled_.file, tree->line, tree->column};
  Finding f = make_finding(check, std::move(message), at);
  f.node_path = path;
  findings_.push_back(std::move(f));
  return findings_.back();
}

std::string Context::declared_family(const std::string& kind) const {
  const auto it = families_.find(kind);
  return it == families_.end() ? std::string() : it->second;
}

}  // namespace uabt::conform
