#pragma once
#include <z3++.h>

namespace uabt::smt {

// FRETISH's integer `a / b`: the quotient truncated toward zero, as FRET's targets (C, Lustre,
// SMV) and the concrete evaluator (fretish/evaluate.cpp, ARCHITECTURE §14) compute it.
// SMT-LIB's div is Euclidean, which agrees with truncation for a non-negative dividend.
inline z3::expr truncated_quotient(const z3::expr& a, const z3::expr& b) {
  return z3::ite(a >= 0, a / b, -((-a) / b));
}

// FRETISH's integer `a mod b`: the remainder of the truncated quotient, with the sign of the
// dividend.
inline z3::expr truncated_remainder(const z3::expr& a, const z3::expr& b) {
  return a - b * truncated_quotient(a, b);
}

}  // namespace uabt::smt
