#include "runtime/condition_count.hpp"

#include "bt/node_kinds.hpp"

namespace uabt::runtime {

void ConditionCounter::on_node_ticked(NodeId node, NodeStatus /*result*/) {
  if (kind_.size() <= node) kind_.resize(engine_.node_count(), 0);
  if (kind_[node] == 0) {
    const bool condition =
        bt::node_kind(engine_.info(node).kind) == bt::NodeKind::script_condition ||
        !engine_.condition_reads(node).empty();
    kind_[node] = condition ? 1 : 2;
  }
  if (kind_[node] == 1) ++count_;
}

}  // namespace uabt::runtime
