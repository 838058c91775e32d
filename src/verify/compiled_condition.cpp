#include "verify/compiled_condition.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "smt/evaluate.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;
using smt::Sort;

enum class CompiledCondition::Op : std::uint8_t {
  push_int,
  push_real,
  load,
  to_real,
  logical_not,
  logical_and,
  logical_or,
  logical_xor,
  iff,
  implies,
  eq_i,
  ne_i,
  lt_i,
  le_i,
  gt_i,
  ge_i,
  eq_r,
  ne_r,
  lt_r,
  le_r,
  gt_r,
  ge_r,
  neg_i,
  add_i,
  sub_i,
  mul_i,
  div_i,
  mod_i,
  pow_i,
  abs_i,
  min_i,
  max_i,
  neg_r,
  add_r,
  sub_r,
  mul_r,
  div_r,
  pow_r,
  abs_r,
  min_r,
  max_r,
  ite,
};

namespace {

using Op = CompiledCondition::Op;

Op relation(ExprKind k, bool real) {
  const int base = static_cast<int>(real ? Op::eq_r : Op::eq_i);
  return static_cast<Op>(base + static_cast<int>(k) - static_cast<int>(ExprKind::eq));
}

}  // namespace

CompiledCondition::CompiledCondition(const Expr& condition, const smt::Typing& typing,
                                     const std::map<std::string, std::size_t>& slot_of) {
  compile(condition, typing, slot_of, false);
  // Depth of the value stack the program needs.
  std::size_t depth = 0;
  for (const auto& in : program_) {
    depth = depth + 1 - in.arity;
    max_depth_ = std::max(max_depth_, depth);
  }
  stack_.resize(max_depth_ + 1);
}

void CompiledCondition::emit(Op op, std::uint32_t arity, std::int64_t integer, double real) {
  program_.push_back(Instruction{op, arity, integer, real});
}

void CompiledCondition::compile(const Expr& e, const smt::Typing& typing,
                                const std::map<std::string, std::size_t>& slot_of, bool want_real) {
  const smt::TypeInfo& t = typing.at(e);
  const auto arity = static_cast<std::uint32_t>(e.args.size());
  const bool real = t.sort == Sort::real;
  auto operands = [&](bool as_real) {
    for (const auto& arg : e.args) compile(*arg, typing, slot_of, as_real);
  };
  switch (e.kind) {
    case ExprKind::bool_literal: emit(Op::push_int, 0, e.bool_value ? 1 : 0); break;
    case ExprKind::number:
      if (real) {
        emit(Op::push_real, 0, 0, std::strtod(e.text.c_str(), nullptr));
      } else {
        errno = 0;
        const long long v = std::strtoll(e.text.c_str(), nullptr, 10);
        if (errno == ERANGE) throw smt::EvaluationError("integer literal out of range");
        emit(Op::push_int, 0, v);
      }
      break;
    case ExprKind::identifier:
      if (t.enum_index >= 0) {
        emit(Op::push_int, 0, t.enum_index);
      } else {
        const auto it = slot_of.find(e.text);
        if (it == slot_of.end() || real)
          throw smt::EvaluationError("'" + e.text + "' is outside the enumerated space");
        emit(Op::load, 0, static_cast<std::int64_t>(it->second));
      }
      break;
    case ExprKind::logical_not:
      operands(false);
      emit(Op::logical_not, 1);
      break;
    case ExprKind::logical_and:
      operands(false);
      emit(Op::logical_and, arity);
      break;
    case ExprKind::logical_or:
      operands(false);
      emit(Op::logical_or, arity);
      break;
    case ExprKind::logical_xor:
      operands(false);
      emit(Op::logical_xor, arity);
      break;
    case ExprKind::iff:
      operands(false);
      emit(Op::iff, arity);
      break;
    case ExprKind::implies:
      operands(false);
      emit(Op::implies, arity);
      break;
    case ExprKind::eq:
    case ExprKind::ne:
    case ExprKind::lt:
    case ExprKind::le:
    case ExprKind::gt:
    case ExprKind::ge: {
      const bool compare_real =
          typing.at(*e.args[0]).sort == Sort::real || typing.at(*e.args[1]).sort == Sort::real;
      operands(compare_real);
      emit(relation(e.kind, compare_real), 2);
      break;
    }
    case ExprKind::negate:
      operands(real);
      emit(real ? Op::neg_r : Op::neg_i, 1);
      break;
    case ExprKind::add:
      operands(real);
      emit(real ? Op::add_r : Op::add_i, arity);
      break;
    case ExprKind::sub:
      operands(real);
      emit(real ? Op::sub_r : Op::sub_i, arity);
      break;
    case ExprKind::mul:
      operands(real);
      emit(real ? Op::mul_r : Op::mul_i, arity);
      break;
    case ExprKind::div:
      operands(real);
      emit(real ? Op::div_r : Op::div_i, 2);
      break;
    case ExprKind::mod:
      operands(false);
      emit(Op::mod_i, 2);
      break;
    case ExprKind::pow:
      operands(real);
      emit(real ? Op::pow_r : Op::pow_i, 2);
      break;
    case ExprKind::call:
      if (e.text == "ite") {
        compile(*e.args[0], typing, slot_of, false);
        compile(*e.args[1], typing, slot_of, real);
        compile(*e.args[2], typing, slot_of, real);
        emit(Op::ite, 3);
      } else {
        operands(real);
        const bool is_abs = arity == 1, is_min = e.text.starts_with("min");
        emit(is_abs   ? (real ? Op::abs_r : Op::abs_i)
             : is_min ? (real ? Op::min_r : Op::min_i)
                      : (real ? Op::max_r : Op::max_i),
             arity);
      }
      break;
  }
  if (want_real && !real) emit(Op::to_real, 1);
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
    Val* args = stack + top - in.arity;
    Val out;
    bool none = false;
    for (std::uint32_t k = 0; k < in.arity; ++k) none = none || args[k].none;
    switch (in.op) {
      case Op::push_int: out.i = in.integer; break;
      case Op::push_real: out.r = in.real; break;
      case Op::load: out.i = assignment[in.integer]; break;
      case Op::to_real: out.r = static_cast<double>(args[0].i); break;
      case Op::logical_not: out.i = !args[0].i; break;
      case Op::logical_and:
      case Op::logical_or: {
        // A definite false (and) or true (or) decides, whatever has no value.
        const std::int64_t decisive = in.op == Op::logical_and ? 0 : 1;
        bool decided = false;
        for (std::uint32_t k = 0; k < in.arity; ++k)
          decided = decided || (!args[k].none && args[k].i == decisive);
        out.i = decided ? decisive : 1 - decisive;
        none = !decided && none;
        break;
      }
      case Op::logical_xor:
      case Op::iff: {
        std::int64_t acc = args[0].i;
        for (std::uint32_t k = 1; k < in.arity; ++k)
          acc = in.op == Op::logical_xor ? (acc != args[k].i) : (acc == args[k].i);
        out.i = acc;
        break;
      }
      case Op::implies: {  // right fold: a -> (b -> c)
        std::int64_t acc = args[in.arity - 1].i;
        bool acc_none = args[in.arity - 1].none;
        for (std::uint32_t k = in.arity - 1; k-- > 0;) {
          const bool premise_false = !args[k].none && args[k].i == 0;
          const bool conclusion_true = !acc_none && acc == 1;
          acc_none = !(premise_false || conclusion_true) && (args[k].none || acc_none);
          acc = premise_false || conclusion_true ? 1 : 0;
        }
        out.i = acc;
        none = acc_none;
        break;
      }
      case Op::eq_i: out.i = args[0].i == args[1].i; break;
      case Op::ne_i: out.i = args[0].i != args[1].i; break;
      case Op::lt_i: out.i = args[0].i < args[1].i; break;
      case Op::le_i: out.i = args[0].i <= args[1].i; break;
      case Op::gt_i: out.i = args[0].i > args[1].i; break;
      case Op::ge_i: out.i = args[0].i >= args[1].i; break;
      case Op::eq_r: out.i = args[0].r == args[1].r; break;
      case Op::ne_r: out.i = args[0].r != args[1].r; break;
      case Op::lt_r: out.i = args[0].r < args[1].r; break;
      case Op::le_r: out.i = args[0].r <= args[1].r; break;
      case Op::gt_r: out.i = args[0].r > args[1].r; break;
      case Op::ge_r: out.i = args[0].r >= args[1].r; break;
      case Op::neg_i:
        none = none || __builtin_sub_overflow(std::int64_t{0}, args[0].i, &out.i);
        break;
      case Op::add_i:
      case Op::sub_i:
      case Op::mul_i: {
        std::int64_t acc = args[0].i;
        for (std::uint32_t k = 1; k < in.arity; ++k) {
          const std::int64_t y = args[k].i;
          none = none || (in.op == Op::add_i   ? __builtin_add_overflow(acc, y, &acc)
                          : in.op == Op::sub_i ? __builtin_sub_overflow(acc, y, &acc)
                                               : __builtin_mul_overflow(acc, y, &acc));
        }
        out.i = acc;
        break;
      }
      case Op::div_i:
      case Op::mod_i: {
        const std::int64_t x = args[0].i, y = args[1].i;
        if (y == 0 || (x == INT64_MIN && y == -1)) {
          none = true;
          break;
        }
        // Truncated toward zero, as FRET's targets (and smt::evaluate) divide integers.
        const std::int64_t q = x / y;
        out.i = in.op == Op::div_i ? q : x - y * q;
        break;
      }
      case Op::pow_i: {
        std::int64_t acc = 1;
        for (std::int64_t k = 0; k < args[1].i && !none; ++k)
          none = __builtin_mul_overflow(acc, args[0].i, &acc);
        out.i = acc;
        break;
      }
      case Op::abs_i:
        if (args[0].i < 0)
          none = none || __builtin_sub_overflow(std::int64_t{0}, args[0].i, &out.i);
        else
          out.i = args[0].i;
        break;
      case Op::min_i: out.i = std::min(args[0].i, args[1].i); break;
      case Op::max_i: out.i = std::max(args[0].i, args[1].i); break;
      case Op::neg_r: out.r = -args[0].r; break;
      case Op::add_r:
      case Op::sub_r:
      case Op::mul_r: {
        double acc = args[0].r;
        for (std::uint32_t k = 1; k < in.arity; ++k)
          acc = in.op == Op::add_r   ? acc + args[k].r
                : in.op == Op::sub_r ? acc - args[k].r
                                     : acc * args[k].r;
        out.r = acc;
        break;
      }
      case Op::div_r:
        if (args[1].r == 0.0)
          none = true;
        else
          out.r = args[0].r / args[1].r;
        break;
      case Op::pow_r: out.r = std::pow(args[0].r, args[1].r); break;
      case Op::abs_r: out.r = std::fabs(args[0].r); break;
      case Op::min_r: out.r = std::min(args[0].r, args[1].r); break;
      case Op::max_r: out.r = std::max(args[0].r, args[1].r); break;
      case Op::ite:
        if (args[0].none) {
          none = true;
        } else {
          out = args[0].i ? args[1] : args[2];
          none = out.none;
        }
        break;
    }
    out.none = none;
    top -= in.arity;
    stack[top++] = out;
  }
  if (stack[0].none) return std::nullopt;
  return stack[0].i != 0;
}

}  // namespace uabt::verify::detail
