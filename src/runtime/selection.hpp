#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "runtime/engine.hpp"

namespace uabt::runtime {

// One `select` event: a selection subtree started an alternative.
struct Selection {
  std::uint64_t tick = 0;
  NodeId selector = kNoNode;  // the Fallback / ReactiveFallback
  std::string adaptable;      // the selector's name = its tree's id
  std::uint32_t branch = 0;   // which child of the selector
  std::string requirement;    // that child's name (the requirement id)
  std::string alternative;    // the tree the SubTree calls
  NodeId call = kNoNode;      // the SubTree node
};

// Recognises the compiler's selection subtrees (DESIGN §4, Fig. 4) — a Fallback or
// ReactiveFallback named like the tree it is the root of, whose children are (Reactive)
// Sequences ending in a SubTree — and reports a Selection each time one of those SubTrees
// goes from IDLE to RUNNING (every SubTree does when ticked, also if it completes at once).
class SelectionObserver : public Observer {
 public:
  SelectionObserver(const Engine& engine, std::function<void(const Selection&)> on_select);
  void on_status_change(NodeId node, NodeStatus previous, NodeStatus next) override;

  // The selector a SubTree node selects for, or kNoNode.
  static NodeId selector_of(const Engine& engine, NodeId call);

 private:
  const Engine& engine_;
  std::function<void(const Selection&)> on_select_;
  std::vector<NodeId> cache_;  // per node: selector, kNoNode (none), or kUnknown
};

}  // namespace uabt::runtime
