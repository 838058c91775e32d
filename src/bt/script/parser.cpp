// Recursive-descent parser for BT.CPP 4.x scripts (precedence: see ast.hpp).
#include <algorithm>

#include "bt/script/ast.hpp"

namespace uabt::bt::script {

class Parser {
 public:
  Parser(std::string_view code, Script& program) : tokens_(tokenize(code)), p_(program) {}

  void parse_statements() {
    while (true) {
      if (peek() == Tok::end) break;
      if (peek() == Tok::semicolon) {  // empty statement
        ++pos_;
        continue;
      }
      p_.statements_.push_back(expression());
      if (peek() == Tok::semicolon) {
        ++pos_;
        continue;
      }
      if (peek() != Tok::end)
        fail("expected ';' or end of script, found " + describe(peek()), token());
    }
  }

 private:
  enum Group : unsigned { kArithmetic = 1, kBitwise = 2 };

  Tok peek() const { return tokens_[pos_].kind; }
  const Token& token() const { return tokens_[pos_]; }
  const Token& advance() { return tokens_[pos_++]; }

  [[noreturn]] void fail(const std::string& message, const Token& at) {
    throw ScriptError(message, at.column);
  }

  std::uint32_t depth_of(std::uint32_t index) const { return depths_[index]; }

  std::uint32_t add(Expr e, std::uint32_t depth, const Token& at) {
    if (depth > static_cast<std::uint32_t>(kMaxScriptDepth))
      fail("expression nested deeper than " + std::to_string(kMaxScriptDepth) + " levels", at);
    e.column = at.column;
    p_.nodes_.push_back(std::move(e));
    depths_.push_back(depth);
    return static_cast<std::uint32_t>(p_.nodes_.size() - 1);
  }

  std::uint32_t unary(Op op, std::uint32_t operand, const Token& at) {
    Expr e;
    e.op = op;
    e.a = operand;
    return add(std::move(e), depth_of(operand) + 1, at);
  }

  std::uint32_t binary(Op op, std::uint32_t lhs, std::uint32_t rhs, const Token& at) {
    Expr e;
    e.op = op;
    e.a = lhs;
    e.b = rhs;
    return add(std::move(e), std::max(depth_of(lhs), depth_of(rhs)) + 1, at);
  }

  // Lexy's dsl::groups in BT.CPP: one comparison operand uses arithmetic or bitwise
  // operators, not both, unless parenthesized.
  void note_group(Group g, const Token& at) {
    if ((groups_ & ~static_cast<unsigned>(g)) != 0)
      fail(
          "arithmetic and bitwise/logical-not operators cannot be mixed without parentheses "
          "(at " +
              describe(at.kind) + ")",
          at);
    groups_ |= g;
  }

  // A full expression: the top level, inside ( ), and the middle of ?:.
  std::uint32_t expression() {
    if (++nesting_ > kMaxScriptDepth) fail("expression nested too deeply", token());
    const unsigned saved_groups = groups_;
    groups_ = 0;
    const std::uint32_t result = assignment();
    groups_ = saved_groups;
    --nesting_;
    return result;
  }

  static bool is_assign(Tok t) {
    return t == Tok::assign_create || t == Tok::assign || t == Tok::add_assign ||
           t == Tok::sub_assign || t == Tok::mul_assign || t == Tok::div_assign;
  }

  std::uint32_t assignment() {
    const Token& first = token();
    const std::uint32_t lhs = conditional();
    if (!is_assign(peek())) return lhs;
    const Token& op_token = advance();
    if (p_.nodes_[lhs].op != Op::name)
      fail("the left side of " + describe(op_token.kind) + " must be a blackboard key", first);
    // The right side may assign again: `a := b := 3` is `a := (b := 3)`, as in BT.CPP.
    if (++nesting_ > kMaxScriptDepth) fail("expression nested too deeply", op_token);
    const std::uint32_t rhs = assignment();
    --nesting_;
    Op op = Op::assign;
    switch (op_token.kind) {
      case Tok::assign_create: op = Op::assign_create; break;
      case Tok::add_assign: op = Op::add_assign; break;
      case Tok::sub_assign: op = Op::sub_assign; break;
      case Tok::mul_assign: op = Op::mul_assign; break;
      case Tok::div_assign: op = Op::div_assign; break;
      default: break;
    }
    if (nesting_ > 1) p_.nested_assignment_ = true;
    return binary(op, lhs, rhs, op_token);
  }

  std::uint32_t conditional() {
    const std::uint32_t condition = logical();
    if (peek() != Tok::question) return condition;
    const Token& q = advance();
    const std::uint32_t then = expression();
    if (peek() != Tok::colon) fail("expected ':' of '?:', found " + describe(peek()), token());
    ++pos_;
    const std::uint32_t otherwise = logical();
    if (peek() == Tok::question) fail("'?:' cannot be chained without parentheses", token());
    Expr e;
    e.op = Op::conditional;
    e.a = condition;
    e.b = then;
    e.c = otherwise;
    const std::uint32_t depth =
        std::max({depth_of(condition), depth_of(then), depth_of(otherwise)}) + 1;
    return add(std::move(e), depth, q);
  }

  std::uint32_t logical() {
    std::uint32_t lhs = comparison();
    while (peek() == Tok::and_and || peek() == Tok::or_or) {
      const Token& op = advance();
      const std::uint32_t rhs = comparison();
      lhs = binary(op.kind == Tok::and_and ? Op::logic_and : Op::logic_or, lhs, rhs, op);
    }
    return lhs;
  }

  static bool is_compare(Tok t) {
    return t == Tok::eq || t == Tok::ne || t == Tok::lt || t == Tok::gt || t == Tok::le ||
           t == Tok::ge;
  }

  std::uint32_t comparison() {
    const Token& first = token();
    std::vector<std::uint32_t> operands{operand()};
    std::vector<CompareOp> ops;
    while (is_compare(peek())) {
      switch (advance().kind) {
        case Tok::eq: ops.push_back(CompareOp::eq); break;
        case Tok::ne: ops.push_back(CompareOp::ne); break;
        case Tok::lt: ops.push_back(CompareOp::lt); break;
        case Tok::gt: ops.push_back(CompareOp::gt); break;
        case Tok::le: ops.push_back(CompareOp::le); break;
        default: ops.push_back(CompareOp::ge); break;
      }
      operands.push_back(operand());
    }
    if (ops.empty()) return operands.front();
    Expr e;
    e.op = Op::compare;
    e.list_begin = static_cast<std::uint32_t>(p_.operands_.size());
    e.list_size = static_cast<std::uint32_t>(operands.size());
    e.ops_begin = static_cast<std::uint32_t>(p_.compare_ops_.size());
    std::uint32_t depth = 0;
    for (auto o : operands) depth = std::max(depth, depth_of(o));
    p_.operands_.insert(p_.operands_.end(), operands.begin(), operands.end());
    p_.compare_ops_.insert(p_.compare_ops_.end(), ops.begin(), ops.end());
    return add(std::move(e), depth + 1, first);
  }

  // One comparison operand: its operators must all be of one group.
  std::uint32_t operand() {
    const unsigned saved = groups_;
    groups_ = 0;
    const std::uint32_t result = bit_or();
    groups_ = saved;
    return result;
  }

  std::uint32_t bit_or() {
    std::uint32_t lhs = bit_and();
    while (peek() == Tok::pipe || peek() == Tok::caret) {
      const Token& op = advance();
      note_group(kBitwise, op);
      lhs = binary(op.kind == Tok::pipe ? Op::bit_or : Op::bit_xor, lhs, bit_and(), op);
    }
    return lhs;
  }

  std::uint32_t bit_and() {
    std::uint32_t lhs = concat();
    while (peek() == Tok::amp) {
      const Token& op = advance();
      note_group(kBitwise, op);
      lhs = binary(Op::bit_and, lhs, concat(), op);
    }
    return lhs;
  }

  std::uint32_t concat() {
    std::uint32_t lhs = sum();
    while (peek() == Tok::dotdot) {
      const Token& op = advance();
      note_group(kArithmetic, op);
      lhs = binary(Op::concat, lhs, sum(), op);
    }
    return lhs;
  }

  std::uint32_t sum() {
    std::uint32_t lhs = product();
    while (peek() == Tok::plus || peek() == Tok::minus) {
      const Token& op = advance();
      note_group(kArithmetic, op);
      lhs = binary(op.kind == Tok::plus ? Op::add : Op::sub, lhs, product(), op);
    }
    return lhs;
  }

  std::uint32_t product() {
    std::uint32_t lhs = prefix();
    while (peek() == Tok::star || peek() == Tok::slash) {
      const Token& op = advance();
      note_group(kArithmetic, op);
      lhs = binary(op.kind == Tok::star ? Op::mul : Op::div, lhs, prefix(), op);
    }
    return lhs;
  }

  std::uint32_t prefix() {
    const Tok t = peek();
    if (t != Tok::minus && t != Tok::bang && t != Tok::tilde) return atom();
    const Token& op = advance();
    note_group(t == Tok::minus ? kArithmetic : kBitwise, op);
    if (++nesting_ > kMaxScriptDepth) fail("expression nested too deeply", op);
    const std::uint32_t inner = prefix();
    --nesting_;
    const Op kind = t == Tok::minus  ? Op::negate
                    : t == Tok::bang ? Op::logical_not
                                     : Op::complement;
    return unary(kind, inner, op);
  }

  std::uint32_t atom() {
    const Token& t = advance();
    Expr e;
    switch (t.kind) {
      case Tok::lparen: {
        const std::uint32_t inner = expression();
        if (peek() != Tok::rparen) fail("expected ')', found " + describe(peek()), token());
        ++pos_;
        return inner;
      }
      case Tok::kw_true:
      case Tok::kw_false: e.literal = ScriptValue::of_bool(t.kind == Tok::kw_true); break;
      case Tok::integer:
        e.literal = ScriptValue::of_int(t.integer);
        e.spelling = t.text;
        break;
      case Tok::real:
        e.literal = ScriptValue::of_real(t.real);
        e.spelling = t.text;
        break;
      case Tok::string: e.literal = ScriptValue::of_string(t.text); break;
      case Tok::name:
        e.op = Op::name;
        e.name = t.text;
        return add(std::move(e), 1, t);
      default: fail("expected an operand, found " + describe(t.kind), t);
    }
    e.op = Op::literal;
    return add(std::move(e), 1, t);
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  Script& p_;
  std::vector<std::uint32_t> depths_;
  int nesting_ = 0;
  unsigned groups_ = 0;
};

Script Script::parse(std::string_view code) {
  Script script;
  script.code_ = std::string(code);
  Parser(code, script).parse_statements();
  return script;
}

std::vector<std::string> Script::names() const {
  std::vector<std::string> out;
  for (const Expr& e : nodes_)
    if (e.op == Op::name && std::find(out.begin(), out.end(), e.name) == out.end())
      out.push_back(e.name);
  return out;
}

std::vector<std::string> Script::assigned() const {
  std::vector<const Expr*> targets;  // the name on the left of each assignment
  for (const Expr& e : nodes_)
    if (is_assignment(e.op) && nodes_[e.a].op == Op::name) targets.push_back(&nodes_[e.a]);
  std::sort(targets.begin(), targets.end(),
            [](const Expr* x, const Expr* y) { return x->column < y->column; });
  std::vector<std::string> out;
  for (const Expr* target : targets) out.push_back(entry_key(target->name));
  return out;
}

bool Script::writes() const {
  return std::any_of(nodes_.begin(), nodes_.end(),
                     [](const Expr& e) { return is_assignment(e.op); });
}

}  // namespace uabt::bt::script
