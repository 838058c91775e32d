#pragma once
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/selection.hpp"
#include "smt/types.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::detail {

// Exact coverage counts for one adaptable node by enumerating the discrete variables its guards
// range over (plus those of the assumptions that constrain them, transitively). Each atom is
// evaluated once per assignment of its own variables, then spread over the whole space as a
// bitset; the guards' boolean structure is bitwise logic. Fills everything but `reachable`
// and `gap_region`; counted=false with a reason when the space is not finite and small.
// The regions are grown first from the witnesses of the gap and overlap `findings`, so that
// every state the verifier reports lies in a listed region.
// `requirements` are type checked (in `typing`); `assumptions` only the well-typed ones.
Coverage count_coverage(const std::string& adaptable,
                        const std::vector<const fretish::SelectionRequirement*>& requirements,
                        const std::vector<const fretish::Expr*>& assumptions,
                        const fretish::Domain& domain, const smt::Typing& typing,
                        const std::vector<Finding>& findings = {});

}  // namespace uabt::verify::detail
