// tree-dead-branch: a child BehaviorTree.CPP never ticks. A Fallback stops at a child that
// never fails (AlwaysSuccess, ForceSuccess, an Inverter around one that never succeeds, …), a
// Sequence at one that never succeeds; IfThenElse and WhileDoElse never take the branch their
// first child rules out.
#include "verify/tree/checks.hpp"

namespace uabt::verify::tree {

namespace {

void report(const Site& site, const bt::Node& dead, const bt::Node& cause, std::string message,
            std::vector<Finding>& out) {
  Finding f = make_finding("tree-dead-branch", std::move(message), site.location_of(dead));
  add_path(f, site, true);
  f.related.push_back({site.location_of(cause), "the child that decides: " + describe(cause)});
  out.push_back(std::move(f));
}

}  // namespace

void check_dead_branches(const Site& site, Outcomes& outcomes, std::vector<Finding>& out) {
  const bt::Node& node = *site.node;
  const auto& children = node.children;
  const std::string kind = node.kind();
  const bt::Document& document = *site.document;
  const bool sequence = is_sequence(kind);
  if (sequence || is_fallback(kind)) {
    for (std::size_t k = 0; k + 1 < children.size(); ++k) {
      const bt::Node& child = children[k];
      const bool stops = sequence ? outcomes.always_fails(document, child)
                                  : outcomes.always_succeeds(document, child);
      if (!stops) continue;
      const std::size_t after = children.size() - k - 2;  // dead children after the first
      report(site, children[k + 1], child,
             describe(children[k + 1]) +
                 (after == 0   ? " is"
                  : after == 1 ? " and the child after it are"
                               : " and the " + std::to_string(after) + " children after it are") +
                 " never ticked: " + describe(child) + " before it in " + describe(node) +
                 (sequence ? " never succeeds" : " never fails"),
             out);
      return;
    }
    return;
  }
  if ((bt::node_kind(kind) == bt::NodeKind::if_then_else ||
       bt::node_kind(kind) == bt::NodeKind::while_do_else) &&
      children.size() >= 2) {
    const bt::Node& condition = children[0];
    if (outcomes.always_fails(document, condition)) {
      report(site, children[1], condition,
             describe(children[1]) + ", the then-branch of " + describe(node) +
                 ", is never ticked: its condition " + describe(condition) + " never succeeds",
             out);
    } else if (children.size() == 3 && outcomes.always_succeeds(document, condition)) {
      report(site, children[2], condition,
             describe(children[2]) + ", the else-branch of " + describe(node) +
                 ", is never ticked: its condition " + describe(condition) + " never fails",
             out);
    }
  }
}

}  // namespace uabt::verify::tree
