#include "base/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string_view>

namespace uabt {

namespace {

// 2^63: integer-valued doubles below it in magnitude fit a signed 64-bit integer.
constexpr double kTwoTo63 = 9223372036854775808.0;

bool fits_int64(double v) {
  return std::floor(v) == v && v >= -kTwoTo63 && v < kTwoTo63;
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// "-12.50" style: optional '-', digits, optional '.' and digits.
bool is_plain_decimal(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  const auto dot = s.find('.');
  if (dot == std::string_view::npos) return all_digits(s);
  return all_digits(s.substr(0, dot)) && all_digits(s.substr(dot + 1));
}

std::size_t significant_digits(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  std::string digits;
  for (char c : s)
    if (c != '.') digits += c;
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  digits.erase(0, first);
  if (s.find('.') != std::string_view::npos) {
    // Trailing zeros after the point carry no precision.
    const auto last = digits.find_last_not_of('0');
    digits.erase(last + 1);
  }
  return digits.size();
}

bool parse_u64(std::string_view s, std::uint64_t& out) {
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

// "p/q" → its finite decimal expansion, when q has no prime factors but 2 and 5.
bool fraction_to_decimal(std::string_view text, std::string& decimal) {
  bool negative = false;
  if (!text.empty() && text.front() == '-') {
    negative = true;
    text.remove_prefix(1);
  }
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return false;
  std::uint64_t p = 0, q = 0;
  if (!parse_u64(text.substr(0, slash), p) || !parse_u64(text.substr(slash + 1), q) || q == 0)
    return false;
  const std::uint64_t g = std::gcd(p, q);
  p /= g;
  q /= g;
  std::uint64_t rest = q;
  while (rest % 2 == 0) rest /= 2;
  while (rest % 5 == 0) rest /= 5;
  if (rest != 1) return false;
  decimal.clear();
  if (negative && p != 0) decimal += '-';
  decimal += number_text(static_cast<std::int64_t>(p / q));
  unsigned __int128 remainder = p % q;
  if (remainder != 0) decimal += '.';
  // q divides a power of ten, so the division ends; 64 digits bound q = 2^64.
  for (int i = 0; remainder != 0 && i < 80; ++i) {
    remainder *= 10;
    decimal += static_cast<char>('0' + static_cast<int>(remainder / q));
    remainder %= q;
  }
  return remainder == 0;
}

}  // namespace

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  if (value == 0) return "0";  // -0 too
  const double magnitude = std::fabs(value);
  const std::chars_format format = magnitude >= 1e-7 && magnitude < 1e21
                                       ? std::chars_format::fixed
                                       : std::chars_format::scientific;
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, format);
  return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
}

std::string number_text(std::int64_t value) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, ec == std::errc() ? end : buffer);
}

nlohmann::ordered_json number_json(double value) {
  if (!std::isfinite(value)) return number_text(value);
  if (fits_int64(value)) return static_cast<std::int64_t>(value);
  return value;
}

nlohmann::ordered_json value_json(const Value& value) {
  switch (value.kind) {
    case Value::Kind::boolean: return value.boolean;
    case Value::Kind::integer: return value.integer;
    case Value::Kind::enumeration: return value.text;
    case Value::Kind::real: {
      if (value.text == number_text(value.real) && std::isfinite(value.real))
        return number_json(value.real);
      std::string decimal = value.text;
      if (!is_plain_decimal(decimal) && !fraction_to_decimal(value.text, decimal))
        return value.text;
      // A double holds any decimal of at most 15 significant digits so that it prints back
      // as the same decimal: only then is the number exact.
      if (significant_digits(decimal) > 15) return value.text;
      double number = 0;
      const auto [ptr, ec] =
          std::from_chars(decimal.data(), decimal.data() + decimal.size(), number);
      if (ec != std::errc() || ptr != decimal.data() + decimal.size() || !std::isfinite(number))
        return value.text;
      return number_json(number);
    }
  }
  return value.to_string();
}

nlohmann::ordered_json state_json(const State& state) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, value] : state) out[name] = value_json(value);
  return out;
}

Value number_value(double value) {
  if (fits_int64(value)) return Value::of_int(static_cast<std::int64_t>(value));
  return Value::of_real(value, number_text(value));
}

}  // namespace uabt
