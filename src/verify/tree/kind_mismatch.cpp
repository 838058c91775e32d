// tree-kind-mismatch: BehaviorTree.CPP builds a node from its ID alone, so <Condition
// ID="Drill"/> runs the Drill action (BehaviorTree.CPP #774); a guard that names an action
// would run it to decide which alternative to select.
#include "load/references.hpp"
#include "verify/tree/checks.hpp"

namespace uabt::verify::tree {

namespace {

const char* article(bt::Family family) {
  return family == bt::Family::action ? "an" : "a";
}

std::string registered_as(const Registry& registry, const std::string& id, bt::Family family) {
  const char* by = bt::find_builtin(id) != nullptr ? "BehaviorTree.CPP registers "
                   : registry.mission().nodes      ? "nodes.xml registers "
                                                   : "<TreeNodesModel> registers ";
  return std::string(by) + id + " as " + article(family) + " " + bt::family_name(family);
}

}  // namespace

void check_node_kind(const Site& site, const Registry& registry, std::vector<Finding>& out) {
  const bt::Node& node = *site.node;
  const std::string& tag = node.tag;
  if (tag != "Action" && tag != "Condition" && tag != "Control" && tag != "Decorator") return;
  const std::string* id = node.attribute("ID");
  if (id == nullptr) return;  // bt-structure's
  const bt::Family family = registry.family(*id);
  if (family == bt::Family::unknown || family == bt::Family::subtree) return;
  if (tag == bt::family_name(family)) return;
  Finding f =
      make_finding("tree-kind-mismatch",
                   "<" + tag + " ID=\"" + *id + "\"> but " + registered_as(registry, *id, family) +
                       ": BehaviorTree.CPP builds the node from its ID and ignores the "
                       "element name, so the tree does not do what it says",
                   site.location());
  f.notes.push_back("write <" + std::string(bt::family_name(family)) + " ID=\"" + *id +
                    "\"/> (or <" + *id + "/>), or register the node as the kind you meant");
  add_path(f, site);
  out.push_back(std::move(f));
}

void check_guard_kinds(const Registry& registry, std::vector<Finding>& out) {
  for (const auto& s : registry.mission().selections) {
    if (!s.guard) continue;
    for (const fretish::Expr* atom : load::boolean_atoms(*s.guard)) {
      if (atom->kind != fretish::ExprKind::identifier) continue;
      const bt::Family family = registry.family(atom->text);
      if (family == bt::Family::unknown || family == bt::Family::condition) continue;
      Finding f =
          make_finding("tree-kind-mismatch",
                       "the guard of " + s.id + " reads '" + atom->text + "' as a condition, but " +
                           registered_as(registry, atom->text, family) +
                           ": the selection subtree would tick it to decide, running the node",
                       start_of(atom->range, s.location));
      f.requirements.push_back(s.id);
      f.adaptable = s.adaptable;
      f.alternatives.push_back(s.alternative);
      f.notes.push_back(
          "guard on a condition the robot reports: a Condition in nodes.xml, or "
          "a variable of domain.fret");
      out.push_back(std::move(f));
    }
  }
}

}  // namespace uabt::verify::tree
