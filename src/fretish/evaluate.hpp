#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "fretish/expr.hpp"

namespace uabt::fretish {

// The value of a FRETISH expression in a state, the one meaning every evaluator shares
// (ARCHITECTURE §14): the witness checker (smt::evaluate), the monitor's compiled expressions
// and verify's compiled conditions apply these operators and differ only in how they read a
// name.
//
// - Integers are exact 64-bit; a result beyond 64 bits has no value. `/` truncates toward
//   zero and `mod` keeps the dividend's sign, as FRET's targets (C, Lustre, SMV) compute them.
// - An operation with a real operand is real (a double); so are absReal, minReal, maxReal and
//   `^` unless both are integers and the exponent is a whole number written out. A real that is
//   not finite (`0.0 ^ -1`, `(-8) ^ 0.5`, beyond the double range) has no value.
// - A division or `mod` by zero, an unset name and an ill-typed operation have no value.
// - No value is local: it reaches the result only where the result depends on it. A definite
//   false decides an `&`, a definite true an `|`, a false premise or a true conclusion an `=>`,
//   and ite reads only its chosen branch; `x = 0 | 10 / x > 1` has a value in every state.
struct Val {
  enum class Kind : std::uint8_t { missing, boolean, number, symbol };
  // Why a value is absent; a value with a fault keeps the kind it would have had.
  enum class Fault : std::uint8_t { none, unset, division_by_zero, overflow, not_finite, type };
  Kind kind = Kind::missing;
  bool integer = false;  // a number of integer type: `whole` is exact
  Fault fault = Fault::none;
  int symbol = -1;         // an enum literal or another name that is a value
  std::int64_t whole = 0;  // an integer's value, a boolean's 0/1
  double number = 0;       // a number's value (an integer's as a double), a boolean's 0/1

  static Val of_bool(bool b) { return {Kind::boolean, false, Fault::none, -1, b, b ? 1.0 : 0.0}; }
  static Val of_number(double x) { return {Kind::number, false, Fault::none, -1, 0, x}; }
  static Val of_whole(std::int64_t i) {
    return {Kind::number, true, Fault::none, -1, i, static_cast<double>(i)};
  }
  static Val of_integer(double x) {  // a whole number read as a double (JSON)
    if (!(x > -0x1p63 && x < 0x1p63)) return none(Fault::overflow, Kind::number, true);
    return of_whole(static_cast<std::int64_t>(x));
  }
  static Val of_symbol(int s) { return {Kind::symbol, false, Fault::none, s, 0, 0}; }
  static Val none(Fault f, Kind k = Kind::missing, bool integer = false) {
    return {k, integer, f, -1, 0, 0};
  }

  bool known() const { return kind != Kind::missing && fault == Fault::none; }
  bool truth() const { return whole != 0; }  // a known boolean's value
};

// "division by zero", "no value", …: why a value is absent, for messages.
const char* fault_text(Val::Fault fault);

// An operator of the expression language: every kind of Expr but literals, names and calls,
// and the functions FRET's expressions have.
enum class Op : std::uint8_t {
  logical_not,
  logical_and,
  logical_or,
  logical_xor,
  implies,
  iff,
  eq,
  ne,
  lt,
  le,
  gt,
  ge,
  add,
  sub,
  mul,
  div,
  mod,
  pow,        // a real power
  pow_whole,  // `^` with an exponent written as a whole number: an integer for an integer base
  negate,
  abs_int,
  abs_real,
  min_int,
  min_real,
  max_int,
  max_real,
  ite,
  unknown,  // a call of no function above: no value
};

// The operator `e` applies (a connective, relation, arithmetic or one of FRET's functions).
Op operator_of(const Expr& e);

// The operator's value on `n` operand values (all of them evaluated): the one meaning above.
Val apply(Op op, const Val* args, std::size_t n);

// A number written out: an integer when it has no fraction or exponent (no value beyond 64
// bits), else a real.
Val number_literal(const std::string& text);

// The value of `e` where `name(identifier, prefer_literal)` gives each name's value;
// `prefer_literal` is set for the other side of an `=` whose first side is an enum value.
using NameValue = std::function<Val(const std::string& name, bool prefer_literal)>;
Val evaluate(const Expr& e, const NameValue& name);

}  // namespace uabt::fretish
