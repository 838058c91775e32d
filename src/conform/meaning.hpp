#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "conform/context.hpp"
#include "conform/equivalence.hpp"
#include "fretish/expr.hpp"

namespace uabt::conform {

// What one tick of a selection subtree does, started from IDLE, read off its XML: which
// conditions it ticks in which order and which alternative it starts first. Only what is a pure
// function of the state in one tick is readable: conditions, Sequence/Fallback (reactive or
// not), IfThenElse/WhileDoElse, Inverter/ForceSuccess/ForceFailure, AlwaysSuccess/AlwaysFailure,
// SubTree calls (of an alternative: the selection; of another tree: its root).
struct TickNode {
  enum class Op {
    success,
    failure,
    alternative,
    condition,
    sequence,
    fallback,
    invert,
    force_success,
    force_failure,
    if_then_else
  };
  Op op = Op::failure;
  fretish::ExprPtr condition;  // condition: what it checks
  int alternative = -1;        // alternative: its code
  std::vector<TickNode> children;
  const bt::Node* node = nullptr;
  std::string path;
};

// The selection's outcome codes: an alternative's index, or one of these.
inline constexpr int kSelectsNothingButSucceeds = -1;
inline constexpr int kFails = -2;

struct SelectionMeaning {
  enum class Verdict { equal, differs, unreadable, unknown };
  Verdict verdict = Verdict::unreadable;
  std::string reason;  // unreadable / unknown: why
  State witness;       // differs: a state of the domain where the selections differ
  std::string compiled_selects, required_selects;  // differs: what each selects there
  std::string required_by;                         // differs: that requirement's id, if any
  std::vector<std::string> alternatives;           // differs: compiled's, then required's
  // Every alternative call of the subtree: (alternative name, call node, path).
  struct Call {
    std::string alternative;
    const bt::Node* node = nullptr;
    std::string path;
  };
  std::vector<Call> calls;
};

// Proves with Z3 that the selection tree `tree` of `adaptable` selects, in every state of the
// domain, the alternative of the first requirement whose guard holds (nothing — the subtree
// fails — when none holds): ARCHITECTURE §6's conformance by meaning, whatever the tree's shape.
SelectionMeaning prove_selection_meaning(const Context& ctx, Prover& prover,
                                         const std::string& adaptable, const bt::TreeDef& tree);

}  // namespace uabt::conform
