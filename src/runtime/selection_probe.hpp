#pragma once
#include <cstdint>
#include <string>

#include "base/value.hpp"
#include "bt/tree.hpp"
#include "runtime/status.hpp"

namespace uabt::runtime {

// One tick of a selection tree in a fixed state, as the engine runs it: how many condition
// nodes of that tree it ticked and which SubTree (alternative) it started first.
struct SelectionProbe {
  std::uint64_t conditions = 0;  // robot conditions and ScriptConditions of the tree
  std::string first_call;        // ID of the first SubTree started, "" if none
  NodeStatus status = NodeStatus::idle;
};

// Ticks tree `tree_id` of `doc` once, from IDLE, in a simulated world whose state is `state`
// (the alternatives' actions take one tick and succeed). Throws LoadError as Engine::build.
SelectionProbe probe_selection(const bt::Document& doc, const std::string& tree_id,
                               const State& state);

}  // namespace uabt::runtime
