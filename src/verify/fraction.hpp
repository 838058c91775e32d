#pragma once
#include <compare>
#include <optional>
#include <stdexcept>
#include <string>

namespace uabt::verify::detail {

// Thrown when an exact computation leaves 128 bits: the measure is then given as bounds.
struct FractionOverflow : std::overflow_error {
  FractionOverflow() : std::overflow_error("the exact arithmetic exceeds 128 bits") {}
};

// An exact rational over 128-bit integers, always reduced, denominator > 0. Every operation
// checks for overflow (FractionOverflow) rather than wrapping: a measure is exact or absent.
class Fraction {
 public:
  Fraction() = default;
  Fraction(long long n) : num_(n) {}  // NOLINT: an integer is a fraction
  static Fraction of(__int128 num, __int128 den);

  // A FRETISH number literal ("12", "-0.25", "1e3"); nullopt when it does not fit.
  static std::optional<Fraction> parse(const std::string& literal);

  __int128 numerator() const { return num_; }
  __int128 denominator() const { return den_; }
  bool is_zero() const { return num_ == 0; }
  int sign() const { return num_ > 0 ? 1 : num_ < 0 ? -1 : 0; }
  // The greatest integer not above the value.
  __int128 floor() const {
    const __int128 q = num_ / den_;
    return num_ % den_ != 0 && num_ < 0 ? q - 1 : q;
  }
  double to_double() const { return static_cast<double>(num_) / static_cast<double>(den_); }
  // "3", "-7/2": exact.
  std::string text() const;
  // "0.125" when the value is a short decimal, else text(): how a person reads a bound.
  std::string decimal() const;

  Fraction operator-() const;
  friend Fraction operator+(const Fraction& a, const Fraction& b);
  friend Fraction operator-(const Fraction& a, const Fraction& b) { return a + (-b); }
  friend Fraction operator*(const Fraction& a, const Fraction& b);
  friend Fraction operator/(const Fraction& a, const Fraction& b);
  Fraction& operator+=(const Fraction& b) { return *this = *this + b; }
  friend bool operator==(const Fraction& a, const Fraction& b) {
    return a.num_ == b.num_ && a.den_ == b.den_;
  }
  friend std::strong_ordering operator<=>(const Fraction& a, const Fraction& b);

 private:
  __int128 num_ = 0;
  __int128 den_ = 1;
};

std::string int128_text(__int128 value);

}  // namespace uabt::verify::detail
