// BehaviorTree.CPP script conditions back into FRETISH (the inverse of compile's
// atom_to_script), following BT.CPP 4.x's grammar (scripting/operators.hpp).
#include "conform/script_parse.hpp"

#include <cctype>
#include <stdexcept>

namespace uabt::conform {

using fretish::ExprKind;
using fretish::ExprPtr;

namespace {

enum class TokenKind { number, name, root_name, string, op, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text;
  std::size_t offset = 0;
};

struct ScriptError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

bool is_name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

std::vector<Token> tokenize(const std::string& code) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  const std::size_t n = code.size();
  auto at = [&](std::size_t k) { return k < n ? code[k] : '\0'; };
  while (i < n) {
    const char c = code[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    Token t;
    t.offset = i;
    if (is_digit(c) || (c == '.' && is_digit(at(i + 1)))) {
      std::size_t j = i;
      while (is_digit(at(j))) ++j;
      if (at(j) == '.') {
        ++j;
        while (is_digit(at(j))) ++j;
      }
      if (at(j) == 'e' || at(j) == 'E') {
        std::size_t k = j + 1;
        if (at(k) == '+' || at(k) == '-') ++k;
        if (is_digit(at(k))) {
          while (is_digit(at(k))) ++k;
          j = k;
        }
      }
      if (is_name_char(at(j)))
        throw ScriptError("malformed number '" + code.substr(i, j + 1 - i) + "'");
      t.kind = TokenKind::number;
      t.text = code.substr(i, j - i);
      if (t.text.front() == '.') t.text = "0" + t.text;
      if (t.text.back() == '.') t.text += "0";
      i = j;
    } else if (is_name_start(c) || (c == '@' && is_name_start(at(i + 1)))) {
      const bool root = c == '@';
      std::size_t j = root ? i + 1 : i;
      const std::size_t start = j;
      while (is_name_char(at(j))) ++j;
      t.kind = root ? TokenKind::root_name : TokenKind::name;
      t.text = code.substr(start, j - start);
      i = j;
    } else if (c == '\'') {
      const std::size_t close = code.find('\'', i + 1);
      if (close == std::string::npos) throw ScriptError("unterminated string");
      t.kind = TokenKind::string;
      t.text = code.substr(i + 1, close - i - 1);
      i = close + 1;
    } else {
      static const char* const two_char[] = {"==", "!=", "<=", ">=", "&&", "||",
                                             ":=", "+=", "-=", "*=", "/="};
      std::string op(1, c);
      for (const char* candidate : two_char) {
        if (c == candidate[0] && at(i + 1) == candidate[1]) op = candidate;
      }
      static const std::string singles = "()!<>+-*/=;?:&|^~";
      if (op.size() == 1 && singles.find(c) == std::string::npos)
        throw ScriptError(std::string("unexpected character '") + c + "'");
      t.kind = TokenKind::op;
      t.text = op;
      i += op.size();
    }
    tokens.push_back(std::move(t));
  }
  Token end;
  end.offset = n;
  tokens.push_back(end);
  return tokens;
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, const fretish::Domain& domain, ScriptReading& out)
      : tokens_(std::move(tokens)), domain_(domain), out_(out) {}

  ExprPtr parse() {
    ExprPtr e = logical();
    if (peek().kind != TokenKind::end) unexpected();
    return e;
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  bool at_op(const char* op) const { return peek().kind == TokenKind::op && peek().text == op; }
  const Token& next() { return tokens_[pos_++]; }

  [[noreturn]] void unexpected() const {
    const Token& t = peek();
    if (t.kind == TokenKind::end) throw ScriptError("the code ends too early");
    if (t.kind == TokenKind::op) {
      const std::string& op = t.text;
      if (op == ":=" || op == "=" || op == "+=" || op == "-=" || op == "*=" || op == "/=")
        throw ScriptError("'" + op + "' assigns to the blackboard: a condition must not");
      if (op == ";") throw ScriptError("';' chains statements: a condition is one expression");
      if (op == "?" || op == ":")
        throw ScriptError("the conditional operator '?:' is not supported");
      if (op == "&" || op == "|" || op == "^" || op == "~")
        throw ScriptError("the bitwise operator '" + op + "' is not a condition operator");
    }
    throw ScriptError("unexpected '" + t.text + "' at offset " + std::to_string(t.offset));
  }

  // && and || share one level and associate to the left (BT.CPP's `logical`).
  ExprPtr logical() {
    ExprPtr lhs = comparison();
    while (at_op("&&") || at_op("||")) {
      const ExprKind kind = next().text == "&&" ? ExprKind::logical_and : ExprKind::logical_or;
      lhs = fretish::make_expr(kind, {lhs, comparison()});
    }
    return lhs;
  }

  static bool comparison_kind(const Token& t, ExprKind& kind) {
    if (t.kind != TokenKind::op) return false;
    if (t.text == "==")
      kind = ExprKind::eq;
    else if (t.text == "!=")
      kind = ExprKind::ne;
    else if (t.text == "<")
      kind = ExprKind::lt;
    else if (t.text == "<=")
      kind = ExprKind::le;
    else if (t.text == ">")
      kind = ExprKind::gt;
    else if (t.text == ">=")
      kind = ExprKind::ge;
    else
      return false;
    return true;
  }

  // A chain a < b <= c holds when every adjacent pair does.
  ExprPtr comparison() {
    ExprPtr first = sum();
    std::vector<ExprPtr> links;
    ExprPtr lhs = first;
    ExprKind kind{};
    while (comparison_kind(peek(), kind)) {
      next();
      ExprPtr rhs = sum();
      links.push_back(fretish::make_expr(kind, {lhs, rhs}));
      lhs = rhs;
    }
    if (links.empty()) return first;
    if (links.size() == 1) return links.front();
    return fretish::make_expr(ExprKind::logical_and, std::move(links));
  }

  ExprPtr sum() {
    ExprPtr lhs = product();
    while (at_op("+") || at_op("-")) {
      const ExprKind kind = next().text == "+" ? ExprKind::add : ExprKind::sub;
      lhs = fretish::make_expr(kind, {lhs, product()});
    }
    return lhs;
  }

  ExprPtr product() {
    ExprPtr lhs = prefix();
    while (at_op("*") || at_op("/")) {
      const ExprKind kind = next().text == "*" ? ExprKind::mul : ExprKind::div;
      lhs = fretish::make_expr(kind, {lhs, prefix()});
    }
    return lhs;
  }

  // BT.CPP applies one prefix operator to an atom.
  ExprPtr prefix() {
    if (at_op("-")) {
      next();
      return fretish::make_expr(ExprKind::negate, {atom()});
    }
    if (at_op("!")) {
      next();
      return fretish::make_expr(ExprKind::logical_not, {atom()});
    }
    return atom();
  }

  bool is_enum_literal(const std::string& text) const {
    for (const auto& v : domain_.variables)
      for (const auto& literal : v.enum_values)
        if (literal == text) return true;
    return false;
  }

  ExprPtr atom() {
    const Token& t = peek();
    switch (t.kind) {
      case TokenKind::number: next(); return fretish::make_number(t.text);
      case TokenKind::string: {
        next();
        if (!is_enum_literal(t.text))
          throw ScriptError("the string '" + t.text + "' is not a value of any enum of the domain");
        if (domain_.find(t.text) != nullptr)
          throw ScriptError("the string '" + t.text +
                            "' is both an enum value and a variable of the domain");
        return fretish::make_identifier(t.text);
      }
      case TokenKind::name:
      case TokenKind::root_name: {
        next();
        if (t.kind == TokenKind::name && (t.text == "true" || t.text == "false"))
          return fretish::make_bool(t.text == "true");
        if (domain_.find(t.text) == nullptr && is_enum_literal(t.text))
          throw ScriptError("'" + t.text +
                            "' is read as a blackboard entry, not as the enum value; write '" +
                            t.text + "' in quotes");
        if (t.kind == TokenKind::name) out_.local_reads.push_back(t.text);
        return fretish::make_identifier(t.text);
      }
      case TokenKind::op:
        if (t.text == "(") {
          next();
          ExprPtr inner = logical();
          if (!at_op(")")) unexpected();
          next();
          return inner;
        }
        unexpected();
      case TokenKind::end: unexpected();
    }
    unexpected();
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  const fretish::Domain& domain_;
  ScriptReading& out_;
};

}  // namespace

ScriptReading parse_script_condition(const std::string& code, const fretish::Domain& domain) {
  ScriptReading reading;
  try {
    Parser parser(tokenize(code), domain, reading);
    reading.expr = parser.parse();
  } catch (const ScriptError& e) {
    reading.expr = nullptr;
    reading.local_reads.clear();
    reading.error = e.what();
  }
  return reading;
}

}  // namespace uabt::conform
