#include "fretish/requirement.hpp"

#include "base/text.hpp"

namespace uabt::fretish {

namespace {

SourceRange span(const SourceRange& a, const SourceRange& b) {
  return {a.begin_line, a.begin_column, b.end_line, b.end_column};
}

}  // namespace

ExprPtr Requirement::folded_condition() const {
  ExprPtr guard;
  bool guard_is_fold = false;  // `guard` was made here (so it may absorb the next operand)
  SourceRange first_range;
  for (const Condition& c : conditions) {
    if (!c.expr) continue;
    // unless C and "C is false" negate; "unless C is false" negates twice.
    const bool negate = (c.qualifier == "unless") != c.is_false_suffix;
    ExprPtr term = negate ? make_expr(ExprKind::logical_not, {c.expr}, c.range) : c.expr;
    if (!guard) {
      guard = term;
      first_range = c.range;
      continue;
    }
    const ExprKind kind = c.connective == "or" ? ExprKind::logical_or : ExprKind::logical_and;
    std::vector<ExprPtr> args;
    if (guard_is_fold && guard->kind == kind) {
      args = guard->args;
    } else {
      args.push_back(guard);
    }
    args.push_back(term);
    guard = make_expr(kind, std::move(args), span(first_range, c.range));
    guard_is_fold = true;
  }
  return guard;
}

bool is_assumption(const Requirement& r) {
  return lower_case(r.component) == "environment";
}

}  // namespace uabt::fretish
