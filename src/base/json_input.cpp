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

std::size_t json_string_source_offset(std::string_view text, std::size_t quote, int start_line,
                                      int start_column, int reported_line, int reported_column) {
  // The place within the decoded string.
  const int line = reported_line - start_line + 1;
  const int column = line == 1 ? reported_column - start_column + 1 : reported_column;
  auto hex = [&](std::size_t at) -> long {
    if (at + 4 > text.size()) return -1;
    long code = 0;
    for (std::size_t k = at; k < at + 4; ++k) {
      const char c = text[k];
      const int digit = c >= '0' && c <= '9'   ? c - '0'
                        : c >= 'a' && c <= 'f' ? c - 'a' + 10
                        : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                               : -1;
      if (digit < 0) return -1;
      code = code * 16 + digit;
    }
    return code;
  };
  int at_line = 1, at_column = 1;
  std::size_t i = quote + 1;
  while (i < text.size() && text[i] != '"') {
    // One decoded unit: how many raw characters, how many decoded bytes, a line break or not.
    std::size_t raw = 1;
    int bytes = 1;
    bool newline = false;
    if (text[i] == '\\' && i + 1 < text.size()) {
      raw = 2;
      newline = text[i + 1] == 'n';
      if (text[i + 1] == 'u') {
        raw = 6;
        const long code = hex(i + 2);
        newline = code == '\n';
        bytes = code < 0x80 ? 1 : code < 0x800 ? 2 : 3;
        const bool pair = code >= 0xD800 && code <= 0xDBFF && i + 11 < text.size() &&
                          text[i + 6] == '\\' && text[i + 7] == 'u' && hex(i + 8) >= 0xDC00 &&
                          hex(i + 8) <= 0xDFFF;
        if (pair) {
          raw = 12;
          bytes = 4;
        }
      }
    }
    if (at_line > line || (at_line == line && at_column + bytes > column)) return i;
    if (newline) {
      ++at_line;
      at_column = 1;
    } else {
      at_column += bytes;
    }
    i += raw;
  }
  return std::min(i, text.size());
}

}  // namespace uabt
