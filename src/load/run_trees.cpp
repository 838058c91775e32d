#include "load/run_trees.hpp"

#include <map>
#include <set>

#include "bt/node_kinds.hpp"

namespace uabt::load {

bool selected(const Mission& m, const Alternative& alt) {
  if (m.requirements_incomplete.count(alt.adaptable) != 0) return true;
  for (const auto* r : m.selections_for(alt.adaptable))
    if (r->alternative == alt.name) return true;
  return false;
}

std::vector<RunTree> run_trees(const Mission& m) {
  // The compiled document's namespace: first of an ID wins, generated selection trees included.
  std::map<std::string, RunTree> by_id;
  for (const bt::TreeDef& t : m.tree.trees) by_id.emplace(t.id, RunTree{&t, nullptr});
  for (const AdaptableSite& site : m.adaptables) by_id.emplace(site.id, RunTree{});
  std::map<std::string, std::vector<const Alternative*>> chosen;
  for (const Alternative& alt : m.alternatives) {
    if (!selected(m, alt)) continue;
    chosen[alt.adaptable].push_back(&alt);
    if (const bt::TreeDef* main = alt.document.find_tree(alt.tree_id))
      by_id.emplace(main->id, RunTree{main, &alt});
    for (const bt::TreeDef& t : alt.document.trees) by_id.emplace(t.id, RunTree{&t, &alt});
  }

  std::vector<RunTree> out;
  std::set<const bt::TreeDef*> seen;
  std::vector<RunTree> pending;
  auto enter = [&](const std::string& id) {
    const auto it = by_id.find(id);
    if (it != by_id.end() && it->second.tree != nullptr && seen.insert(it->second.tree).second)
      pending.push_back(it->second);
  };
  if (const bt::TreeDef* main = m.tree.main()) {
    enter(main->id);
  } else {
    for (const auto& [id, tree] : by_id) enter(id);
  }
  while (!pending.empty()) {
    const RunTree next = pending.back();
    pending.pop_back();
    out.push_back(next);
    std::vector<const bt::Node*> stack{&next.tree->root};
    while (!stack.empty()) {
      const bt::Node* n = stack.back();
      stack.pop_back();
      const std::string* id = n->attribute("ID");
      if (id != nullptr && bt::is_subtree(n->tag)) enter(*id);
      if (id != nullptr && n->tag == "Adaptable")
        for (const Alternative* alt : chosen[*id]) enter(alt->tree_id);
      for (const auto& c : n->children) stack.push_back(&c);
    }
  }
  return out;
}

}  // namespace uabt::load
