#pragma once
#include <set>
#include <string>

#include "conform/context.hpp"
#include "conform/equivalence.hpp"

namespace uabt::conform {

// The selection tree of one adaptable node against its requirements: shape, one branch per
// requirement (compiled-missing-alternative), guards equivalent under D
// (compiled-guard-mismatch), priority order (compiled-order), alternatives equal to their
// files (compiled-alternative-mismatch; `checked_alternatives` keeps each one to one report).
void check_selection(Context& ctx, Prover& prover, const std::string& adaptable,
                     std::set<std::string>& checked_alternatives);

}  // namespace uabt::conform
