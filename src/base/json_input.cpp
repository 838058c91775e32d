#include "base/json_input.hpp"

#include <algorithm>
#include <cctype>
#include <unordered_map>
#include <vector>

#include "base/number_fit.hpp"

namespace uabt {
namespace {

JsonInputError error_at(std::string_view text, std::size_t offset, std::string message) {
  JsonInputError e;
  e.offset = std::min(offset, text.size());
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < e.offset; ++i) {
    if (text[i] == '\n') {
      ++e.line;
      line_start = i + 1;
    }
  }
  e.column = static_cast<int>(e.offset - line_start) + 1;
  e.message = std::move(message);
  return e;
}

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error
// while parsing value - invalid literal; last read: 'no'" becomes "invalid JSON in value:
// invalid literal; last read: 'no'".
std::string syntax_message(const std::string& what) {
  std::string detail = what;
  if (const auto column = what.find("column "); column != std::string::npos)
    if (const auto colon = what.find(": ", column); colon != std::string::npos)
      detail = what.substr(colon + 2);
  static constexpr std::string_view kParsing = "syntax error while parsing ";
  if (detail.rfind(kParsing, 0) == 0) {
    detail = detail.substr(kParsing.size());
    if (const auto dash = detail.find(" - "); dash != std::string::npos)
      return "invalid JSON in " + detail.substr(0, dash) + ": " + detail.substr(dash + 3);
  }
  return "invalid JSON: " + detail;
}

}  // namespace

namespace detail {

// Scans the bytes outside strings: the first place where nesting passes kMaxJsonDepth, a
// number fits no type or an object repeats a key. Invalid JSON is left to the parser.
std::optional<JsonInputError> refuse_before_parsing(std::string_view text) {
  // One entry per open array or object; an object remembers where each of its keys starts,
  // because the parser keeps only the last of two equal keys and says nothing.
  struct Open {
    bool object = false;
    std::unordered_map<std::string_view, std::size_t> keys;
  };
  std::vector<Open> open;
  bool in_string = false, escaped = false;
  std::size_t string_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
        if (open.empty() || !open.back().object) continue;
        std::size_t next = i + 1;
        while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
        if (next >= text.size() || text[next] != ':') continue;  // a value, not a key
        const std::string_view key = text.substr(string_start, i + 1 - string_start);
        const auto [first, inserted] = open.back().keys.emplace(key, string_start);
        if (!inserted) {
          const JsonInputError earlier = error_at(text, first->second, "");
          return error_at(text, string_start,
                          "key " + std::string(key) + " appears twice in one object (first at " +
                              std::to_string(earlier.line) + ":" + std::to_string(earlier.column) +
                              "); JSON readers keep only one of them, so write it once");
        }
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
      string_start = i;
    } else if (c == '[' || c == '{') {
      if (static_cast<int>(open.size()) >= kMaxJsonDepth)
        return error_at(text, i,
                        "JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                            " arrays and objects (uabt's limit for every JSON input)");
      open.push_back({c == '{', {}});
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i;
      while (end < text.size() && is_number_char(text[end])) ++end;
      const std::string_view token = text.substr(i, end - i);
      if (std::string why = number_misfit(token); !why.empty())
        return error_at(text, i, std::move(why));
      i = end - 1;
    }
  }
  return std::nullopt;
}

JsonInputError syntax_error(std::string_view text, const nlohmann::json::parse_error& e) {
  return error_at(text, e.byte == 0 ? 0 : e.byte - 1, syntax_message(e.what()));
}

JsonInputError unrepresentable(std::string_view text) {
  return error_at(text, 0, "invalid JSON: a value uabt cannot represent");
}

}  // namespace detail

}  // namespace uabt
