#pragma once
// Every JSON file uabt reads (scenarios, world.json, uplink.json, FRET exports, monitor traces)
// goes through parse_json_input, so that hostile input gives one kind of error everywhere: a
// place in the file and uabt's own words, never a library exception, a stack overflow or a
// number silently rounded to infinity.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace uabt {

// Deepest nesting of arrays and objects a JSON input may have. uabt's formats need at most
// six levels; the margin leaves room for descriptions, yet a hostile file cannot make a
// recursive reader overflow the stack.
inline constexpr int kMaxJsonDepth = 64;

struct JsonInputError {
  std::size_t offset = 0;  // byte of `text` where the problem starts
  int line = 1;            // 1-based, of `offset`
  int column = 1;
  std::string message;  // e.g. "invalid JSON in array: unexpected end of input; expected ']'"
};

// Where a place inside a JSON string value stands in the file. `quote` is the offset of the
// string's opening quote in `text`; a parser of the decoded string reported `line:column`
// (1-based, in bytes) counting from `start_line:start_column`, where the string's first
// character stands. Escapes count as written ("\n" is two characters of one line, "\u00e9"
// six); a place inside an escape is the escape's backslash, one past the end the closing quote.
std::size_t json_string_source_offset(std::string_view text, std::size_t quote, int start_line,
                                      int start_column, int line, int column);

namespace detail {
// The first place where nesting passes kMaxJsonDepth, a number fits no type, or an object
// repeats a key, if any.
std::optional<JsonInputError> refuse_before_parsing(std::string_view text);
JsonInputError syntax_error(std::string_view text, const nlohmann::json::parse_error& e);
JsonInputError unrepresentable(std::string_view text);
}  // namespace detail

// Parses one JSON document (as nlohmann::json, or nlohmann::ordered_json where the order of
// keys matters). Nesting beyond kMaxJsonDepth, numbers that fit no 64-bit type (an integer
// beyond 64 bits, a real beyond a double's range such as 1e400) and a key written twice in one
// object (which the parser would silently resolve to the last) are refused by a scan over the
// bytes before the recursive parse; syntax errors are reported in uabt's words.
template <class Json = nlohmann::json>
std::optional<Json> parse_json_input(std::string_view text, JsonInputError& error) {
  if (auto refused = detail::refuse_before_parsing(text)) {
    error = std::move(*refused);
    return std::nullopt;
  }
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    error = detail::syntax_error(text, e);
  } catch (const nlohmann::json::exception&) {
    // The scan refuses every number the parser cannot hold; this is the fail-closed remainder.
    error = detail::unrepresentable(text);
  }
  return std::nullopt;
}

}  // namespace uabt
