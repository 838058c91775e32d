#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "base/value.hpp"
#include "load/mission.hpp"
#include "verify/verify.hpp"

namespace uabt::verify {

// `guard-division-by-zero`: every `/` and `mod` of a selection guard, a mission property
// (guarantees and Environment assumptions) and a domain assumption whose divisor can be zero
// in a state of the domain that its assumptions allow, where the division's own context
// holds (the other conjuncts around it, the premise of an implication, the branch of an
// ite), with that state as the witness. A literal zero divisor is arith-division-by-zero's.
std::vector<Finding> check_divisions(const load::Mission& mission, const Options& options);

// An expression whose divisions are checked: a guard, a property, an assumption, or a tree's
// script read as FRETISH (verify/script_reading.hpp).
struct DivisionSource {
  fretish::ExprPtr expr;  // a condition
  SourceLocation where;   // the file, and a place when the expression has none
  std::string what;       // "the guard of Req1"
  const fretish::SelectionRequirement* selection = nullptr;  // whose guard it is
  // Also a literal zero divisor, as arith-division-by-zero (a guard's typing reports its own).
  bool literal_zero = false;
  // What a division by zero does there.
  std::string consequence = "the solver then gives it any value";
};

// The one check behind check_divisions, for any expressions over `domain`: each division whose
// divisor can be zero where its context holds is a guard-division-by-zero with that state.
std::vector<Finding> check_divisions(const fretish::Domain& domain,
                                     const std::vector<DivisionSource>& sources,
                                     const Options& options);

// A state of `domain` (its assumptions included) in which `divisor` is zero, nullopt when
// there is none or the divisor does not type-check. For divisions outside FRETISH (world.json
// effects, whose divisors are translated first).
std::optional<State> zero_divisor_state(const fretish::Domain& domain,
                                        const fretish::ExprPtr& divisor, const Options& options);

}  // namespace uabt::verify
