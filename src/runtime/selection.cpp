#include "runtime/selection.hpp"

#include <set>

#include "bt/node_kinds.hpp"

namespace uabt::runtime {

namespace {
constexpr NodeId kUnknown = kNoNode - 1;
}

SelectionObserver::SelectionObserver(const Engine& engine,
                                     std::function<void(const Selection&)> on_select)
    : engine_(engine), on_select_(std::move(on_select)) {}

NodeId SelectionObserver::selector_of(const Engine& engine, NodeId call) {
  const NodeInfo& sub = engine.info(call);
  using bt::NodeKind;
  if (!bt::is_subtree(sub.kind) || sub.parent == kNoNode) return kNoNode;
  const NodeId branch = sub.parent;
  const NodeInfo& seq = engine.info(branch);
  const NodeKind seq_kind = bt::node_kind(seq.kind);
  if (seq_kind != NodeKind::sequence && seq_kind != NodeKind::reactive_sequence) return kNoNode;
  if (sub.child_index + 1 != engine.children(branch).size()) return kNoNode;
  if (seq.parent == kNoNode || engine.info(seq.parent).instance != seq.instance) return kNoNode;
  // Fig. 4: the branch is a child of the selector, a (Reactive)Fallback. A decision structure
  // (optimized): the branch is a named leaf [SubTree] anywhere below it. Either way the
  // selector is its tree's root, named like the tree.
  const bool leaf = engine.children(branch).size() == 1 && !seq.name.empty();
  NodeId selector = seq.parent;
  if (leaf)
    while (engine.info(selector).parent != kNoNode &&
           engine.info(engine.info(selector).parent).instance == seq.instance)
      selector = engine.info(selector).parent;
  const NodeInfo& root = engine.info(selector);
  static const std::set<NodeKind> fallbacks = {NodeKind::fallback, NodeKind::reactive_fallback};
  static const std::set<NodeKind> decisions = {NodeKind::fallback,     NodeKind::reactive_fallback,
                                               NodeKind::if_then_else, NodeKind::while_do_else,
                                               NodeKind::sequence,     NodeKind::reactive_sequence};
  if (!(leaf ? decisions : fallbacks).contains(bt::node_kind(root.kind))) return kNoNode;
  if (root.name.empty() || root.name != root.tree_id) return kNoNode;
  if (root.parent != kNoNode && engine.info(root.parent).instance == root.instance) return kNoNode;
  return selector;
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
