#pragma once
#include <map>
#include <optional>
#include <string>

#include "fretish/expr.hpp"
#include "smt/types.hpp"
#include "verify/fraction.hpp"

namespace uabt::verify::detail {

// An atom `Σ coefficient·variable + constant  op  0` over numeric variables, exact.
struct LinearAtom {
  std::map<std::string, Fraction> coefficients;  // non-zero only
  Fraction constant;
  fretish::ExprKind op = fretish::ExprKind::eq;  // eq ne lt le gt ge

  // The atom's truth where the left-hand side takes `value`.
  bool holds_at(const Fraction& value) const;
  // `op` applied to lhs(values) (missing variables are an error).
  bool holds(const std::map<std::string, Fraction>& values) const;
};

// The atom as a linear relation, when it is one: + - unary minus, multiplication by a constant,
// real division by a non-zero constant, numbers and integer/real variables. nullopt for
// anything else (products of variables, integer division, mod, powers, functions) or when a
// constant does not fit in 128 bits.
std::optional<LinearAtom> linear_atom(const fretish::Expr& atom, const smt::Typing& typing);

}  // namespace uabt::verify::detail
