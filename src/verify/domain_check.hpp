#pragma once
#include <vector>

#include "smt/encoder.hpp"
#include "verify/session.hpp"

namespace uabt::verify::detail {

// false when a declaration of the domain is invalid (domain-invalid: an empty range, a refused
// enum): the domain is unknown then, and no question is asked of it.
bool domain_known(const fretish::Domain& domain);

// Asks whether D is satisfiable and, when it is, asserts it for every later question. When it
// is not, reports `domain-inconsistent` naming a minimal set of declarations and assumptions
// that contradict each other; when the solver cannot tell, `verification-inconclusive`.
Answer check_domain(Session& session, const std::vector<smt::Encoder::DomainPart>& parts,
                    std::vector<Finding>& findings);

}  // namespace uabt::verify::detail
