#include "bt/xml_scan.hpp"

#include "bt/xml_io.hpp"

#include <cstddef>
#include <string_view>

namespace uabt::bt::detail {

namespace {

// Length of the UTF-8 sequence starting at text[i], or 0 when it is not valid UTF-8
// (overlong forms, surrogates and code points above U+10FFFF are invalid too).
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned min_second = 0x80, max_second = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) min_second = 0xA0;
    if (lead == 0xED) max_second = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) min_second = 0x90;
    if (lead == 0xF4) max_second = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < min_second || byte(i + 1) > max_second) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

bool is_name_start(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':' || u >= 0x80;
}

bool is_name_char(char c) {
  return is_name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

// True when `rest` starts with a reference XML defines without a DTD: &lt; &gt; &amp; &apos;
// &quot; or a character reference &#N; / &#xH;. tinyxml2 passes anything else through, and
// after an earlier reference in the same value it writes a wrong byte instead (seen with
// "&#10;é&e"), so a stray '&' is refused rather than guessed at.
bool is_reference(std::string_view rest) {
  for (const std::string_view named : {"&lt;", "&gt;", "&amp;", "&apos;", "&quot;"})
    if (rest.starts_with(named)) return true;
  if (!rest.starts_with("&#")) return false;
  const bool hex = rest.size() > 2 && rest[2] == 'x';
  std::size_t k = hex ? 3 : 2, digits = 0;
  for (; k < rest.size() && digits <= 8; ++k, ++digits) {
    const char c = rest[k];
    const bool digit =
        (c >= '0' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')));
    if (!digit) break;
  }
  return digits > 0 && digits <= 8 && k < rest.size() && rest[k] == ';';
}

constexpr const char* kStrayAmpersand =
    "'&' must start a reference (&lt; &gt; &amp; &apos; &quot; &#N;); write &amp; for a literal "
    "'&'";

// Walks the text keeping line and column of the current byte.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {}

  bool done() const { return pos_ >= text_.size(); }
  std::size_t pos() const { return pos_; }
  int line() const { return line_; }
  int column() const { return column_; }
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  bool starts_with(std::string_view s) const { return text_.substr(pos_).starts_with(s); }
  std::string_view rest() const { return text_.substr(pos_); }

  void advance() {
    const char c = text_[pos_++];
    if (c == '\n') {
      ++line_;
      column_ = 1;
    } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++column_;  // continuation bytes belong to the previous character
    }
  }
  void advance(std::size_t n) {
    for (std::size_t k = 0; k < n && !done(); ++k) advance();
  }
  // Moves past the next occurrence of `end`; false (at the end of the text) when there is none.
  bool skip_past(std::string_view end) {
    while (!done()) {
      if (starts_with(end)) {
        advance(end.size());
        return true;
      }
      advance();
    }
    return false;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

std::optional<ScanProblem> check_encoding(std::string_view text) {
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    Cursor at(text);
    at.advance(nul);
    return ScanProblem{"binary content (a NUL byte at offset " + std::to_string(nul) +
                           "): this is not an XML text file",
                       at.line(), at.column()};
  }
  bool only_space = true;
  Cursor cursor(text);
  while (!cursor.done()) {
    const std::size_t i = cursor.pos();
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) {
      return ScanProblem{"invalid UTF-8 (byte offset " + std::to_string(i) +
                             "): BehaviorTree XML must be UTF-8 encoded",
                         cursor.line(), cursor.column()};
    }
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\r' && text[i] != '\n') {
      only_space = false;
    }
    cursor.advance(length);
  }
  if (only_space) return ScanProblem{"empty file: expected a <root> element", 1, 1};
  return std::nullopt;
}

}  // namespace

}  // namespace uabt::bt::detail

namespace uabt::bt {

// The scanner's own notion of a name, so the writer compacts exactly what the reader accepts.
bool is_xml_name(std::string_view name) {
  if (name.empty() || !detail::is_name_start(name.front())) return false;
  for (const char c : name)
    if (!detail::is_name_char(c)) return false;
  return true;
}

}  // namespace uabt::bt

namespace uabt::bt::detail {

ScanResult scan_xml(const std::string& input, int max_depth) {
  ScanResult result;
  std::string_view text = input;
  if (auto problem = check_encoding(text)) {
    result.problem = std::move(problem);
    return result;
  }
  // A byte-order mark is not a column: columns count from the first real character.
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  Cursor cursor(text);
  // Open elements, innermost last; never longer than max_depth.
  std::vector<ElementStart> open;
  bool complete = true;  // false when the text ends inside markup: tinyxml2 reports that
  while (!cursor.done()) {
    if (cursor.peek() != '<') {
      if (cursor.peek() == '&' && !is_reference(cursor.rest())) {
        result.problem = ScanProblem{kStrayAmpersand, cursor.line(), cursor.column()};
        return result;
      }
      cursor.advance();
      continue;
    }
    const int line = cursor.line(), column = cursor.column();
    if (cursor.starts_with("<!--")) {
      if (!(complete = cursor.skip_past("-->"))) break;
    } else if (cursor.starts_with("<![CDATA[")) {
      if (!(complete = cursor.skip_past("]]>"))) break;
    } else if (cursor.starts_with("<!")) {
      // <!DOCTYPE>, <!ENTITY>, <!ELEMENT>, <!ATTLIST>: all DTD markup.
      result.problem = ScanProblem{
          "DTD not allowed: <!DOCTYPE>, <!ENTITY> and other declarations are refused, since "
          "entity expansion can make a small file huge",
          line, column};
      return result;
    } else if (cursor.starts_with("<?")) {
      if (!(complete = cursor.skip_past("?>"))) break;
    } else if (cursor.starts_with("</")) {
      cursor.advance(2);
      std::string name;
      while (!cursor.done() && is_name_char(cursor.peek())) {
        name += cursor.peek();
        cursor.advance();
      }
      if (!(complete = cursor.skip_past(">"))) break;
      if (open.empty()) {
        result.problem = ScanProblem{"</" + name + "> closes no open element", line, column};
        return result;
      }
      if (open.back().name != name) {
        const ElementStart& inner = open.back();
        result.problem =
            ScanProblem{"</" + name + "> does not close <" + inner.name + ">, opened at line " +
                            std::to_string(inner.line) + ", column " + std::to_string(inner.column),
                        line, column};
        return result;
      }
      open.pop_back();
    } else if (is_name_start(cursor.peek(1))) {
      cursor.advance();
      ElementStart element{"", line, column};
      while (!cursor.done() && is_name_char(cursor.peek())) {
        element.name += cursor.peek();
        cursor.advance();
      }
      // To the end of the tag; '>' inside a quoted attribute value does not end it.
      char quote = '\0';
      bool self_closing = false;
      bool ended = false;
      while (!cursor.done() && !ended) {
        const char c = cursor.peek();
        if (quote != '\0') {
          if (c == quote) quote = '\0';
          if (c == '&' && !is_reference(cursor.rest())) {
            result.problem = ScanProblem{kStrayAmpersand, cursor.line(), cursor.column()};
            return result;
          }
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '>') {
          ended = true;
        } else if (c == '/' && cursor.peek(1) == '>') {
          self_closing = ended = true;
          cursor.advance();
        }
        cursor.advance();
      }
      if (!(complete = ended)) break;
      // An empty element counts as deep as one with content: one limit, however it is written.
      if (static_cast<int>(open.size()) >= max_depth) {
        result.problem = ScanProblem{"elements nested deeper than " + std::to_string(max_depth) +
                                         " levels: tinyxml2, the XML parser of "
                                         "BehaviorTree.CPP, refuses deeper files; split the tree "
                                         "into SubTrees",
                                     line, column};
        return result;
      }
      if (!self_closing) open.push_back(element);
      result.elements.push_back(std::move(element));
    } else {
      result.problem =
          ScanProblem{"'<' must start a tag; write &lt; for a literal '<'", line, column};
      return result;
    }
  }
  if (complete && !open.empty()) {
    const ElementStart& inner = open.back();
    result.problem = ScanProblem{"<" + inner.name + "> is never closed", inner.line, inner.column};
  }
  return result;
}

}  // namespace uabt::bt::detail
