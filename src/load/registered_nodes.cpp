#include "load/registered_nodes.hpp"

#include <cctype>
#include <map>
#include <set>
#include <tuple>

#include "base/suggest.hpp"
#include "bt/node_kinds.hpp"

namespace uabt::load {

namespace {

std::string port_list(const bt::NodeModel& model) {
  std::string out;
  for (const auto& p : model.ports) out += (out.empty() ? "" : ", ") + p.name;
  return out.empty() ? "none" : out;
}

class Registry {
 public:
  explicit Registry(Mission& m) : m_(m) {
    std::vector<std::string> names;
    for (const auto& model : *m.nodes) {
      if (bt::family_named(model.family) == bt::Family::subtree) continue;
      models_.emplace(model.id, &model);
      names.push_back(model.id);
    }
    names_ = NameIndex(names);
  }

  void check_tree(const bt::TreeDef& tree) {
    // A file included by several alternatives is one file: report its nodes once.
    if (!checked_.insert({tree.file, tree.line, tree.column}).second) return;
    std::vector<const bt::Node*> stack{&tree.root};
    while (!stack.empty()) {
      const bt::Node* n = stack.back();
      stack.pop_back();
      check_node(tree, *n);
      for (auto it = n->children.rbegin(); it != n->children.rend(); ++it) stack.push_back(&*it);
    }
  }

 private:
  void check_node(const bt::TreeDef& tree, const bt::Node& n) {
    if (n.tag.empty() || n.tag == "Adaptable") return;
    if (bt::is_explicit_family_tag(n.tag) && n.attribute("ID") == nullptr) return;  // bt-structure
    const std::string kind = n.kind();
    if (bt::find_builtin(kind) != nullptr) return;
    const SourceLocation at{tree.file, n.line, n.column};
    const auto it = models_.find(kind);
    if (it == models_.end()) {
      Finding f = make_finding("ref-unknown-node",
                               "node '" + kind +
                                   "' is not registered in nodes.xml: BehaviorTree.CPP refuses "
                                   "to load a tree with a node the robot does not have",
                               at);
      if (const std::string hint = names_.did_you_mean(kind); !hint.empty())
        f.notes.push_back(hint);
      m_.findings.push_back(std::move(f));
      return;
    }
    const bt::NodeModel& model = *it->second;
    std::vector<std::string> port_names;
    for (const auto& p : model.ports) port_names.push_back(p.name);
    for (const auto& [attribute, value] : n.attributes) {
      if (!bt::is_port_attribute(attribute)) continue;
      bool known = false;
      for (const auto& p : model.ports) known |= p.name == attribute;
      if (known) continue;
      Finding f = make_finding("ref-unknown-port",
                               "'" + attribute + "' is not a port of " + kind +
                                   " in nodes.xml (its ports: " + port_list(model) +
                                   "): BehaviorTree.CPP refuses to load the tree",
                               at);
      if (const std::string hint = did_you_mean(attribute, port_names); !hint.empty())
        f.notes.push_back(hint);
      m_.findings.push_back(std::move(f));
    }
    for (const auto& p : model.ports) {
      if (p.direction == "output_port" || !p.default_value.empty()) continue;
      if (n.attribute(p.name) != nullptr) continue;
      Finding f = make_finding("ref-missing-port",
                               "input port '" + p.name + "' of " + kind +
                                   " is not set and nodes.xml gives it no default: the node "
                                   "fails when it reads it",
                               at);
      f.notes.push_back("set it (" + p.name + "=\"{" + p.name + "}\" reads the blackboard entry " +
                        p.name + ") or give the port a default in nodes.xml");
      m_.findings.push_back(std::move(f));
    }
  }

  Mission& m_;
  std::map<std::string, const bt::NodeModel*> models_;
  NameIndex names_;  // the registered IDs, for "did you mean"
  std::set<std::tuple<std::string, int, int>> checked_;
};

}  // namespace

void check_registered_nodes(Mission& m) {
  if (!m.nodes) return;
  Registry registry(m);
  for (const auto& t : m.tree.trees) registry.check_tree(t);
  for (const auto& alt : m.alternatives)
    for (const auto& t : alt.document.trees) registry.check_tree(t);
}

}  // namespace uabt::load
