#include "gate/properties.hpp"

#include <map>
#include <set>

#include "bt/node_kinds.hpp"
#include "load/run_trees.hpp"

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

// Why a node label of a tree no tree of the run calls observes nothing.
std::string why_never_called(const std::string& label, const bt::TreeDef& tree,
                             const load::Alternative* alt) {
  return "its only nodes '" + label + "' are in the tree '" + tree.id + "'" +
         (alt != nullptr ? " of alternative '" + alt->name + "'" : "") +
         ", which no tree of the run calls, so the run has no such node";
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
  // Nodes of the run: the trees it instantiates (ARCHITECTURE §12). A label several nodes share
  // means any of them.
  std::set<std::string> labels, leaves;
  std::set<const bt::TreeDef*> run;
  for (const load::RunTree& t : load::run_trees(m)) {
    visit(t.tree->root, labels, leaves);
    run.insert(t.tree);
  }
  for (const load::Alternative& alt : m.alternatives) o.literals.insert(alt.name);
  // A label only trees outside the run have observes nothing: say why, once per label.
  std::map<std::string, std::string> gone_labels, gone_leaves;
  auto outside_the_run = [&](const bt::TreeDef& t, const load::Alternative* alt) {
    if (run.count(&t) != 0) return;
    std::set<std::string> tree_labels, tree_leaves;
    visit(t.root, tree_labels, tree_leaves);
    auto why = [&](const std::string& label) {
      return alt != nullptr && !load::selected(m, *alt) ? why_gone(m, label, *alt)
                                                        : why_never_called(label, t, alt);
    };
    for (const std::string& label : tree_labels)
      if (labels.count(label) == 0) gone_labels.emplace(label, why(label));
    for (const std::string& leaf : tree_leaves)
      if (leaves.count(leaf) == 0) gone_leaves.emplace(leaf, why(leaf));
  };
  for (const bt::TreeDef& t : m.tree.trees) outside_the_run(t, nullptr);
  for (const load::Alternative& alt : m.alternatives)
    for (const bt::TreeDef& t : alt.document.trees) outside_the_run(t, &alt);
  // A leaf's name is a condition (or an action's effect) on the world's blackboard.
  for (const std::string& kind : leaves)
    if (o.variables.count(kind) == 0) o.variables[kind] = Type::boolean;
  for (const std::string& label : labels)
    for (const char* suffix : {".success", ".failure", ".running"})
      o.variables[label + suffix] = Type::boolean;
  for (const auto& [leaf, why] : gone_leaves)
    if (o.variables.count(leaf) == 0) o.not_observable[leaf] = why;
  for (const auto& [label, why] : gone_labels)
    for (const char* suffix : {".success", ".failure", ".running"})
      o.not_observable[label + suffix] = why;
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
