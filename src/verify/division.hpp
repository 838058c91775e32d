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

// A state of `domain` (its assumptions included) in which `divisor` is zero, nullopt when
// there is none or the divisor does not type-check. For divisions outside FRETISH (world.json
// effects, whose divisors are translated first).
std::optional<State> zero_divisor_state(const fretish::Domain& domain,
                                        const fretish::ExprPtr& divisor, const Options& options);

// "wind=0, battery=0"
std::string state_text(const State& state);

}  // namespace uabt::verify
