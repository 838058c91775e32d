#include "gate/properties.hpp"

#include <map>

namespace uabt::gate {

namespace {

using Type = monitor::Observables::Type;

void visit(const bt::Node& root, std::map<std::string, int>& by_kind,
           std::map<std::string, int>& by_name, std::map<std::string, bool>& leaves) {
  std::vector<const bt::Node*> stack{&root};
  while (!stack.empty()) {
    const bt::Node* n = stack.back();
    stack.pop_back();
    if (n->tag != "Adaptable") {
      if (const std::string* name = n->attribute("name"); name != nullptr && !name->empty())
        ++by_name[*name];
      ++by_kind[n->kind()];
      if (n->children.empty() && n->tag != "SubTree") leaves[n->kind()] = true;
    }
    for (const auto& c : n->children) stack.push_back(&c);
  }
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
  std::map<std::string, int> by_kind, by_name;
  std::map<std::string, bool> leaves;
  for (const bt::TreeDef& t : m.tree.trees) visit(t.root, by_kind, by_name, leaves);
  for (const load::Alternative& alt : m.alternatives) {
    o.literals.insert(alt.name);
    for (const bt::TreeDef& t : alt.document.trees) visit(t.root, by_kind, by_name, leaves);
  }
  // A leaf's name is a condition (or an action's effect) on the world's blackboard.
  for (const auto& [kind, _] : leaves)
    if (o.variables.count(kind) == 0) o.variables[kind] = Type::boolean;
  std::vector<std::string> labels;
  for (const auto& [name, _] : by_name) labels.push_back(name);
  for (const auto& [kind, count] : by_kind)
    if (count == 1 && by_name.count(kind) == 0) labels.push_back(kind);
  for (const std::string& label : labels)
    for (const char* suffix : {".success", ".failure", ".running"})
      o.variables[label + suffix] = Type::boolean;
  for (const load::AdaptableSite& site : m.adaptables) {
    o.variables[site.id] = Type::boolean;
    o.variables[site.id + ".selected"] = Type::name;
  }
  return o;
}

std::vector<Finding> check_mission_properties(const load::Mission& m) {
  return monitor::check_properties(m.properties, mission_observables(m), m.domain.tick_seconds);
}

}  // namespace uabt::gate
