#include "fretish/source_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace uabt::fretish::detail {

TextMap::TextMap(std::string_view text, const TextOrigin& origin)
    : file_(origin.file), line_(origin.line), column_(origin.column) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') line_starts_.push_back(i + 1);
}

SourceLocation TextMap::location(std::size_t offset) const {
  const auto next = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto index = static_cast<std::size_t>(next - line_starts_.begin()) - 1;
  const int in_line = static_cast<int>(offset - line_starts_[index]);
  SourceLocation loc;
  loc.file = file_;
  loc.line = line_ + static_cast<int>(index);
  loc.column = (index == 0 ? column_ : 1) + in_line;
  return loc;
}

SourceRange TextMap::range(std::size_t begin, std::size_t end) const {
  const SourceLocation b = location(begin);
  const SourceLocation e = location(end > begin ? end - 1 : begin);
  return {b.line, b.column, e.line, e.column};
}

namespace {

bool is_id_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '%';
}

bool is_operator_char(char c) {
  return std::strchr("&|!~<>=-+*/^", c) != nullptr && c != '\0';
}

std::string join_alternatives(const std::vector<const char*>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += (i + 1 == names.size()) ? " or " : ", ";
    out += names[i];
  }
  return out;
}

// The operator or keyword just before `offset`, when there is one ("&", "satisfy").
std::string previous_operator(std::string_view text, std::size_t offset) {
  std::size_t end = std::min(offset, text.size());
  while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  if (end == 0) return {};
  std::size_t begin = end;
  if (is_operator_char(text[end - 1]) || text[end - 1] == '(' || text[end - 1] == ',') {
    if (text[end - 1] == '(' || text[end - 1] == ',') return std::string(1, text[end - 1]);
    while (begin > 0 && end - begin < 3 && is_operator_char(text[begin - 1])) --begin;
    return std::string(text.substr(begin, end - begin));
  }
  while (begin > 0 && is_id_char(text[begin - 1])) --begin;
  const std::string_view word = text.substr(begin, end - begin);
  return is_reserved_word(word) ? std::string(word) : std::string();
}

// The ASCII that FRETISH means by characters word processors and formula editors put in.
struct AsciiForm {
  char32_t code;
  const char* ascii;
};
constexpr AsciiForm kAsciiForms[] = {
    {U'\u2264', "<="},      {U'\u2265', ">="},  {U'\u2260', "!="}, {U'\u00AC', "!"},
    {U'\u2227', "&"},       {U'\u2228', "|"},   {U'\u2192', "->"}, {U'\u21D2', "=>"},
    {U'\u2194', "<->"},     {U'\u21D4', "<=>"}, {U'\u2212', "-"},  {U'\u2013', "-"},
    {U'\u2014', "-"},       {U'\u00D7', "*"},   {U'\u00F7', "/"},  {U'\u201C', "\""},
    {U'\u201D', "\""},      {U'\u2018', "'"},   {U'\u2019', "'"},  {U'\u00A0', "a space"},
    {U'\u2009', "a space"}, {U'\u2261', "<->"}, {U'\u2295', "xor"}};

// "'≤' (U+2264, not ASCII): write <=" for the UTF-8 character at the start of `text`.
std::string describe_non_ascii(std::string_view text) {
  const unsigned char lead = static_cast<unsigned char>(text[0]);
  const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
  char32_t code = length == 1 ? lead : lead & (0x7F >> length);
  bool valid = length > 1 && text.size() >= length;
  for (std::size_t k = 1; valid && k < length; ++k) {
    const unsigned char next = static_cast<unsigned char>(text[k]);
    valid = (next & 0xC0) == 0x80;
    code = (code << 6) | (next & 0x3F);
  }
  if (!valid) return "a byte that is not UTF-8 (FRETISH is ASCII)";
  char hex[16];
  std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(code));
  std::string out = "'" + std::string(text.substr(0, length)) + "' (" + hex + ", not ASCII)";
  for (const auto& form : kAsciiForms)
    if (form.code == code)
      return out + ": write " +
             (std::string_view(form.ascii) == "a space" ? std::string("a space")
                                                        : "'" + std::string(form.ascii) + "'");
  return out + ": FRETISH is ASCII";
}

}  // namespace

bool is_reserved_word(std::string_view word) {
  namespace pegtl = tao::pegtl;
  pegtl::memory_input<pegtl::tracking_mode::lazy> in(word.data(), word.size(), "");
  return pegtl::parse<pegtl::seq<grammar::reserved_word, pegtl::eof>>(in);
}

std::string describe_token(std::string_view text, std::size_t offset, const char* end_name) {
  if (offset >= text.size()) return end_name;
  const char c = text[offset];
  if (c == '\n' || c == '\r') return end_name;
  if (std::isalpha(static_cast<unsigned char>(c))) {
    std::size_t end = offset;
    while (end < text.size() && is_id_char(text[end])) ++end;
    const std::string_view word = text.substr(offset, end - offset);
    if (is_reserved_word(word)) return "keyword '" + std::string(word) + "'";
    return "'" + std::string(word) + "'";
  }
  if (std::isdigit(static_cast<unsigned char>(c))) {
    std::size_t end = offset;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '.'))
      ++end;
    return "'" + std::string(text.substr(offset, end - offset)) + "'";
  }
  if (c == '"') return "a quoted string";
  if (is_operator_char(c)) {
    std::size_t end = offset;
    while (end < text.size() && end - offset < 3 && is_operator_char(text[end])) ++end;
    return "'" + std::string(text.substr(offset, end - offset)) + "'";
  }
  if (static_cast<unsigned char>(c) >= 0x80) return describe_non_ascii(text.substr(offset));
  if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) == 0x7f)
    return "a character that is not printable ASCII";
  return "'" + std::string(1, c) + "'";
}

Finding syntax_finding(const ParseOutcome& outcome, std::string_view text, const TextMap& map,
                       const char* end_name) {
  const SourceLocation where = map.location(outcome.error_offset);
  if (outcome.too_deep) {
    return make_finding("fretish-syntax",
                        "nesting deeper than " + std::to_string(kMaxNesting) +
                            " (parentheses, 'if … then' or function calls)",
                        where);
  }
  const std::string found = describe_token(text, outcome.error_offset, end_name);
  if (outcome.expected.empty()) return make_finding("fretish-syntax", "unexpected " + found, where);

  std::string message = "expected " + join_alternatives(outcome.expected);
  const bool wants_expression =
      std::any_of(outcome.expected.begin(), outcome.expected.end(),
                  [](const char* n) { return std::strcmp(n, "an expression") == 0; });
  const std::string after = wants_expression ? previous_operator(text, outcome.error_offset) : "";
  if (!after.empty()) message += " after '" + after + "'";
  if (after.empty() || found != end_name) message += ", found " + found;
  return make_finding("fretish-syntax", message, where);
}

std::size_t without_final_period(std::string_view text) {
  std::size_t end = text.size();
  while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  if (end > 0 && text[end - 1] == '.') --end;
  return end;
}

}  // namespace uabt::fretish::detail
