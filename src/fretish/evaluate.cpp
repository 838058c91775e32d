#include "fretish/evaluate.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace uabt::fretish {

namespace {

using Kind = Val::Kind;
using Fault = Val::Fault;

// The first absent operand's fault, if any.
const Val* first_absent(const Val* args, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k)
    if (!args[k].known()) return &args[k];
  return nullptr;
}

Fault fault_of(const Val& v) {
  return v.fault == Fault::none ? Fault::unset : v.fault;
}

bool all_kind(const Val* args, std::size_t n, Kind kind) {
  for (std::size_t k = 0; k < n; ++k)
    if (args[k].kind != kind) return false;
  return true;
}

Val real(double x) {
  return std::isfinite(x) ? Val::of_number(x) : Val::none(Fault::not_finite, Kind::number);
}

// &, |: a definite `decisive` operand decides, whatever else has no value.
Val junction(const Val* args, std::size_t n, bool decisive) {
  const Val* absent = nullptr;
  for (std::size_t k = 0; k < n; ++k) {
    if (!args[k].known()) {
      if (absent == nullptr) absent = &args[k];
      continue;
    }
    if (args[k].kind != Kind::boolean) return Val::none(Fault::type, Kind::boolean);
    if (args[k].truth() == decisive) return Val::of_bool(decisive);
  }
  if (absent != nullptr) return Val::none(fault_of(*absent), Kind::boolean);
  return Val::of_bool(!decisive);
}

// a => b: a false premise or a true conclusion decides.
Val implication(const Val& a, const Val& b) {
  if ((a.known() && a.kind != Kind::boolean) || (b.known() && b.kind != Kind::boolean))
    return Val::none(Fault::type, Kind::boolean);
  if ((a.known() && !a.truth()) || (b.known() && b.truth())) return Val::of_bool(true);
  if (!a.known()) return Val::none(fault_of(a), Kind::boolean);
  if (!b.known()) return Val::none(fault_of(b), Kind::boolean);
  return Val::of_bool(false);
}

Val integer_arithmetic(Op op, std::int64_t a, std::int64_t b) {
  std::int64_t out = 0;
  bool overflow = false;
  switch (op) {
    case Op::add: overflow = __builtin_add_overflow(a, b, &out); break;
    case Op::sub: overflow = __builtin_sub_overflow(a, b, &out); break;
    case Op::mul: overflow = __builtin_mul_overflow(a, b, &out); break;
    case Op::div:
    case Op::mod:
      if (b == 0) return Val::none(Fault::division_by_zero, Kind::number, true);
      if (a == INT64_MIN && b == -1) {
        if (op == Op::mod) return Val::of_whole(0);
        overflow = true;
        break;
      }
      out = op == Op::div ? a / b : a % b;  // C++ truncates toward zero, as FRET's targets
      break;
    case Op::pow_whole: {
      // Exponent b >= 0 (written as a whole number): by squaring, no value past 64 bits.
      std::int64_t acc = 1, base = a;
      for (std::int64_t e = b; e > 0 && !overflow; e >>= 1) {
        if (e & 1) overflow = __builtin_mul_overflow(acc, base, &acc);
        if (e > 1 && !overflow) overflow = __builtin_mul_overflow(base, base, &base);
      }
      out = acc;
      break;
    }
    case Op::min_int:
    case Op::min_real: out = a < b ? a : b; break;
    default: out = a > b ? a : b; break;
  }
  if (overflow) return Val::none(Fault::overflow, Kind::number, true);
  return Val::of_whole(out);
}

Val real_arithmetic(Op op, double a, double b) {
  switch (op) {
    case Op::add: return real(a + b);
    case Op::sub: return real(a - b);
    case Op::mul: return real(a * b);
    case Op::div:
      if (b == 0.0) return Val::none(Fault::division_by_zero, Kind::number);
      return real(a / b);
    case Op::mod: return Val::none(Fault::type, Kind::number);  // mod needs integers
    case Op::pow:
    case Op::pow_whole: return real(std::pow(a, b));
    case Op::min_int:
    case Op::min_real: return real(std::fmin(a, b));
    default: return real(std::fmax(a, b));
  }
}

Val relation(Op op, const Val& a, const Val& b) {
  if (op == Op::eq || op == Op::ne) {
    bool same = false;
    if (a.kind == Kind::number && b.kind == Kind::number)
      same = a.integer && b.integer ? a.whole == b.whole : a.number == b.number;
    else if (a.kind == b.kind && a.kind == Kind::boolean)
      same = a.whole == b.whole;
    else if (a.kind == b.kind && a.kind == Kind::symbol)
      same = a.symbol == b.symbol;
    else
      return Val::none(Fault::type, Kind::boolean);
    return Val::of_bool(op == Op::eq ? same : !same);
  }
  if (a.kind != Kind::number || b.kind != Kind::number)
    return Val::none(Fault::type, Kind::boolean);
  if (a.integer && b.integer) {
    switch (op) {
      case Op::lt: return Val::of_bool(a.whole < b.whole);
      case Op::le: return Val::of_bool(a.whole <= b.whole);
      case Op::gt: return Val::of_bool(a.whole > b.whole);
      default: return Val::of_bool(a.whole >= b.whole);
    }
  }
  switch (op) {
    case Op::lt: return Val::of_bool(a.number < b.number);
    case Op::le: return Val::of_bool(a.number <= b.number);
    case Op::gt: return Val::of_bool(a.number > b.number);
    default: return Val::of_bool(a.number >= b.number);
  }
}

}  // namespace

const char* fault_text(Val::Fault fault) {
  switch (fault) {
    case Fault::division_by_zero: return "division by zero";
    case Fault::overflow: return "an integer beyond 64 bits";
    case Fault::not_finite: return "a real that is not a finite number";
    case Fault::type: return "operands of the wrong type";
    default: return "no value";
  }
}

Op operator_of(const Expr& e) {
  switch (e.kind) {
    case ExprKind::logical_not: return Op::logical_not;
    case ExprKind::logical_and: return Op::logical_and;
    case ExprKind::logical_or: return Op::logical_or;
    case ExprKind::logical_xor: return Op::logical_xor;
    case ExprKind::implies: return Op::implies;
    case ExprKind::iff: return Op::iff;
    case ExprKind::eq: return Op::eq;
    case ExprKind::ne: return Op::ne;
    case ExprKind::lt: return Op::lt;
    case ExprKind::le: return Op::le;
    case ExprKind::gt: return Op::gt;
    case ExprKind::ge: return Op::ge;
    case ExprKind::add: return Op::add;
    case ExprKind::sub: return Op::sub;
    case ExprKind::mul: return Op::mul;
    case ExprKind::div: return Op::div;
    case ExprKind::mod: return Op::mod;
    case ExprKind::pow:
      return e.args.size() == 2 && is_natural_numeral(*e.args[1]) ? Op::pow_whole : Op::pow;
    case ExprKind::negate: return Op::negate;
    case ExprKind::call: {
      static const std::pair<const char*, Op> functions[] = {
          {"absInt", Op::abs_int},   {"absReal", Op::abs_real}, {"minInt", Op::min_int},
          {"minReal", Op::min_real}, {"maxInt", Op::max_int},   {"maxReal", Op::max_real},
          {"ite", Op::ite}};
      const std::size_t arity = e.text == "ite" ? 3 : e.text.starts_with("abs") ? 1 : 2;
      for (const auto& [name, op] : functions)
        if (e.text == name && e.args.size() == arity) return op;
      return Op::unknown;
    }
    default: return Op::unknown;
  }
}

Val apply(Op op, const Val* args, std::size_t n) {
  switch (op) {
    case Op::logical_and: return junction(args, n, false);
    case Op::logical_or: return junction(args, n, true);
    case Op::implies: {  // right fold: a => (b => c)
      Val acc = args[n - 1];
      for (std::size_t k = n - 1; k-- > 0;) acc = implication(args[k], acc);
      if (acc.known() && acc.kind != Kind::boolean) return Val::none(Fault::type, Kind::boolean);
      return acc;
    }
    case Op::ite: {
      if (!args[0].known()) return Val::none(fault_of(args[0]), args[1].kind, args[1].integer);
      if (args[0].kind != Kind::boolean) return Val::none(Fault::type);
      Val out = args[0].truth() ? args[1] : args[2];
      const Val& other = args[0].truth() ? args[2] : args[1];
      // An ite of an integer and a real is a real, whichever branch is chosen.
      if (out.kind == Kind::number && out.integer && other.kind == Kind::number && !other.integer) {
        out.integer = false;
        out.whole = 0;
      }
      return out;
    }
    case Op::unknown: return Val::none(Fault::type);
    default: break;
  }
  // Every other operator needs all its operands.
  const bool logical = op == Op::logical_not || op == Op::logical_xor || op == Op::iff;
  const bool relational = op >= Op::eq && op <= Op::ge;
  const Kind result_kind = logical || relational ? Kind::boolean : Kind::number;
  if (const Val* absent = first_absent(args, n)) {
    bool integer = result_kind == Kind::number && op != Op::pow && op != Op::abs_real &&
                   op != Op::min_real && op != Op::max_real;
    for (std::size_t k = 0; k < n; ++k) integer = integer && args[k].integer;
    return Val::none(fault_of(*absent), result_kind, integer);
  }
  if (logical) {
    if (!all_kind(args, n, Kind::boolean)) return Val::none(Fault::type, Kind::boolean);
    if (op == Op::logical_not) return Val::of_bool(!args[0].truth());
    bool acc = args[0].truth();
    for (std::size_t k = 1; k < n; ++k)
      acc = op == Op::logical_xor ? acc != args[k].truth() : acc == args[k].truth();
    return Val::of_bool(acc);
  }
  if (relational) return relation(op, args[0], args[1]);
  if (!all_kind(args, n, Kind::number)) return Val::none(Fault::type, Kind::number);
  if (op == Op::negate || op == Op::abs_int || op == Op::abs_real) {
    const Val& a = args[0];
    if (a.integer && op != Op::abs_real) {
      if (op == Op::abs_int && a.whole >= 0) return a;
      if (a.whole == INT64_MIN) return Val::none(Fault::overflow, Kind::number, true);
      return Val::of_whole(-a.whole);
    }
    return real(op == Op::negate ? -a.number : std::fabs(a.number));
  }
  // add, sub, mul fold left over two or more operands; the rest take two.
  Val acc = args[0];
  for (std::size_t k = 1; k < n && acc.known(); ++k) {
    const Val& b = args[k];
    const bool whole = acc.integer && b.integer && op != Op::pow && op != Op::min_real &&
                       op != Op::max_real && (op != Op::pow_whole || b.whole >= 0);
    acc = whole ? integer_arithmetic(op, acc.whole, b.whole)
                : real_arithmetic(op, acc.number, b.number);
  }
  return acc;
}

Val number_literal(const std::string& text) {
  if (text.find_first_of(".eE") != std::string::npos)
    return real(std::strtod(text.c_str(), nullptr));
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE) return Val::none(Fault::overflow, Kind::number, true);
  return Val::of_whole(v);
}

Val evaluate(const Expr& e, const NameValue& name) {
  switch (e.kind) {
    case ExprKind::bool_literal: return Val::of_bool(e.bool_value);
    case ExprKind::number: return number_literal(e.text);
    case ExprKind::identifier: return name(e.text, false);
    default: break;
  }
  std::vector<Val> args;
  args.reserve(e.args.size());
  for (const auto& a : e.args) {
    // A bare enum literal on the right of `=` takes its meaning from the left.
    const bool literal = (e.kind == ExprKind::eq || e.kind == ExprKind::ne) && !args.empty() &&
                         args[0].kind == Val::Kind::symbol && a->kind == ExprKind::identifier;
    args.push_back(literal ? name(a->text, true) : evaluate(*a, name));
  }
  return apply(operator_of(e), args.data(), args.size());
}

}  // namespace uabt::fretish
