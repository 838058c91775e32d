#pragma once
#include <optional>
#include <string>

#include "fretish/expr.hpp"

namespace uabt::smt {

// An exact rational written as decimal digit strings: numerator / denominator (> 0).
struct Rational {
  bool negative = false;
  std::string numerator = "0";    // digits, no leading zeros ("0" for zero)
  std::string denominator = "1";  // digits, a power of ten for decimal literals

  bool is_integer() const { return denominator == "1"; }
  bool is_zero() const { return numerator == "0"; }
  // "-3", "15/10000": the form Z3's real_val/int_val accept.
  std::string text() const;
};

// Reads a FRETISH number literal ("12", "0.5", "1e3", "2.5E-2", optionally with a leading
// '-') exactly. nullopt when it is not a number or its exponent is absurdly large.
std::optional<Rational> parse_rational(const std::string& literal);

using fretish::is_integer_literal;

}  // namespace uabt::smt
