// Which nodes of a running tree a property's `<node>.success|failure|running` reads (ARCHITECTURE
// §10, §12): one rule for `uabt run`'s monitor and both `prove` engines.
#pragma once
#include <string>
#include <vector>

#include "load/mission.hpp"
#include "runtime/engine.hpp"

namespace uabt::runtime {

// The alive nodes named `label`, else every alive node whose ID is `label`: a label several
// nodes share means any of them. The selection trees the compiler generates are left out:
// their nodes differ from one selection style to another, and the gate's static check
// (gate::mission_observables) knows only the mission's and the alternatives' own nodes.
// Whether `tree_id` is a selection tree the compiler generates (its ID is an Adaptable's):
// no property observes its nodes.
bool generated_selection_tree(const load::Mission& mission, const std::string& tree_id);

std::vector<NodeId> observed_nodes(const Engine& engine, const load::Mission& mission,
                                   const std::string& label);

}  // namespace uabt::runtime
