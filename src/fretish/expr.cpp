#include "fretish/expr.hpp"

#include <cctype>
#include <string_view>
#include <unordered_set>

#include <tao/pegtl.hpp>

#include "grammar/fretish_tokens.hpp"

namespace uabt::fretish {

ExprPtr make_expr(ExprKind kind, std::vector<ExprPtr> args, SourceRange range) {
  auto e = std::make_shared<Expr>();
  e->kind = kind;
  e->args = std::move(args);
  e->range = range;
  return e;
}

ExprPtr make_identifier(std::string name, SourceRange range) {
  auto e = std::make_shared<Expr>();
  e->kind = ExprKind::identifier;
  e->text = std::move(name);
  e->range = range;
  return e;
}

ExprPtr make_number(std::string literal, SourceRange range) {
  auto e = std::make_shared<Expr>();
  e->kind = ExprKind::number;
  e->text = std::move(literal);
  e->range = range;
  return e;
}

ExprPtr make_bool(bool value, SourceRange range) {
  auto e = std::make_shared<Expr>();
  e->kind = ExprKind::bool_literal;
  e->bool_value = value;
  e->text = value ? "true" : "false";
  e->range = range;
  return e;
}

bool is_boolean_connective(ExprKind kind) {
  switch (kind) {
    case ExprKind::logical_not:
    case ExprKind::logical_and:
    case ExprKind::logical_or:
    case ExprKind::logical_xor:
    case ExprKind::implies:
    case ExprKind::iff: return true;
    default: return false;
  }
}

bool is_relation(ExprKind kind) {
  switch (kind) {
    case ExprKind::eq:
    case ExprKind::ne:
    case ExprKind::lt:
    case ExprKind::le:
    case ExprKind::gt:
    case ExprKind::ge: return true;
    default: return false;
  }
}

bool is_integer_literal(const std::string& text) {
  std::size_t i = text.empty() || text[0] != '-' ? 0 : 1;
  if (i >= text.size()) return false;
  for (; i < text.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return false;
  return true;
}

bool is_natural_numeral(const Expr& e) {
  return e.kind == ExprKind::number && is_integer_literal(e.text) && e.text[0] != '-';
}

bool is_arithmetic(ExprKind kind) {
  switch (kind) {
    case ExprKind::add:
    case ExprKind::sub:
    case ExprKind::mul:
    case ExprKind::div:
    case ExprKind::mod:
    case ExprKind::pow:
    case ExprKind::negate: return true;
    default: return false;
  }
}

namespace {

// Binding strength, loosest first; matches grammar/fretish_expression.hpp.
enum Level {
  kIff = 1,
  kImplies,
  kXor,
  kOr,
  kAnd,
  kNot,
  kRelation,
  kAdditive,
  kMultiplicative,
  kNegate,
  kPower,
  kAtom,
};

int level_of(const Expr& e) {
  switch (e.kind) {
    case ExprKind::iff: return kIff;
    case ExprKind::implies: return kImplies;
    case ExprKind::logical_xor: return kXor;
    case ExprKind::logical_or: return kOr;
    case ExprKind::logical_and: return kAnd;
    case ExprKind::logical_not: return kNot;
    case ExprKind::eq:
    case ExprKind::ne:
    case ExprKind::lt:
    case ExprKind::le:
    case ExprKind::gt:
    case ExprKind::ge: return kRelation;
    case ExprKind::add:
    case ExprKind::sub: return kAdditive;
    case ExprKind::mul:
    case ExprKind::div:
    case ExprKind::mod: return kMultiplicative;
    case ExprKind::negate: return kNegate;
    case ExprKind::pow: return kPower;
    default: return kAtom;
  }
}

const char* operator_text(ExprKind kind) {
  switch (kind) {
    case ExprKind::iff: return " <-> ";
    case ExprKind::implies: return " -> ";
    case ExprKind::logical_xor: return " xor ";
    case ExprKind::logical_or: return " | ";
    case ExprKind::logical_and: return " & ";
    case ExprKind::eq: return " = ";
    case ExprKind::ne: return " != ";
    case ExprKind::lt: return " < ";
    case ExprKind::le: return " <= ";
    case ExprKind::gt: return " > ";
    case ExprKind::ge: return " >= ";
    case ExprKind::add: return " + ";
    case ExprKind::sub: return " - ";
    case ExprKind::mul: return " * ";
    case ExprKind::div: return " / ";
    case ExprKind::mod: return " mod ";
    case ExprKind::pow: return " ^ ";
    default: return " ? ";
  }
}

bool is_plain_identifier(const std::string& name) {
  namespace pegtl = tao::pegtl;
  pegtl::memory_input<pegtl::tracking_mode::lazy> in(name.data(), name.size(), "");
  return pegtl::parse<pegtl::seq<grammar::plain_identifier, pegtl::eof>>(in);
}

std::string quoted(const std::string& name) {
  std::string out = "\"";
  for (char c : name) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string name_text(const std::string& name) {
  return is_plain_identifier(name) ? name : quoted(name);
}

void print(const Expr& e, std::string& out);

// FRET's two grammars disagree on `|` under `xor` and `->` under `<->` (fretish-precedence):
// such operands are always parenthesized so the text means the same to both.
bool ambiguous_mix(ExprKind parent, ExprKind child) {
  return (parent == ExprKind::logical_xor && child == ExprKind::logical_or) ||
         (parent == ExprKind::iff && child == ExprKind::implies);
}

// Prints `child`, parenthesized when it binds looser than `min_level`.
void print_operand(const Expr& child, int min_level, std::string& out,
                   ExprKind parent = ExprKind::bool_literal) {
  if (level_of(child) < min_level || ambiguous_mix(parent, child.kind)) {
    out += '(';
    print(child, out);
    out += ')';
  } else {
    print(child, out);
  }
}

void print(const Expr& e, std::string& out) {
  const int level = level_of(e);
  switch (e.kind) {
    case ExprKind::bool_literal: out += e.bool_value ? "true" : "false"; return;
    case ExprKind::number: out += e.text; return;
    case ExprKind::identifier: out += name_text(e.text); return;
    case ExprKind::call:
      out += name_text(e.text);
      out += '(';
      for (std::size_t i = 0; i < e.args.size(); ++i) {
        if (i > 0) out += ", ";
        print(*e.args[i], out);
      }
      out += ')';
      return;
    case ExprKind::logical_not:
      out += '!';
      // `!x < 20` already means !(x < 20), but nobody should have to know that to read it.
      if (!e.args.empty() && is_relation(e.args[0]->kind)) {
        out += '(';
        print(*e.args[0], out);
        out += ')';
      } else if (!e.args.empty()) {
        print_operand(*e.args[0], kNot, out);
      }
      return;
    case ExprKind::negate: {
      out += '-';
      if (e.args.empty()) return;
      // "-1 ^ 2" would read as (-1) ^ 2 (a signed number): keep a space before a digit
      // unless the operand is that number alone.
      std::string operand;
      print_operand(*e.args[0], kNegate, operand);
      if (e.args[0]->kind != ExprKind::number && !operand.empty() &&
          std::isdigit(static_cast<unsigned char>(operand[0])))
        out += ' ';
      out += operand;
      return;
    }
    case ExprKind::logical_and:
    case ExprKind::logical_or:
      // n-ary: a nested node of the same kind keeps its parentheses so that the tree
      // (not only the meaning) survives a round trip.
      for (std::size_t i = 0; i < e.args.size(); ++i) {
        if (i > 0) out += operator_text(e.kind);
        print_operand(*e.args[i], level + 1, out);
      }
      return;
    case ExprKind::implies:
    case ExprKind::pow:
      // right-associative
      if (e.args.size() == 2) {
        print_operand(*e.args[0], level + 1, out);
        out += operator_text(e.kind);
        print_operand(*e.args[1], e.kind == ExprKind::pow ? kNegate : level, out);
        return;
      }
      break;
    default: break;
  }
  if (e.args.size() != 2) {  // malformed tree built by hand: print something readable
    out += "<?>";
    return;
  }
  // Left-associative binary operators; relations do not chain.
  const bool chains = !is_relation(e.kind);
  print_operand(*e.args[0], chains ? level : level + 1, out, e.kind);
  out += operator_text(e.kind);
  print_operand(*e.args[1], level + 1, out, e.kind);
}

void collect_identifiers(const Expr& e, std::vector<std::string>& out,
                         std::unordered_set<std::string>& seen) {
  if (e.kind == ExprKind::identifier && seen.insert(e.text).second) out.push_back(e.text);
  for (const auto& a : e.args)
    if (a) collect_identifiers(*a, out, seen);
}

}  // namespace

std::string to_fretish(const Expr& e) {
  std::string out;
  print(e, out);
  return out;
}

bool same_expr(const Expr& a, const Expr& b) {
  if (a.kind != b.kind || a.args.size() != b.args.size()) return false;
  switch (a.kind) {
    case ExprKind::bool_literal:
      if (a.bool_value != b.bool_value) return false;
      break;
    case ExprKind::number:
    case ExprKind::identifier:
    case ExprKind::call:
      if (a.text != b.text) return false;
      break;
    default: break;
  }
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    if (!a.args[i] || !b.args[i]) {
      if (a.args[i] != b.args[i]) return false;
      continue;
    }
    if (!same_expr(*a.args[i], *b.args[i])) return false;
  }
  return true;
}

std::vector<std::string> identifiers_of(const Expr& e) {
  std::vector<std::string> out;
  std::unordered_set<std::string> seen;
  collect_identifiers(e, out, seen);
  return out;
}

}  // namespace uabt::fretish
