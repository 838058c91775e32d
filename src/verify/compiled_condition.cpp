#include "verify/compiled_condition.hpp"

#include <algorithm>

#include "smt/evaluate.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;
using fretish::Val;
using smt::Sort;

CompiledCondition::CompiledCondition(const Expr& condition, const smt::Typing& typing,
                                     const std::map<std::string, std::size_t>& slot_of) {
  compile(condition, typing, slot_of);
  std::size_t depth = 0, max_depth = 0;  // of the value stack the program needs
  for (const auto& in : program_) {
    depth = depth + 1 - in.arity;
    max_depth = std::max(max_depth, depth);
  }
  stack_.resize(max_depth + 1);
}

void CompiledCondition::compile(const Expr& e, const smt::Typing& typing,
                                const std::map<std::string, std::size_t>& slot_of) {
  Instruction in;
  switch (e.kind) {
    case ExprKind::bool_literal: in.constant = Val::of_bool(e.bool_value); break;
    case ExprKind::number: in.constant = fretish::number_literal(e.text); break;
    case ExprKind::identifier: {
      const smt::TypeInfo& t = typing.at(e);
      if (t.enum_index >= 0) {
        in.constant = Val::of_symbol(t.enum_index);
        break;
      }
      const auto it = slot_of.find(e.text);
      if (it == slot_of.end() || t.sort == Sort::real)
        throw smt::EvaluationError("'" + e.text + "' is outside the enumerated space");
      in.slot = it->second;
      in.load = t.sort == Sort::boolean   ? Load::boolean
                : t.sort == Sort::integer ? Load::integer
                                          : Load::symbol;
      break;
    }
    default:
      for (const auto& arg : e.args) compile(*arg, typing, slot_of);
      in.load = Load::apply;
      in.op = fretish::operator_of(e);
      in.arity = static_cast<std::uint32_t>(e.args.size());
      break;
  }
  program_.push_back(in);
}

bool CompiledCondition::holds(const std::int64_t* assignment) const {
  const auto v = value(assignment);
  if (!v) throw smt::EvaluationError("division by zero or overflow");
  return *v;
}

std::optional<bool> CompiledCondition::value(const std::int64_t* assignment) const {
  Val* stack = stack_.data();
  std::size_t top = 0;  // number of values on the stack
  for (const Instruction& in : program_) {
    switch (in.load) {
      case Load::constant: stack[top++] = in.constant; break;
      case Load::boolean: stack[top++] = Val::of_bool(assignment[in.slot] != 0); break;
      case Load::integer: stack[top++] = Val::of_whole(assignment[in.slot]); break;
      case Load::symbol:
        stack[top++] = Val::of_symbol(static_cast<int>(assignment[in.slot]));
        break;
      case Load::apply: {
        top -= in.arity;
        stack[top] = fretish::apply(in.op, stack + top, in.arity);
        ++top;
        break;
      }
    }
  }
  if (!stack[0].known() || stack[0].kind != Val::Kind::boolean) return std::nullopt;
  return stack[0].truth();
}

}  // namespace uabt::verify::detail
