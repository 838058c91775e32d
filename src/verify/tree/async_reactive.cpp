// tree-async-reactive: a ReactiveSequence or ReactiveFallback with more than one child that
// may return RUNNING. BehaviorTree.CPP 4.10 re-ticks the earlier children every tick and halts
// every other child when one returns RUNNING, so two asynchronous children halt each other;
// with ReactiveSequence::EnableException(true) (ReactiveFallback's likewise) it throws "only a
// single child can return RUNNING" at the tick instead.
#include "verify/tree/checks.hpp"

namespace uabt::verify::tree {

void check_async_reactive(const Site& site, Outcomes& outcomes, std::vector<Finding>& out) {
  const bt::Node& node = *site.node;
  const std::string kind = node.kind();
  const bt::NodeKind k = bt::node_kind(kind);
  if (k != bt::NodeKind::reactive_sequence && k != bt::NodeKind::reactive_fallback) return;
  const bt::Node* first = nullptr;
  for (const auto& child : node.children) {
    if (!outcomes.may_run(*site.document, child)) continue;
    if (first == nullptr) {
      first = &child;
      continue;
    }
    Finding f = make_finding(
        "tree-async-reactive",
        describe(child) + " may return RUNNING, and so may " + describe(*first) + " before it in " +
            describe(node) +
            ": BehaviorTree.CPP halts one whenever the other runs (and throws \"only a single "
            "child can return RUNNING\" with " +
            kind + "::EnableException(true))",
        site.location_of(child));
    f.notes.push_back(
        std::string("keep one asynchronous child (the last) and make the others conditions, "
                    "or use ") +
        bt::kind_name(k == bt::NodeKind::reactive_sequence ? bt::NodeKind::sequence
                                                           : bt::NodeKind::fallback) +
        " if the earlier children need not be re-checked every tick");
    add_path(f, site, true);
    f.related.push_back(
        {site.location_of(*first), "the first child that may run: " + describe(*first)});
    out.push_back(std::move(f));
    return;
  }
}

}  // namespace uabt::verify::tree
