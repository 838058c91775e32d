#include "smt/rational.hpp"

#include <cctype>

namespace uabt::smt {

namespace {

std::string strip_leading_zeros(const std::string& digits) {
  const auto first = digits.find_first_not_of('0');
  return first == std::string::npos ? "0" : digits.substr(first);
}

// Drops trailing zeros shared by numerator and denominator ("150/100" -> "15/10"): the value
// stays exact and witnesses stay short.
void drop_common_tens(std::string& num, std::string& den) {
  while (den.size() > 1 && num.size() > 1 && num.back() == '0' && den.back() == '0') {
    num.pop_back();
    den.pop_back();
  }
  if (num == "0") den.assign(1, '1');
}

}  // namespace

std::string Rational::text() const {
  std::string out = negative && !is_zero() ? "-" : "";
  out += numerator;
  if (!is_integer()) out += "/" + denominator;
  return out;
}

std::optional<Rational> parse_rational(const std::string& literal) {
  constexpr long kMaxExponent = 4096;  // beyond this the literal is a typo, not a quantity
  std::size_t i = 0;
  Rational r;
  if (i < literal.size() && (literal[i] == '-' || literal[i] == '+')) {
    r.negative = literal[i] == '-';
    ++i;
  }
  std::string digits;
  long scale = 0;  // value = digits * 10^-scale
  bool any_digit = false;
  while (i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i]))) {
    digits += literal[i++];
    any_digit = true;
  }
  if (i < literal.size() && literal[i] == '.') {
    ++i;
    while (i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i]))) {
      digits += literal[i++];
      ++scale;
      any_digit = true;
    }
  }
  if (!any_digit) return std::nullopt;
  if (i < literal.size() && (literal[i] == 'e' || literal[i] == 'E')) {
    ++i;
    bool negative_exponent = false;
    if (i < literal.size() && (literal[i] == '-' || literal[i] == '+')) {
      negative_exponent = literal[i] == '-';
      ++i;
    }
    if (i >= literal.size()) return std::nullopt;
    long exponent = 0;
    while (i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i]))) {
      exponent = exponent * 10 + (literal[i++] - '0');
      if (exponent > kMaxExponent) return std::nullopt;
    }
    scale += negative_exponent ? exponent : -exponent;
  }
  if (i != literal.size()) return std::nullopt;
  std::string num = strip_leading_zeros(digits);
  std::string den = "1";
  if (scale < 0) {
    if (num != "0") num.append(static_cast<std::size_t>(-scale), '0');
  } else if (scale > 0) {
    den.append(static_cast<std::size_t>(scale), '0');
  }
  drop_common_tens(num, den);
  r.numerator = num;
  r.denominator = den;
  if (r.is_zero()) r.negative = false;
  return r;
}

}  // namespace uabt::smt
