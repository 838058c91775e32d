#include "verify/fraction.hpp"

#include <algorithm>

#include "smt/rational.hpp"

namespace uabt::verify::detail {

namespace {

__int128 gcd(__int128 a, __int128 b) {
  if (a < 0) a = -a;
  if (b < 0) b = -b;
  while (b != 0) {
    const __int128 t = a % b;
    a = b;
    b = t;
  }
  return a;
}

__int128 mul(__int128 a, __int128 b) {
  __int128 out;
  if (__builtin_mul_overflow(a, b, &out)) throw FractionOverflow();
  return out;
}

__int128 add(__int128 a, __int128 b) {
  __int128 out;
  if (__builtin_add_overflow(a, b, &out)) throw FractionOverflow();
  return out;
}

constexpr __int128 kMin = static_cast<__int128>(static_cast<unsigned __int128>(1) << 127);

std::optional<__int128> digits_value(const std::string& digits) {
  __int128 v = 0;
  for (char c : digits) {
    if (__builtin_mul_overflow(v, static_cast<__int128>(10), &v) ||
        __builtin_add_overflow(v, static_cast<__int128>(c - '0'), &v))
      return std::nullopt;
  }
  return v;
}

}  // namespace

std::string int128_text(__int128 value) {
  if (value == 0) return "0";
  const bool negative = value < 0;
  unsigned __int128 u = negative ? static_cast<unsigned __int128>(-(value + 1)) + 1
                                 : static_cast<unsigned __int128>(value);
  std::string out;
  while (u != 0) {
    out.insert(out.begin(), static_cast<char>('0' + static_cast<int>(u % 10)));
    u /= 10;
  }
  return negative ? "-" + out : out;
}

Fraction Fraction::of(__int128 num, __int128 den) {
  if (den == 0) throw std::domain_error("fraction with denominator 0");
  if (num == kMin || den == kMin) throw FractionOverflow();
  if (den < 0) {
    num = -num;
    den = -den;
  }
  const __int128 g = gcd(num, den);
  Fraction f;
  f.num_ = g > 1 ? num / g : num;
  f.den_ = g > 1 ? den / g : den;
  if (f.num_ == 0) f.den_ = 1;
  return f;
}

std::optional<Fraction> Fraction::parse(const std::string& literal) {
  const auto r = smt::parse_rational(literal);
  if (!r) return std::nullopt;
  const auto n = digits_value(r->numerator), d = digits_value(r->denominator);
  if (!n || !d) return std::nullopt;
  return of(r->negative ? -*n : *n, *d);
}

std::string Fraction::text() const {
  return den_ == 1 ? int128_text(num_) : int128_text(num_) + "/" + int128_text(den_);
}

std::string Fraction::decimal() const {
  if (den_ == 1) return int128_text(num_);
  // A denominator 2^a 5^b gives a finite decimal of max(a, b) places.
  __int128 d = den_;
  int twos = 0, fives = 0;
  while (d % 2 == 0) d /= 2, ++twos;
  while (d % 5 == 0) d /= 5, ++fives;
  const int places = std::max(twos, fives);
  if (d != 1 || places > 12) return text();
  __int128 scale = 1;
  for (int k = 0; k < places; ++k) scale *= 10;
  const __int128 scaled = num_ * (scale / den_);
  const bool negative = scaled < 0;
  std::string digits = int128_text(negative ? -scaled : scaled);
  while (static_cast<int>(digits.size()) <= places) digits.insert(digits.begin(), '0');
  digits.insert(digits.end() - places, '.');
  return (negative ? "-" : "") + digits;
}

Fraction Fraction::operator-() const {
  if (num_ == kMin) throw FractionOverflow();
  Fraction f = *this;
  f.num_ = -f.num_;
  return f;
}

Fraction operator+(const Fraction& a, const Fraction& b) {
  if (a.den_ == b.den_) return Fraction::of(add(a.num_, b.num_), a.den_);
  const __int128 g = gcd(a.den_, b.den_);
  const __int128 da = a.den_ / g, db = b.den_ / g;
  return Fraction::of(add(mul(a.num_, db), mul(b.num_, da)), mul(a.den_, db));
}

Fraction operator*(const Fraction& a, const Fraction& b) {
  // Cross-reduce first: the products stay as small as the result allows.
  const __int128 g1 = gcd(a.num_, b.den_), g2 = gcd(b.num_, a.den_);
  const __int128 n1 = g1 > 1 ? a.num_ / g1 : a.num_, d2 = g1 > 1 ? b.den_ / g1 : b.den_;
  const __int128 n2 = g2 > 1 ? b.num_ / g2 : b.num_, d1 = g2 > 1 ? a.den_ / g2 : a.den_;
  return Fraction::of(mul(n1, n2), mul(d1, d2));
}

Fraction operator/(const Fraction& a, const Fraction& b) {
  if (b.num_ == 0) throw std::domain_error("division of a fraction by 0");
  return a * Fraction::of(b.den_, b.num_);
}

std::strong_ordering operator<=>(const Fraction& a, const Fraction& b) {
  if (a.den_ == b.den_) return a.num_ <=> b.num_;
  return (a - b).num_ <=> static_cast<__int128>(0);
}

}  // namespace uabt::verify::detail
