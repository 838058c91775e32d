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

// Recognises the compiler's selection subtrees in every style — a root named like its tree
// (ARCHITECTURE §4, Fig. 4: a (Reactive)Fallback whose children are (Reactive)Sequences ending in a
// SubTree; optimized: a decision whose leaves are named Sequences holding only the SubTree) —
// and reports a Selection each time one of those SubTrees goes from IDLE to RUNNING (every
// SubTree does when ticked, also if it completes at once). The one rule of which call selects
// which alternative: `run`'s select events, its `.selected` and prove's all come from here.
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
