#include "runtime/observed_nodes.hpp"

#include <algorithm>

namespace uabt::runtime {

bool generated_selection_tree(const load::Mission& mission, const std::string& tree_id) {
  return std::any_of(mission.adaptables.begin(), mission.adaptables.end(),
                     [&](const load::AdaptableSite& site) { return site.id == tree_id; });
}

std::vector<NodeId> observed_nodes(const Engine& engine, const load::Mission& mission,
                                   const std::string& label) {
  std::vector<NodeId> named, of_kind;
  for (NodeId id = 0; id < engine.node_count(); ++id) {
    const NodeInfo& info = engine.info(id);
    if (!info.alive || (info.name != label && info.kind != label) ||
        generated_selection_tree(mission, info.tree_id))
      continue;
    (info.name == label ? named : of_kind).push_back(id);
  }
  return named.empty() ? of_kind : named;
}

}  // namespace uabt::runtime
