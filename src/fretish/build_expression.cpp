#include "fretish/build_expression.hpp"

#include <algorithm>
#include <cctype>

#include "base/number_fit.hpp"
#include "base/text.hpp"

namespace uabt::fretish::detail {

namespace {

ExprKind relation_kind(std::string_view op) {
  if (op == "<") return ExprKind::lt;
  if (op == "<=") return ExprKind::le;
  if (op == ">") return ExprKind::gt;
  if (op == ">=") return ExprKind::ge;
  if (op == "!=") return ExprKind::ne;
  return ExprKind::eq;  // "=" and "=="
}

ExprKind operator_kind(const SyntaxNode& op, std::string_view text) {
  if (op.is<g::op_iff>()) return ExprKind::iff;
  if (op.is<g::op_implies>()) return ExprKind::implies;
  if (op.is<g::op_xor>()) return ExprKind::logical_xor;
  if (op.is<g::op_or>()) return ExprKind::logical_or;
  if (op.is<g::op_and>()) return ExprKind::logical_and;
  if (op.is<g::op_add>()) return ExprKind::add;
  if (op.is<g::op_sub>()) return ExprKind::sub;
  if (op.is<g::op_mul>()) return ExprKind::mul;
  if (op.is<g::op_div>()) return ExprKind::div;
  if (op.is<g::op_mod>()) return ExprKind::mod;
  return relation_kind(op.text(text));
}

std::string unescape_quoted(std::string_view quoted) {
  std::string out;
  const std::string_view inner = quoted.substr(1, quoted.size() >= 2 ? quoted.size() - 2 : 0);
  for (std::size_t i = 0; i < inner.size(); ++i) {
    if (inner[i] == '\\' && i + 1 < inner.size() && (inner[i + 1] == '"' || inner[i + 1] == '\\'))
      ++i;
    out += inner[i];
  }
  return out;
}

// Marks every `if … then …` under `n`: FRET rewrites the text `if A then B` to `A => B` before
// formalizing it, so `then` is an implication at the level of `->`, looser than `&` and `|`.
// `if` becomes spaces and `then` becomes `=>` padded to its length, keeping every offset.
void blank_if_then(const SyntaxNode& n, std::string& text) {
  if (n.is<g::if_then>() && n.children.size() == 2) {
    text.replace(n.begin, 2, "  ");
    std::size_t then = n.children[0]->end;
    while (then < text.size() && std::isspace(static_cast<unsigned char>(text[then]))) ++then;
    if (then + 4 <= text.size()) text.replace(then, 4, "=>  ");
  }
  for (const auto& child : n.children) blank_if_then(*child, text);
}

bool has_if_then(const SyntaxNode& n) {
  if (n.is<g::if_then>()) return true;
  for (const auto& child : n.children)
    if (has_if_then(*child)) return true;
  return false;
}

}  // namespace

ExprPtr ExpressionBuilder::build(const SyntaxNode& node) {
  try {
    if (has_if_then(node)) {
      std::string spelled(text_.substr(0, node.end));
      blank_if_then(node, spelled);
      // Parse the rewritten span alone: what stands before it becomes spaces.
      std::fill(spelled.begin(), spelled.begin() + static_cast<std::ptrdiff_t>(node.begin), ' ');
      ParseOutcome outcome = run_parse<g::expression_span>(spelled);
      if (outcome.ok && outcome.root && outcome.root->children.size() == 1) {
        ExpressionBuilder rewritten(spelled, map_, findings_);
        return rewritten.visit(*outcome.root->children.front()).expr;
      }
    }
    return visit(node).expr;
  } catch (const Refusal& e) {
    findings_.push_back(make_finding("fretish-syntax", e.message, map_.location(e.offset)));
    return nullptr;
  }
}

std::string ExpressionBuilder::name_of(const SyntaxNode& node) const {
  if (node.is<g::plain_identifier>()) return std::string(node.text(text_));
  if (node.is<g::quoted_identifier>()) return unescape_quoted(node.text(text_));
  if (!node.children.empty()) return name_of(*node.children.front());
  return std::string(node.text(text_));
}

ExpressionBuilder::Built ExpressionBuilder::make(ExprKind kind, std::vector<Built> args,
                                                 std::size_t begin, std::size_t end) {
  int depth = 0;
  std::vector<ExprPtr> operands;
  operands.reserve(args.size());
  for (auto& a : args) {
    depth = std::max(depth, a.depth);
    operands.push_back(std::move(a.expr));
  }
  if (depth + 1 > kMaxExprDepth)
    throw Refusal{begin,
                  "expression nested deeper than " + std::to_string(kMaxExprDepth) + " operators"};
  return {make_expr(kind, std::move(operands), map_.range(begin, end)), depth + 1};
}

ExpressionBuilder::Built ExpressionBuilder::visit(const SyntaxNode& n) {
  const SourceRange range = map_.range(n.begin, n.end);
  if (n.is<g::equivalence>() || n.is<g::exclusive>() || n.is<g::additive>() ||
      n.is<g::multiplicative>())
    return left_fold(n);
  if (n.is<g::implication>()) return right_fold(n);
  if (n.is<g::disjunction>()) return flat(n, ExprKind::logical_or);
  if (n.is<g::conjunction>()) return flat(n, ExprKind::logical_and);
  if (n.is<g::negation>()) return negation(n);
  if (n.is<g::relation>()) return relation(n);
  if (n.is<g::power_chain>()) return power_chain(n);
  if (n.is<g::paren_expression>()) return parenthesized(n);
  if (n.is<g::call>()) return call(n);
  if (n.is<g::occurrence>()) return occurrence(n);
  if (n.is<g::if_then>() && n.children.size() == 2) {
    std::vector<Built> args;
    args.push_back(visit(*n.children[0]));
    args.push_back(visit(*n.children[1]));
    return make(ExprKind::implies, std::move(args), n.begin, n.end);
  }
  if (n.is<g::number>()) {
    std::string literal(n.text(text_));
    if (std::string why = number_misfit(literal, /*exact_integers=*/true); !why.empty())
      throw Refusal{n.begin, why};
    return {make_number(std::move(literal), range)};
  }
  if (n.is<g::negative_number>() && n.children.size() == 1) {
    // FRET's NUMBER carries its sign: -1 ^ 2 is (-1) ^ 2.
    std::vector<Built> args;
    args.push_back(visit(*n.children[0]));
    return make(ExprKind::negate, std::move(args), n.begin, n.end);
  }
  if (n.is<g::bool_true>() || n.is<g::bool_false>()) {
    const bool value = n.is<g::bool_true>();
    const std::string spelled(n.text(text_));
    if (spelled != lower_case(spelled))
      warn_not_fret(n.begin, "FRET reads only lower-case '" + lower_case(spelled) +
                                 "' inside an expression: write '" + lower_case(spelled) + "'");
    return {make_bool(value, range)};
  }
  if (n.is<g::plain_identifier>() || n.is<g::quoted_identifier>())
    return {make_identifier(name_of(n), range)};
  // A wrapper the grammar adds around one expression node.
  if (n.children.size() == 1) return visit(*n.children.front());
  return {make_identifier(std::string(n.text(text_)), range)};
}

void ExpressionBuilder::warn_not_fret(std::size_t offset, const std::string& message) {
  findings_.push_back(make_finding("fretish-not-fret", message, map_.location(offset)));
}

void ExpressionBuilder::check_operator(const SyntaxNode& op) {
  const std::string_view spelled = op.text(text_);
  if (op.is<g::op_relation>() && spelled == "==")
    warn_not_fret(op.begin, "FRET has no '==': write '=' so that FRET can load the requirement");
  // FRET's NUMBER takes a leading '-', so it reads `x-1` as `x` followed by `-1` and fails.
  if (op.is<g::op_sub>() && op.end < text_.size() &&
      std::isdigit(static_cast<unsigned char>(text_[op.end])))
    warn_not_fret(op.begin,
                  "FRET reads a '-' written against a number as its sign and cannot parse this "
                  "subtraction: write a space after '-'");
}

void ExpressionBuilder::warn_mixed(const SyntaxNode& op, const char* inner_spelled_as) {
  const std::string outer = lower_case(op.text(text_));
  findings_.push_back(make_finding(
      "fretish-precedence",
      "'" + outer + "' and '" + inner_spelled_as + "' mixed without parentheses: uabt reads '" +
          inner_spelled_as +
          "' as binding tighter (FRET's formalization), but FRET's requirement grammar groups "
          "them left to right; add parentheses",
      map_.location(op.begin)));
}

ExpressionBuilder::Built ExpressionBuilder::left_fold(const SyntaxNode& n) {
  const auto& c = n.children;
  if (c.size() == 1) return visit(*c[0]);
  // `a xor b | c` and `a <-> b -> c`: FRET's two grammars group these differently.
  const bool check_xor = n.is<g::exclusive>();
  const bool check_iff = n.is<g::equivalence>();
  if (check_xor || check_iff) {
    for (std::size_t i = 0; i < c.size(); i += 2) {
      const SyntaxNode& operand = *c[i];
      const bool mixed =
          (check_xor && operand.is<g::disjunction>() && operand.children.size() > 1) ||
          (check_iff && operand.is<g::implication>() && operand.children.size() > 1);
      if (!mixed) continue;
      const SyntaxNode& outer_op = i > 0 ? *c[i - 1] : *c[i + 1];
      const std::string inner = std::string(operand.children[1]->text(text_));
      warn_mixed(outer_op, inner.c_str());
      break;
    }
  }
  Built acc = visit(*c[0]);
  for (std::size_t i = 1; i + 1 < c.size(); i += 2) {
    std::vector<Built> args;
    args.push_back(std::move(acc));
    args.push_back(visit(*c[i + 1]));
    check_operator(*c[i]);
    acc = make(operator_kind(*c[i], text_), std::move(args), c[0]->begin, c[i + 1]->end);
  }
  return acc;
}

ExpressionBuilder::Built ExpressionBuilder::right_fold(const SyntaxNode& n) {
  const auto& c = n.children;
  std::size_t last = c.size() - 1;
  Built acc = visit(*c[last]);
  while (last >= 2) {
    std::vector<Built> args;
    args.push_back(visit(*c[last - 2]));
    args.push_back(std::move(acc));
    acc = make(operator_kind(*c[last - 1], text_), std::move(args), c[last - 2]->begin, n.end);
    last -= 2;
  }
  return acc;
}

ExpressionBuilder::Built ExpressionBuilder::flat(const SyntaxNode& n, ExprKind kind) {
  if (n.children.size() == 1) return visit(*n.children[0]);
  std::vector<Built> args;
  for (std::size_t i = 0; i < n.children.size(); i += 2) args.push_back(visit(*n.children[i]));
  return make(kind, std::move(args), n.begin, n.end);
}

ExpressionBuilder::Built ExpressionBuilder::negation(const SyntaxNode& n) {
  const auto& c = n.children;
  Built acc = visit(*c.back());
  for (std::size_t i = c.size() - 1; i-- > 0;) {
    std::vector<Built> args;
    args.push_back(std::move(acc));
    acc = make(ExprKind::logical_not, std::move(args), c[i]->begin, n.end);
  }
  return acc;
}

ExpressionBuilder::Built ExpressionBuilder::relation(const SyntaxNode& n) {
  const auto& c = n.children;
  if (c.size() != 3) return visit(*c[0]);
  std::vector<Built> args;
  args.push_back(visit(*c[0]));
  args.push_back(visit(*c[2]));
  check_operator(*c[1]);
  return make(relation_kind(c[1]->text(text_)), std::move(args), n.begin, n.end);
}

ExpressionBuilder::Built ExpressionBuilder::power_chain(const SyntaxNode& n) {
  // Segments "-…- operand" joined by '^'; each segment's signs negate the rest of the chain.
  struct Segment {
    std::vector<const SyntaxNode*> signs;
    const SyntaxNode* operand = nullptr;
  };
  std::vector<Segment> segments(1);
  for (const auto& child : n.children) {
    if (child->is<g::op_negate>()) {
      segments.back().signs.push_back(child.get());
    } else {
      segments.back().operand = child.get();
      segments.emplace_back();
    }
  }
  segments.pop_back();
  Built acc;
  for (std::size_t i = segments.size(); i-- > 0;) {
    const Segment& s = segments[i];
    Built operand = visit(*s.operand);
    if (i + 1 == segments.size()) {
      acc = std::move(operand);
    } else {
      std::vector<Built> args;
      args.push_back(std::move(operand));
      args.push_back(std::move(acc));
      acc = make(ExprKind::pow, std::move(args), s.operand->begin, n.end);
    }
    for (std::size_t k = s.signs.size(); k-- > 0;) {
      std::vector<Built> args;
      args.push_back(std::move(acc));
      acc = make(ExprKind::negate, std::move(args), s.signs[k]->begin, n.end);
    }
  }
  return acc;
}

ExpressionBuilder::Built ExpressionBuilder::parenthesized(const SyntaxNode& n) {
  Built inner = visit(*n.children.front());
  auto copy = std::make_shared<Expr>(*inner.expr);
  copy->parenthesized = true;
  copy->range = map_.range(n.begin, n.end);
  return {std::move(copy), inner.depth};
}

ExpressionBuilder::Built ExpressionBuilder::call(const SyntaxNode& n) {
  std::vector<Built> args;
  std::string name;
  for (const auto& child : n.children) {
    if (child->is<g::function_name>())
      name = name_of(*child);
    else
      args.push_back(visit(*child));
  }
  Built b = make(ExprKind::call, std::move(args), n.begin, n.end);
  std::const_pointer_cast<Expr>(b.expr)->text = std::move(name);
  return b;
}

ExpressionBuilder::Built ExpressionBuilder::occurrence(const SyntaxNode& n) {
  // "at the previous|next occurrence of P, Q" is FRET's prevOcc(P, Q) / nextOcc(P, Q).
  std::vector<Built> args;
  std::string name = "nextOcc";
  for (const auto& child : n.children) {
    if (child->is<g::occurrence_direction>())
      name = lower_case(child->text(text_)) == "previous" ? "prevOcc" : "nextOcc";
    else
      args.push_back(visit(*child));
  }
  Built b = make(ExprKind::call, std::move(args), n.begin, n.end);
  std::const_pointer_cast<Expr>(b.expr)->text = std::move(name);
  return b;
}

}  // namespace uabt::fretish::detail
