#pragma once
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "fretish/expr.hpp"
#include "smt/types.hpp"
#include "verify/fraction.hpp"

namespace uabt::verify::detail {

// Σ coefficient·variable + constant, exact: the arithmetic of linear_atom and of the explicit
// engine's cuts (prove/cells.cpp). Beyond 128 bits an operation throws FractionOverflow.
struct Affine {
  std::map<std::string, Fraction, std::less<>> terms;  // no zero coefficient
  Fraction constant;

  static Affine of_variable(const std::string& name);
  static Affine of_constant(const Fraction& value);
  bool is_constant() const { return terms.empty(); }
  Affine scaled(const Fraction& k) const;
  Affine plus(const Affine& other, int sign = 1) const;  // this + sign·other
};
// l·r when a factor is constant, l / r when r is a non-zero constant; nullopt otherwise (and
// when either is nullopt).
std::optional<Affine> product(const std::optional<Affine>& l, const std::optional<Affine>& r);
std::optional<Affine> quotient(const std::optional<Affine>& l, const std::optional<Affine>& r);

// How a caller reads the leaves of an expression as an affine form: which identifiers are
// variables of the form, and which divisions truncate (integer division, a step function).
struct AffineReading {
  std::function<bool(const fretish::Expr& identifier)> variable;
  std::function<bool(const fretish::Expr& division)> truncates;
};
// The affine form of a numeric expression: numbers, variables, + - unary minus, multiplication
// by a constant and division by a non-zero constant that does not truncate. nullopt for
// anything else; beyond 128 bits it throws FractionOverflow.
std::optional<Affine> affine_form(const fretish::Expr& e, const AffineReading& reading);

// An atom `Σ coefficient·variable + constant  op  0` over numeric variables, exact.
struct LinearAtom {
  std::map<std::string, Fraction, std::less<>> coefficients;  // non-zero only
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
