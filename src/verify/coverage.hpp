#pragma once
#include <set>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/selection.hpp"
#include "smt/types.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::detail {

// The assumptions that constrain the variables in `names`, transitively (an assumption over
// a name pulls its other variables in): the guards' space. Adds their variables to `names`
// and their atoms to `atoms`. Other assumptions only constrain other variables and, the
// domain being consistent, do not change what the guards select.
std::vector<const fretish::Expr*> link_assumptions(
    const std::vector<const fretish::Expr*>& assumptions, const smt::Typing& typing,
    std::set<std::string>& names, std::vector<const fretish::Expr*>& atoms);

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
