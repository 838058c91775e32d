#include "bt/script/lexer.hpp"

#include <cctype>
#include <charconv>

namespace uabt::bt::script {

std::string describe(Tok kind) {
  switch (kind) {
    case Tok::end: return "end of script";
    case Tok::integer:
    case Tok::real: return "a number";
    case Tok::string: return "a string";
    case Tok::name: return "a name";
    case Tok::kw_true: return "'true'";
    case Tok::kw_false: return "'false'";
    case Tok::lparen: return "'('";
    case Tok::rparen: return "')'";
    case Tok::semicolon: return "';'";
    case Tok::question: return "'?'";
    case Tok::colon: return "':'";
    case Tok::assign_create: return "':='";
    case Tok::assign: return "'='";
    case Tok::add_assign: return "'+='";
    case Tok::sub_assign: return "'-='";
    case Tok::mul_assign: return "'*='";
    case Tok::div_assign: return "'/='";
    case Tok::eq: return "'=='";
    case Tok::ne: return "'!='";
    case Tok::lt: return "'<'";
    case Tok::gt: return "'>'";
    case Tok::le: return "'<='";
    case Tok::ge: return "'>='";
    case Tok::and_and: return "'&&'";
    case Tok::or_or: return "'||'";
    case Tok::bang: return "'!'";
    case Tok::tilde: return "'~'";
    case Tok::amp: return "'&'";
    case Tok::pipe: return "'|'";
    case Tok::caret: return "'^'";
    case Tok::plus: return "'+'";
    case Tok::minus: return "'-'";
    case Tok::star: return "'*'";
    case Tok::slash: return "'/'";
    case Tok::dotdot: return "'..'";
  }
  return "?";
}

namespace {

bool is_name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '@';
}
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

class Lexer {
 public:
  explicit Lexer(std::string_view code) : code_(code) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    while (true) {
      skip_space();
      Token t;
      t.column = pos_ + 1;
      if (pos_ >= code_.size()) {
        out.push_back(std::move(t));
        return out;
      }
      const char c = code_[pos_];
      if (is_digit(c)) {
        number(t);
      } else if (is_name_start(c)) {
        name(t);
      } else if (c == '\'') {
        string(t);
      } else {
        symbol(t);
      }
      out.push_back(std::move(t));
    }
  }

 private:
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < code_.size() ? code_[pos_ + ahead] : '\0';
  }

  void skip_space() {
    while (pos_ < code_.size() && std::isspace(static_cast<unsigned char>(code_[pos_]))) ++pos_;
  }

  void number(Token& t) {
    const std::size_t start = pos_;
    if (peek() == '0' && (peek(1) == 'x' || peek(1) == 'X')) {
      pos_ += 2;
      const std::size_t digits = pos_;
      while (std::isxdigit(static_cast<unsigned char>(peek()))) ++pos_;
      if (pos_ == digits) throw ScriptError("hexadecimal number without digits", t.column);
      std::uint64_t value = 0;
      const auto [end, ec] = std::from_chars(code_.data() + digits, code_.data() + pos_, value, 16);
      if (ec != std::errc() || value > static_cast<std::uint64_t>(INT64_MAX))
        throw ScriptError("number out of range: " + std::string(code_.substr(start, pos_ - start)),
                          t.column);
      t.kind = Tok::integer;
      t.integer = static_cast<std::int64_t>(value);
      t.text = std::string(code_.substr(start, pos_ - start));
      return;
    }
    while (is_digit(peek())) ++pos_;
    bool real = false;
    // "1..2" is 1 .. 2 (concatenation), so a '.' makes a real only before a digit.
    if (peek() == '.' && is_digit(peek(1))) {
      real = true;
      ++pos_;
      while (is_digit(peek())) ++pos_;
    }
    if (peek() == 'e' || peek() == 'E') {
      std::size_t ahead = 1;
      if (peek(ahead) == '+' || peek(ahead) == '-') ++ahead;
      if (is_digit(peek(ahead))) {
        real = true;
        pos_ += ahead;
        while (is_digit(peek())) ++pos_;
      }
    }
    if (is_name_char(peek()))
      throw ScriptError(
          "malformed number near '" + std::string(code_.substr(start, pos_ + 1 - start)) + "'",
          t.column);
    const char* first = code_.data() + start;
    const char* last = code_.data() + pos_;
    t.text.assign(first, last);
    if (real) {
      t.kind = Tok::real;
      const auto [end, ec] = std::from_chars(first, last, t.real);
      if (ec != std::errc() || end != last)
        throw ScriptError("number out of range: " + std::string(first, last), t.column);
    } else {
      t.kind = Tok::integer;
      const auto [end, ec] = std::from_chars(first, last, t.integer);
      if (ec != std::errc() || end != last)
        throw ScriptError("number out of range: " + std::string(first, last), t.column);
    }
  }

  void name(Token& t) {
    const std::size_t start = pos_++;
    while (is_name_char(peek())) ++pos_;
    t.text = std::string(code_.substr(start, pos_ - start));
    if (t.text == "true") {
      t.kind = Tok::kw_true;
    } else if (t.text == "false") {
      t.kind = Tok::kw_false;
    } else {
      t.kind = Tok::name;
    }
  }

  void string(Token& t) {
    const std::size_t start = ++pos_;
    while (pos_ < code_.size() && code_[pos_] != '\'') ++pos_;
    if (pos_ >= code_.size()) throw ScriptError("unterminated string: missing closing '", t.column);
    t.kind = Tok::string;
    t.text = std::string(code_.substr(start, pos_ - start));
    ++pos_;
  }

  void symbol(Token& t) {
    const char c = peek();
    const char n = peek(1);
    auto two = [&](Tok kind) {
      t.kind = kind;
      pos_ += 2;
    };
    auto one = [&](Tok kind) {
      t.kind = kind;
      pos_ += 1;
    };
    switch (c) {
      case '(': return one(Tok::lparen);
      case ')': return one(Tok::rparen);
      case ';': return one(Tok::semicolon);
      case '?': return one(Tok::question);
      case ':': return n == '=' ? two(Tok::assign_create) : one(Tok::colon);
      case '=': return n == '=' ? two(Tok::eq) : one(Tok::assign);
      case '!': return n == '=' ? two(Tok::ne) : one(Tok::bang);
      case '<': return n == '=' ? two(Tok::le) : one(Tok::lt);
      case '>': return n == '=' ? two(Tok::ge) : one(Tok::gt);
      case '&': return n == '&' ? two(Tok::and_and) : one(Tok::amp);
      case '|': return n == '|' ? two(Tok::or_or) : one(Tok::pipe);
      case '^': return one(Tok::caret);
      case '~': return one(Tok::tilde);
      case '+': return n == '=' ? two(Tok::add_assign) : one(Tok::plus);
      case '-': return n == '=' ? two(Tok::sub_assign) : one(Tok::minus);
      case '*': return n == '=' ? two(Tok::mul_assign) : one(Tok::star);
      case '/': return n == '=' ? two(Tok::div_assign) : one(Tok::slash);
      case '.':
        if (n == '.') return two(Tok::dotdot);
        break;
      case '"':
        throw ScriptError("strings are written in single quotes in BT.CPP scripts: 'text'",
                          t.column);
      default: break;
    }
    throw ScriptError("unexpected " + character_at(pos_), t.column);
  }

  // The character at `at` for a message: a whole UTF-8 sequence in quotes, or the byte's value
  // where it is not printable text, so that a message is always valid UTF-8 (JSON and SARIF
  // readers refuse anything else).
  std::string character_at(std::size_t at) const {
    const auto byte = static_cast<unsigned char>(code_[at]);
    // A lead byte's sequence length; 0 for a continuation byte or one no UTF-8 text holds.
    std::size_t length = byte < 0x80                   ? 1
                         : byte >= 0xC2 && byte < 0xE0 ? 2
                         : byte >= 0xE0 && byte < 0xF0 ? 3
                         : byte >= 0xF0 && byte < 0xF5 ? 4
                                                       : 0;
    for (std::size_t i = 1; i < length; ++i)
      if (at + i >= code_.size() || (static_cast<unsigned char>(code_[at + i]) & 0xC0) != 0x80)
        length = 0;
    if (length == 0 || (length == 1 && (byte < 0x20 || byte == 0x7F))) {
      static constexpr char kHex[] = "0123456789ABCDEF";
      return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 0xF];
    }
    return "character '" + std::string(code_.substr(at, length)) + "'";
  }

  std::string_view code_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<Token> tokenize(std::string_view code) {
  return Lexer(code).run();
}

}  // namespace uabt::bt::script
