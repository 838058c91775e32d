#include "smt/atoms.hpp"

namespace uabt::smt {

using fretish::Expr;
using fretish::ExprKind;

bool is_boolean_structure(const Expr& e, const Typing& typing) {
  switch (e.kind) {
    case ExprKind::logical_not:
    case ExprKind::logical_and:
    case ExprKind::logical_or:
    case ExprKind::logical_xor:
    case ExprKind::implies:
    case ExprKind::iff: return true;
    case ExprKind::eq:
    case ExprKind::ne: {
      const TypeInfo* t = e.args.empty() ? nullptr : typing.find(*e.args[0]);
      return t != nullptr && t->sort == Sort::boolean;
    }
    default: return false;
  }
}

namespace {

void collect(const Expr& e, const Typing& typing, std::vector<const Expr*>& out) {
  if (is_boolean_structure(e, typing)) {
    for (const auto& arg : e.args) collect(*arg, typing, out);
    return;
  }
  if (e.kind == ExprKind::bool_literal) return;
  out.push_back(&e);
}

}  // namespace

std::vector<const Expr*> atom_occurrences(const Expr& condition, const Typing& typing) {
  std::vector<const Expr*> out;
  collect(condition, typing, out);
  return out;
}

}  // namespace uabt::smt
