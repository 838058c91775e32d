#include "gate/properties.hpp"

#include <map>
#include <set>

#include "bt/node_kinds.hpp"

namespace uabt::gate {

namespace {

using Type = monitor::Observables::Type;

// Every label a node of `root` answers to (its name, its ID) and the IDs of its leaves.
void visit(const bt::Node& root, std::set<std::string>& labels, std::set<std::string>& leaves) {
  std::vector<const bt::Node*> stack{&root};
  while (!stack.empty()) {
    const bt::Node* n = stack.back();
    stack.pop_back();
    if (n->tag != "Adaptable") {
      if (const std::string* name = n->attribute("name"); name != nullptr && !name->empty())
        labels.insert(*name);
      labels.insert(n->kind());
      if (n->children.empty() && !bt::is_subtree(n->tag)) leaves.insert(n->kind());
    }
    for (const auto& c : n->children) stack.push_back(&c);
  }
}

// Whether the compiler copies `alt` into the tree (unknown while a requirement of its node
// does not parse: counted as selected, so that mistake is not reported twice).
bool selected(const load::Mission& m, const load::Alternative& alt) {
  if (m.requirements_incomplete.count(alt.adaptable) != 0) return true;
  for (const auto* r : m.selections_for(alt.adaptable))
    if (r->alternative == alt.name) return true;
  return false;
}

// Why a node label of an alternative no requirement selects observes nothing: that
// alternative is not compiled into the tree, so no node of the run has the label.
std::string why_gone(const load::Mission& m, const std::string& label,
                     const load::Alternative& alt) {
  const std::string where = "alternative '" + alt.name + "' of '" + alt.adaptable + "'";
  if (m.uplinks.empty())
    return "its only nodes '" + label + "' are in " + where +
           ", which no requirement selects, so the compiled tree does not have them";
  std::string uplinks;
  for (const std::string& u : m.uplinks) uplinks += (uplinks.empty() ? "'" : ", '") + u + "'";
  std::string removed;
  for (const load::UplinkMerge& r : m.merges)
    if (r.rule == "removed" && r.adaptable == alt.adaptable)
      removed += (removed.empty() ? "" : ", ") + r.requirement;
  return "the uplink " + uplinks + " removed the last node '" + label + "': it was only in " +
         where + ", which no requirement selects any more" +
         (removed.empty() ? "" : " (the uplink removed " + removed + ")");
}

}  // namespace

monitor::Observables mission_observables(const load::Mission& m) {
  monitor::Observables o;
  o.literals.insert("none");
  for (const fretish::Variable& v : m.domain.variables) {
    o.variables[v.name] = v.type == fretish::VarType::boolean       ? Type::boolean
                          : v.type == fretish::VarType::enumeration ? Type::name
                                                                    : Type::number;
    for (const std::string& literal : v.enum_values) o.literals.insert(literal);
  }
  // Nodes of the run: the mission's trees and the alternatives a requirement selects (the
  // compiler copies only those). A label several nodes share means any of them (ARCHITECTURE §12).
  std::set<std::string> labels, leaves;
  for (const bt::TreeDef& t : m.tree.trees) visit(t.root, labels, leaves);
  std::map<std::string, const load::Alternative*> only_unselected, unselected_leaves;
  for (const load::Alternative& alt : m.alternatives) {
    o.literals.insert(alt.name);
    if (selected(m, alt)) {
      for (const bt::TreeDef& t : alt.document.trees) visit(t.root, labels, leaves);
      continue;
    }
    std::set<std::string> unused_labels, unused_leaves;
    for (const bt::TreeDef& t : alt.document.trees) visit(t.root, unused_labels, unused_leaves);
    for (const std::string& label : unused_labels) only_unselected.emplace(label, &alt);
    for (const std::string& leaf : unused_leaves) unselected_leaves.emplace(leaf, &alt);
  }
  // A leaf's name is a condition (or an action's effect) on the world's blackboard.
  for (const std::string& kind : leaves)
    if (o.variables.count(kind) == 0) o.variables[kind] = Type::boolean;
  for (const std::string& label : labels)
    for (const char* suffix : {".success", ".failure", ".running"})
      o.variables[label + suffix] = Type::boolean;
  for (const auto& [leaf, alt] : unselected_leaves)
    if (leaves.count(leaf) == 0 && o.variables.count(leaf) == 0)
      o.not_observable[leaf] = why_gone(m, leaf, *alt);
  for (const auto& [label, alt] : only_unselected) {
    if (labels.count(label) != 0) continue;
    for (const char* suffix : {".success", ".failure", ".running"})
      o.not_observable[label + suffix] = why_gone(m, label, *alt);
  }
  for (const load::AdaptableSite& site : m.adaptables) {
    o.variables[site.id] = Type::boolean;
    o.variables[site.id + ".selected"] = Type::name;
  }
  return o;
}

std::vector<Finding> check_mission_properties(const load::Mission& m) {
  return monitor::check_properties(m.properties, mission_observables(m));
}

}  // namespace uabt::gate
