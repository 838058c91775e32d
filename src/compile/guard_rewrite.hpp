#pragma once
#include <stdexcept>
#include <string>

#include "fretish/domain.hpp"
#include "fretish/expr.hpp"

namespace uabt::compile {

// A guard that cannot be expressed as a BehaviorTree.CPP condition subtree.
struct UnsupportedGuard : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// True when `e` denotes a truth value (a connective, a boolean literal, a relation, or an
// identifier that is a boolean variable rather than an enum literal or a number).
bool is_boolean_valued(const fretish::Expr& e, const fretish::Domain& domain);

// True when `e` is a number FRETISH computes as a real: a real variable or a number written
// with a fraction or an exponent, or + - * / with such an operand (integers divide
// truncating, so `/` of two integers is an integer).
bool is_real_valued(const fretish::Expr& e, const fretish::Domain& domain);

// Rewrites xor, ->, <-> into & | ! (Algorithm 1 knows only those), and equalities between
// truth values (`OnDust = true`, `A = B`) into the same connectives. An equality of reals
// becomes two orderings (`x = 0.5` is `x >= 0.5 & x <= 0.5`): BehaviorTree.CPP's script `==`
// holds within float epsilon of equal, its `<=` and `>=` are exact. Other relations over
// numbers and enums stay atoms.
fretish::ExprPtr to_and_or_not(const fretish::Expr& e, const fretish::Domain& domain);

}  // namespace uabt::compile
