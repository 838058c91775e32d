#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/value.hpp"
#include "bt/tree.hpp"
#include "fretish/domain.hpp"

namespace uabt::testing::oracle {

// An independent judge of condition-checking subtrees for the mutation test: it ticks them
// (BehaviorTree.CPP semantics, scripts evaluated over doubles and strings as BT.CPP does) in
// every state of a sample of the domain, sharing no code with the conformance checker.
//
// The sample is complete for the guards the test mutates: every atom is a boolean, an enum
// comparison or a comparison of one variable with a constant, so a variable's atoms only change
// value at the constants; sampling each constant c as c-1, c-0.5, c, c+0.5, c+1 (integers: their
// rounding; every value of a range of at most 16) and the bounds visits every combination of
// atom values.

// The result of ticking a guard once: nullopt when BT.CPP would refuse the tree or throw
// (a decorator without exactly one child, a node that is not a condition, an undefined script
// variable, a call of a missing tree).
std::optional<bool> tick_guard(const bt::Document& doc, const bt::Node& guard, const State& state);

// States of `domain` (assumptions hold) over its variables plus `extra_booleans`, sampled
// around `constants`.
std::vector<State> sample_states(const fretish::Domain& domain,
                                 const std::vector<std::string>& extra_booleans,
                                 const std::vector<double>& constants);

struct Verdict {
  bool equivalent = true;
  std::string reason;  // for a difference: which branch, which state
};

// Does every branch guard of every selection tree decide the same as in `original`, in every
// sampled state? (Guard mutants keep the branches where they are.)
Verdict same_guards(const bt::Document& original, const bt::Document& mutant,
                    const std::vector<std::string>& adaptables, const fretish::Domain& domain);

// Does the selector run the same alternative call in every sampled state?
bool same_selection(const bt::Document& original, const bt::Document& mutant,
                    const std::vector<std::string>& adaptables, const fretish::Domain& domain);

}  // namespace uabt::testing::oracle
