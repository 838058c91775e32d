#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace uabt::bt::script {

// A script that does not parse or fails while running. `column` is 1-based within the
// script text (0 when the failure is not tied to a place, e.g. an undefined key at tick).
class ScriptError : public std::runtime_error {
 public:
  ScriptError(const std::string& message, std::size_t column)
      : std::runtime_error(message), column_(column) {}
  std::size_t column() const { return column_; }

 private:
  std::size_t column_;
};

enum class Tok : std::uint8_t {
  end,
  integer,
  real,
  string,
  name,
  kw_true,
  kw_false,
  lparen,
  rparen,
  semicolon,
  question,
  colon,
  assign_create,  // :=
  assign,         // =
  add_assign,     // +=
  sub_assign,     // -=
  mul_assign,     // *=
  div_assign,     // /=
  eq,
  ne,
  lt,
  gt,
  le,
  ge,
  and_and,
  or_or,
  bang,
  tilde,
  amp,
  pipe,
  caret,
  plus,
  minus,
  star,
  slash,
  dotdot,
};

struct Token {
  Tok kind = Tok::end;
  std::size_t column = 0;  // 1-based
  std::int64_t integer = 0;
  double real = 0.0;
  std::string text;  // name or string contents; a number as written
};

// Spelling of a token kind for messages: "':='", "a number", "end of script".
std::string describe(Tok kind);

// BT.CPP 4.x script tokens: numbers (decimal, 0x hex, reals with '.' or exponent),
// single-quoted strings, names [A-Za-z_@][A-Za-z0-9_]*, true/false, operators.
std::vector<Token> tokenize(std::string_view code);

}  // namespace uabt::bt::script
