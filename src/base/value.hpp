#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace uabt {

// The value of one state variable in a witness or a simulated world.
// Reals are exact rationals from the solver; `text` keeps their exact form
// ("1/3", "0.5") and `real` an approximation for evaluation and pictures.
struct Value {
  enum class Kind { boolean, integer, real, enumeration };
  Kind kind = Kind::boolean;
  bool boolean = false;
  std::int64_t integer = 0;
  double real = 0.0;
  std::string text;  // enum literal, or exact real

  static Value of_bool(bool b);
  static Value of_int(std::int64_t i);
  static Value of_real(double r, std::string exact);
  static Value of_enum(std::string literal);

  std::string to_string() const;
  bool operator==(const Value& other) const;
};

// A full assignment of the domain's variables, in declaration order.
using State = std::vector<std::pair<std::string, Value>>;

const Value* find_value(const State& state, const std::string& name);

}  // namespace uabt
