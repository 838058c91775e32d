#include "compile/guard_rewrite.hpp"

namespace uabt::compile {

using fretish::Expr;
using fretish::ExprKind;
using fretish::ExprPtr;
using fretish::make_expr;

bool is_boolean_valued(const Expr& e, const fretish::Domain& domain) {
  if (fretish::is_boolean_connective(e.kind) || fretish::is_relation(e.kind)) return true;
  if (e.kind == ExprKind::bool_literal) return true;
  if (e.kind == ExprKind::identifier) {
    const fretish::Variable* v = domain.find(e.text);
    if (v != nullptr) return v->type == fretish::VarType::boolean;
    return domain.enum_owning(e.text) == nullptr;  // undeclared: a condition
  }
  return false;
}

bool is_real_valued(const Expr& e, const fretish::Domain& domain) {
  switch (e.kind) {
    case ExprKind::number: return e.text.find_first_of(".eE") != std::string::npos;
    case ExprKind::identifier: {
      const fretish::Variable* v = domain.find(e.text);
      return v != nullptr && v->type == fretish::VarType::real;
    }
    case ExprKind::negate:
    case ExprKind::add:
    case ExprKind::sub:
    case ExprKind::mul:
    case ExprKind::div:
      for (const auto& a : e.args)
        if (is_real_valued(*a, domain)) return true;
      return false;
    default: return false;
  }
}

namespace {

ExprPtr negation(ExprPtr e) {
  const SourceRange range = e->range;
  return make_expr(ExprKind::logical_not, {std::move(e)}, range);
}
ExprPtr conj(ExprPtr a, ExprPtr b) {
  return make_expr(ExprKind::logical_and, {std::move(a), std::move(b)});
}
ExprPtr disj(ExprPtr a, ExprPtr b) {
  return make_expr(ExprKind::logical_or, {std::move(a), std::move(b)});
}

ExprPtr iff_of(const ExprPtr& a, const ExprPtr& b) {
  return disj(conj(a, b), conj(negation(a), negation(b)));
}
ExprPtr xor_of(const ExprPtr& a, const ExprPtr& b) {
  return disj(conj(a, negation(b)), conj(negation(a), b));
}

}  // namespace

ExprPtr to_and_or_not(const Expr& e, const fretish::Domain& domain) {
  auto rewrite_args = [&]() {
    std::vector<ExprPtr> args;
    for (const auto& a : e.args) args.push_back(to_and_or_not(*a, domain));
    return args;
  };
  switch (e.kind) {
    case ExprKind::logical_not:
    case ExprKind::logical_and:
    case ExprKind::logical_or: return make_expr(e.kind, rewrite_args(), e.range);
    case ExprKind::implies: {
      // Right-associative chains arrive as nested binary nodes.
      auto args = rewrite_args();
      ExprPtr result = args.back();
      for (std::size_t i = args.size() - 1; i-- > 0;) result = disj(negation(args[i]), result);
      return result;
    }
    case ExprKind::iff:
    case ExprKind::logical_xor: {
      auto args = rewrite_args();
      ExprPtr result = args.front();
      for (std::size_t i = 1; i < args.size(); ++i)
        result = e.kind == ExprKind::iff ? iff_of(result, args[i]) : xor_of(result, args[i]);
      return result;
    }
    case ExprKind::eq:
    case ExprKind::ne: {
      const Expr& lhs = *e.args.at(0);
      const Expr& rhs = *e.args.at(1);
      if (is_real_valued(lhs, domain) || is_real_valued(rhs, domain)) {
        auto relation = [&](ExprKind kind) {
          return make_expr(kind, {std::make_shared<Expr>(lhs), std::make_shared<Expr>(rhs)},
                           e.range);
        };
        return e.kind == ExprKind::eq ? conj(relation(ExprKind::ge), relation(ExprKind::le))
                                      : disj(relation(ExprKind::lt), relation(ExprKind::gt));
      }
      if (!is_boolean_valued(lhs, domain) || !is_boolean_valued(rhs, domain)) break;
      ExprPtr a = to_and_or_not(lhs, domain);
      ExprPtr b = to_and_or_not(rhs, domain);
      const bool equal = e.kind == ExprKind::eq;
      // X = true is X; X = false is !X; otherwise an equivalence.
      if (b->kind == ExprKind::bool_literal) return b->bool_value == equal ? a : negation(a);
      if (a->kind == ExprKind::bool_literal) return a->bool_value == equal ? b : negation(b);
      return equal ? iff_of(a, b) : xor_of(a, b);
    }
    default: break;
  }
  // Atoms (identifiers, literals, relations over numbers or enums) are kept as they are.
  auto copy = std::make_shared<Expr>(e);
  return copy;
}

}  // namespace uabt::compile
