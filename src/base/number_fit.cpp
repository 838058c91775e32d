#include "base/number_fit.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace uabt {

std::string number_misfit(std::string_view literal, bool exact_integers) {
  std::string_view digits = literal;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (digits.find_first_of(".eE") == std::string_view::npos) {
    if (exact_integers) return "";
    std::int64_t value = 0;
    if (std::from_chars(digits.data(), digits.data() + digits.size(), value).ec !=
        std::errc::result_out_of_range)
      return "";
    return "the integer " + std::string(literal) +
           " does not fit in 64 bits (-9223372036854775808 to 9223372036854775807)";
  }
  // strtod tells an overflow (infinity) from an underflow (zero); from_chars reports both alike.
  const std::string text(digits);
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(value))
    return "the number " + std::string(literal) +
           " does not fit in a 64-bit real (largest about 1.8e308)";
  return "";
}

}  // namespace uabt
