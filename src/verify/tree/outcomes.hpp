#pragma once
// What a node can return, as far as the tree alone decides it (BehaviorTree.CPP 4.10's tick
// rules): each answer is computed once per node, so asking about every node is linear.
#include <array>
#include <unordered_map>

#include "verify/tree/walk.hpp"

namespace uabt::verify::tree {

class Outcomes {
 public:
  explicit Outcomes(const Registry& registry) : registry_(registry) {}

  // Never FAILURE nor SKIPPED (SUCCESS or RUNNING only): a Fallback never ticks what follows.
  bool always_succeeds(const bt::Document& document, const bt::Node& node);
  // Never SUCCESS nor SKIPPED (FAILURE or RUNNING only): a Sequence never ticks what follows.
  bool always_fails(const bt::Document& document, const bt::Node& node);
  // May return RUNNING (an asynchronous node, or one with such a descendant).
  bool may_run(const bt::Document& document, const bt::Node& node);

 private:
  enum Question { succeeds = 0, fails = 1, runs = 2, skips = 3 };
  bool answer(const bt::Document& document, const bt::Node& node, Question q);
  bool compute(const bt::Document& document, const bt::Node& node, Question q);
  bool may_skip(const bt::Document& document, const bt::Node& node);
  const bt::Node* subtree_root(const bt::Document& document, const bt::Node& node) const;

  const Registry& registry_;
  // Per node, per question: 0 unknown, 1 computing (a SubTree cycle), 2 false, 3 true.
  std::unordered_map<const bt::Node*, std::array<unsigned char, 4>> memo_;
};

}  // namespace uabt::verify::tree
