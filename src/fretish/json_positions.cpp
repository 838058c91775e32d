#include "fretish/json_positions.hpp"

#include <cctype>
#include <string>

namespace uabt::fretish::detail {

namespace {

enum class Role { other, requirements, variables, requirement };

struct Frame {
  bool is_object = false;
  Role role = Role::other;
  std::string key;  // objects: the member whose value comes next
};

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  JsonLayout run() {
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '"') {
        string_token();
      } else if (c == '{' || c == '[') {
        value_starts(c);
        Frame f;
        f.is_object = c == '{';
        f.role = pending_role_;
        stack_.push_back(std::move(f));
        advance();
      } else if (c == '}' || c == ']') {
        if (!stack_.empty()) stack_.pop_back();
        advance();
      } else if (c == ',') {
        if (!stack_.empty() && stack_.back().is_object) stack_.back().key.clear();
        advance();
      } else if (c == ':' || std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else {
        value_starts(c);  // number, true, false, null
        while (i_ < text_.size() &&
               std::string_view(",]} \t\r\n").find(text_[i_]) == std::string_view::npos)
          advance();
      }
    }
    return std::move(layout_);
  }

 private:
  void advance() {
    if (text_[i_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++i_;
  }

  bool expecting_key() const {
    return !stack_.empty() && stack_.back().is_object && stack_.back().key.empty();
  }

  // Called at the first character of any value; decides the role of a container value.
  void value_starts(char first) {
    pending_role_ = Role::other;
    const JsonPosition here{line_, column_};
    if (stack_.empty()) {
      if (first == '[') pending_role_ = Role::requirements;  // a bare array of requirements
      return;
    }
    const Frame& parent = stack_.back();
    if (parent.role == Role::requirements) {
      layout_.requirements.push_back({here, false, {}});
      pending_role_ = Role::requirement;
    } else if (parent.role == Role::variables) {
      layout_.variables.push_back(here);
    } else if (stack_.size() == 1 && parent.is_object) {
      if (parent.key == "requirements") pending_role_ = Role::requirements;
      if (parent.key == "variables") pending_role_ = Role::variables;
    }
  }

  void string_token() {
    const bool is_key = expecting_key();
    if (!is_key) value_starts('"');
    const bool is_text = !is_key && !stack_.empty() && stack_.back().role == Role::requirement &&
                         stack_.back().key == "fulltext";
    const std::size_t quote = i_;
    advance();  // opening quote
    if (is_text && !layout_.requirements.empty()) {
      layout_.requirements.back().has_text = true;
      layout_.requirements.back().text = {line_, column_};
      layout_.requirements.back().text_quote = quote;
    }
    std::string value;
    while (i_ < text_.size() && text_[i_] != '"') {
      if (text_[i_] == '\\' && i_ + 1 < text_.size()) {
        value += text_[i_];
        advance();
      }
      value += text_[i_];
      advance();
    }
    if (i_ < text_.size()) advance();  // closing quote
    if (is_key) stack_.back().key = value;
  }

  std::string_view text_;
  std::size_t i_ = 0;
  int line_ = 1;
  int column_ = 1;
  std::vector<Frame> stack_;
  Role pending_role_ = Role::other;
  JsonLayout layout_;
};

}  // namespace

JsonLayout scan_fret_export(std::string_view text) {
  return Scanner(text).run();
}

JsonPosition position_of(std::string_view text, std::size_t offset) {
  JsonPosition p;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

}  // namespace uabt::fretish::detail
