#pragma once
#include <optional>
#include <string>

#include "conform/context.hpp"
#include "fretish/expr.hpp"

namespace uabt::conform {

// Why a condition-checking subtree has no boolean meaning.
struct GuardProblem {
  const bt::Node* node = nullptr;
  std::string path;
  std::string message;
  // bt-structure or another compiled-* rule already reports this node (an Inverter with two
  // children, a dangling SubTree, an <Adaptable>): the guard rule stays silent about it.
  bool reported_elsewhere = false;
};

struct GuardReading {
  fretish::ExprPtr formula;  // nullptr when `problem` is set
  std::optional<GuardProblem> problem;
};

// Reads a condition-checking subtree back into the condition it decides (synchronously, in
// one tick): Sequence/ReactiveSequence = and, Fallback/ReactiveFallback = or, Inverter = not,
// ForceSuccess/AlwaysSuccess = true, ForceFailure/AlwaysFailure = false, a condition leaf =
// the boolean atom of its name, ScriptCondition = its code, SubTree = the called tree's root.
// `blackboard_visible`: the state's blackboard entries are visible here (every SubTree call on
// the way shares its parent's blackboard), so a ScriptCondition may read them.
GuardReading read_guard(const Context& ctx, const bt::Node& node, const std::string& path,
                        bool blackboard_visible);

}  // namespace uabt::conform
