#include "verify/tree/outcomes.hpp"

namespace uabt::verify::tree {

namespace {

bool has(const bt::Node& node, const char* attribute) {
  return node.attribute(attribute) != nullptr;
}

}  // namespace

bool Outcomes::always_succeeds(const bt::Document& document, const bt::Node& node) {
  return answer(document, node, succeeds);
}

bool Outcomes::always_fails(const bt::Document& document, const bt::Node& node) {
  return answer(document, node, fails);
}

bool Outcomes::may_run(const bt::Document& document, const bt::Node& node) {
  return answer(document, node, runs);
}

bool Outcomes::may_skip(const bt::Document& document, const bt::Node& node) {
  return answer(document, node, skips);
}

const bt::Node* Outcomes::subtree_root(const bt::Document& document, const bt::Node& node) const {
  const std::string* id = node.attribute("ID");
  if (id == nullptr) return nullptr;
  const bt::TreeDef* target = document.find_tree(*id);
  return target == nullptr ? nullptr : &target->root;
}

bool Outcomes::answer(const bt::Document& document, const bt::Node& node, Question q) {
  unsigned char& slot = memo_[&node][q];
  if (slot == 1) return q == runs || q == skips;  // a SubTree cycle: assume the worst
  if (slot != 0) return slot == 3;
  slot = 1;
  const bool result = compute(document, node, q);
  slot = result ? 3 : 2;  // unordered_map keeps references to its elements as it grows
  return result;
}

// What can be told without the world: BehaviorTree.CPP 4.10's controls and decorators over
// their children; robot leaves may return anything but SKIPPED, conditions never RUNNING.
bool Outcomes::compute(const bt::Document& document, const bt::Node& node, Question q) {
  const std::string kind = node.kind();
  const auto& children = node.children;
  // _skipIf and _while may skip the node; _failureIf makes it fail, _successIf succeed.
  const bool may_be_skipped = has(node, "_skipIf") || has(node, "_while");
  switch (q) {
    case succeeds:
      if (may_be_skipped || has(node, "_failureIf")) return false;
      break;
    case fails:
      if (may_be_skipped || has(node, "_successIf")) return false;
      break;
    case skips:
      if (may_be_skipped) return true;
      break;
    case runs: break;
  }
  if (node.tag == "Adaptable") return q == runs;  // an alternative is an action tree
  const bt::NodeKind k = bt::node_kind(kind);
  if (k == bt::NodeKind::subtree) {
    const bt::Node* root = subtree_root(document, node);
    if (root == nullptr) return q == runs || q == skips;
    return answer(document, *root, q);
  }
  const bt::Family family = registry_.family(kind);
  const ControlRule rule = control_rule(kind, family, children.size());
  if (rule.combine == Combine::leaf) {
    switch (q) {
      case succeeds: return k == bt::NodeKind::always_success;
      case fails: return k == bt::NodeKind::always_failure;
      case skips: return false;
      case runs:
        if (family == bt::Family::condition) return false;
        if (family == bt::Family::action)
          return k == bt::NodeKind::robot || k == bt::NodeKind::sleep;
        // Neither built in nor registered: a domain name is a condition the robot reports,
        // anything else one of its actions.
        return !registry_.is_domain_name(kind);
    }
  }
  if (q == runs && rule.may_run_alone) return true;
  if (q == runs || q == skips) {
    if (k == bt::NodeKind::skip_unless_updated && q == skips) return true;
    for (const auto& child : children)
      if (answer(document, child, q)) return true;
    return false;
  }
  const bt::Node& first = children.front();
  switch (rule.combine) {
    case Combine::force_success: return q == succeeds && !may_skip(document, first);
    case Combine::force_failure: return q == fails && !may_skip(document, first);
    case Combine::invert:
      return q == succeeds ? always_fails(document, first) : always_succeeds(document, first);
    case Combine::sequence:
    case Combine::fallback: {
      // A Sequence fails as soon as one child fails and succeeds only when all do; a Fallback
      // the other way round.
      const bool sequence = rule.combine == Combine::sequence;
      const bool all = sequence == (q == succeeds);
      for (const auto& child : children) {
        const bool holds = answer(document, child, q);
        if (!all && holds) return true;
        if (all && !holds) return false;
      }
      return all;
    }
    default: return false;  // what the children return does not decide it alone
  }
}

}  // namespace uabt::verify::tree
