#include "runtime/selection.hpp"

namespace uabt::runtime {

namespace {
constexpr NodeId kUnknown = kNoNode - 1;
}

SelectionObserver::SelectionObserver(const Engine& engine,
                                     std::function<void(const Selection&)> on_select)
    : engine_(engine), on_select_(std::move(on_select)) {}

NodeId SelectionObserver::selector_of(const Engine& engine, NodeId call) {
  const NodeInfo& sub = engine.info(call);
  if (sub.kind != "SubTree" || sub.parent == kNoNode) return kNoNode;
  const NodeId branch = sub.parent;
  const NodeInfo& seq = engine.info(branch);
  if (seq.kind != "Sequence" && seq.kind != "ReactiveSequence") return kNoNode;
  if (sub.child_index + 1 != engine.children(branch).size()) return kNoNode;
  if (seq.parent == kNoNode) return kNoNode;
  const NodeInfo& fallback = engine.info(seq.parent);
  if (fallback.kind != "Fallback" && fallback.kind != "ReactiveFallback") return kNoNode;
  if (fallback.name.empty() || fallback.name != fallback.tree_id) return kNoNode;
  // The selector is its tree's root (its parent is the SubTree calling that tree, if any).
  if (fallback.parent != kNoNode && engine.info(fallback.parent).instance == fallback.instance)
    return kNoNode;
  return seq.parent;
}

void SelectionObserver::on_status_change(NodeId node, NodeStatus previous, NodeStatus next) {
  if (previous != NodeStatus::idle || next != NodeStatus::running) return;
  if (cache_.size() <= node) cache_.resize(engine_.node_count(), kUnknown);
  if (cache_[node] == kUnknown) cache_[node] = selector_of(engine_, node);
  const NodeId selector = cache_[node];
  if (selector == kNoNode) return;
  const NodeInfo& call = engine_.info(node);
  const NodeInfo& branch = engine_.info(call.parent);
  Selection s;
  s.tick = engine_.tick_count();
  s.selector = selector;
  s.adaptable = engine_.info(selector).name;
  s.branch = branch.child_index;
  s.requirement = branch.name;
  if (const std::string* id = call.element->attribute("ID")) s.alternative = *id;
  s.call = node;
  on_select_(s);
}

}  // namespace uabt::runtime
