#pragma once
#include <vector>

#include "smt/encoder.hpp"
#include "verify/session.hpp"

namespace uabt::verify::detail {

// Asks whether D is satisfiable and, when it is, asserts it for every later question. When it
// is not, reports `domain-inconsistent` naming a minimal set of declarations and assumptions
// that contradict each other; when the solver cannot tell, `verification-inconclusive`.
Answer check_domain(Session& session, const std::vector<smt::Encoder::DomainPart>& parts,
                    std::vector<Finding>& findings);

}  // namespace uabt::verify::detail
