#include "verify/tree/tree_checks.hpp"

#include <set>
#include <tuple>

#include "verify/tree/checks.hpp"

namespace uabt::verify::tree {

namespace {

// Every node of one tree, depth first in document order, with its ancestors.
template <typename Visit>
void walk(const bt::Document& document, const bt::TreeDef& tree, Visit&& visit) {
  if (tree.root.tag.empty()) return;
  std::vector<const bt::Node*> path;  // the ancestors of the node visited: the stack's nodes
  Site site{&document, &tree, &tree.root, &path};
  visit(site);
  // (node, next child to enter); a node is visited when first reached.
  std::vector<std::pair<const bt::Node*, std::size_t>> stack{{&tree.root, 0}};
  path.push_back(&tree.root);
  while (!stack.empty()) {
    auto& [node, next] = stack.back();
    if (next == node->children.size()) {
      stack.pop_back();
      path.pop_back();
      continue;
    }
    const bt::Node* child = &node->children[next++];
    site.node = child;
    visit(site);
    stack.emplace_back(child, 0);
    path.push_back(child);
  }
}

}  // namespace

std::vector<Finding> check_trees(const load::Mission& mission) {
  std::vector<Finding> out;
  const Registry registry(mission);
  Outcomes outcomes(registry);
  // A file included by several alternatives is one file: its trees are checked once.
  std::set<std::tuple<std::string, int, int>> checked;
  // A finding in an alternative belongs to its adaptable node (its JUnit suite, JSON fields).
  auto check_document = [&](const bt::Document& document, const load::Alternative* alternative) {
    const std::size_t first = out.size();
    for (const auto& tree : document.trees) {
      if (!checked.insert({tree.file, tree.line, tree.column}).second) continue;
      walk(document, tree, [&](const Site& site) {
        check_output_ports(site, registry, out);
        check_dead_branches(site, outcomes, out);
        check_async_reactive(site, outcomes, out);
        check_node_kind(site, registry, out);
      });
    }
    if (alternative == nullptr) return;
    for (std::size_t k = first; k < out.size(); ++k) {
      out[k].adaptable = alternative->adaptable;
      out[k].alternatives = {alternative->name};
    }
  };
  check_document(mission.tree, nullptr);
  for (const auto& alternative : mission.alternatives)
    check_document(alternative.document, &alternative);
  check_guard_kinds(registry, out);
  return out;
}

}  // namespace uabt::verify::tree
