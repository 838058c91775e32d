#include "smt/evaluate.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "smt/rational.hpp"

namespace uabt::smt {

using fretish::Expr;
using fretish::ExprKind;
using fretish::Variable;
using fretish::VarType;

namespace {

// A value during evaluation; integers stay exact until mixed with a real.
struct Val {
  enum class Kind { boolean, integer, real, enumeration } kind = Kind::boolean;
  bool b = false;
  std::int64_t i = 0;
  double r = 0.0;
  std::string literal;
  const Variable* enum_type = nullptr;

  bool numeric() const { return kind == Kind::integer || kind == Kind::real; }
  double as_double() const { return kind == Kind::integer ? static_cast<double>(i) : r; }
};

Val boolean(bool b) {
  Val v;
  v.b = b;
  return v;
}
Val integer(std::int64_t i) {
  Val v;
  v.kind = Val::Kind::integer;
  v.i = i;
  return v;
}
Val real(double r) {
  Val v;
  v.kind = Val::Kind::real;
  v.r = r;
  return v;
}

const Variable* declared(const fretish::Domain& d, const std::string& name) {
  for (const auto& v : d.variables)
    if (v.name == name) return &v;
  return nullptr;
}

bool has_literal(const Variable& v, const std::string& name) {
  for (const auto& l : v.enum_values)
    if (l == name) return true;
  return false;
}

// FRET's targets (C, Lustre, SMV): the quotient is truncated toward zero.
std::int64_t truncated_div(std::int64_t a, std::int64_t b) {
  if (a == std::numeric_limits<std::int64_t>::min() && b == -1) throw EvaluationError("overflow");
  return a / b;
}

class Evaluator {
 public:
  Evaluator(const fretish::Domain& d, const State& s) : domain_(d), state_(s) {}

  Val eval(const Expr& e, const Variable* enum_hint = nullptr) {
    switch (e.kind) {
      case ExprKind::bool_literal: return boolean(e.bool_value);
      case ExprKind::number: return number(e.text);
      case ExprKind::identifier: return identifier(e.text, enum_hint);
      case ExprKind::call: return call(e, enum_hint);
      case ExprKind::logical_not: return boolean(!truth(*e.args[0]));
      case ExprKind::logical_and:
        for (const auto& a : e.args)
          if (!truth(*a)) return boolean(false);
        return boolean(true);
      case ExprKind::logical_or:
        for (const auto& a : e.args)
          if (truth(*a)) return boolean(true);
        return boolean(false);
      case ExprKind::logical_xor: {
        bool acc = truth(*e.args[0]);
        for (std::size_t k = 1; k < e.args.size(); ++k) acc = acc != truth(*e.args[k]);
        return boolean(acc);
      }
      case ExprKind::iff: {
        bool acc = truth(*e.args[0]);
        for (std::size_t k = 1; k < e.args.size(); ++k) acc = acc == truth(*e.args[k]);
        return boolean(acc);
      }
      case ExprKind::implies: {
        bool acc = truth(*e.args.back());
        for (std::size_t k = e.args.size() - 1; k-- > 0;) acc = !truth(*e.args[k]) || acc;
        return boolean(acc);
      }
      case ExprKind::eq:
      case ExprKind::ne: {
        const bool equal = equals(*e.args[0], *e.args[1]);
        return boolean(e.kind == ExprKind::eq ? equal : !equal);
      }
      case ExprKind::lt:
      case ExprKind::le:
      case ExprKind::gt:
      case ExprKind::ge: return boolean(compare(e.kind, num(*e.args[0]), num(*e.args[1])));
      case ExprKind::negate: {
        Val v = num(*e.args[0]);
        if (v.kind == Val::Kind::real) return real(-v.r);
        std::int64_t out;
        if (__builtin_sub_overflow(std::int64_t{0}, v.i, &out)) throw EvaluationError("overflow");
        return integer(out);
      }
      case ExprKind::add:
      case ExprKind::sub:
      case ExprKind::mul: {
        Val acc = num(*e.args[0]);
        for (std::size_t k = 1; k < e.args.size(); ++k) acc = arith(e.kind, acc, num(*e.args[k]));
        return acc;
      }
      case ExprKind::div:
      case ExprKind::mod:
      case ExprKind::pow: return arith(e.kind, num(*e.args[0]), num(*e.args[1]));
    }
    throw EvaluationError("unknown expression kind");
  }

  bool truth(const Expr& e) {
    const Val v = eval(e);
    if (v.kind != Val::Kind::boolean)
      throw EvaluationError("'" + fretish::to_fretish(e) + "' is not a condition");
    return v.b;
  }

 private:
  const fretish::Domain& domain_;
  const State& state_;

  Val number(const std::string& text) {
    const auto r = parse_rational(text);
    if (!r) throw EvaluationError("not a number: " + text);
    if (is_integer_literal(text)) {
      char* end = nullptr;
      errno = 0;
      const long long v = std::strtoll(text.c_str(), &end, 10);
      if (errno == ERANGE) throw EvaluationError("integer literal out of range: " + text);
      return integer(v);
    }
    return real(std::strtod(text.c_str(), nullptr));
  }

  Val identifier(const std::string& name, const Variable* enum_hint) {
    if (enum_hint != nullptr && has_literal(*enum_hint, name)) return literal(name, enum_hint);
    if (const Value* value = find_value(state_, name)) {
      switch (value->kind) {
        case Value::Kind::boolean: return boolean(value->boolean);
        case Value::Kind::integer: return integer(value->integer);
        case Value::Kind::real: return real(value->real);
        case Value::Kind::enumeration: return literal(value->text, declared(domain_, name));
      }
    }
    for (const auto& v : domain_.variables)
      if (v.type == VarType::enumeration && has_literal(v, name)) return literal(name, &v);
    throw EvaluationError("the state gives no value to '" + name + "'");
  }

  static Val literal(const std::string& name, const Variable* enum_type) {
    Val v;
    v.kind = Val::Kind::enumeration;
    v.literal = name;
    v.enum_type = enum_type;
    return v;
  }

  bool in_state(const Expr& e) const {
    return e.kind != ExprKind::identifier || find_value(state_, e.text) != nullptr;
  }

  bool equals(const Expr& lhs, const Expr& rhs) {
    // A bare enum literal takes its meaning from the other side.
    const bool lhs_first = in_state(lhs) || !in_state(rhs);
    const Val a = eval(lhs_first ? lhs : rhs);
    const Val b =
        eval(lhs_first ? rhs : lhs, a.kind == Val::Kind::enumeration ? a.enum_type : nullptr);
    if (a.kind == Val::Kind::boolean && b.kind == Val::Kind::boolean) return a.b == b.b;
    if (a.kind == Val::Kind::enumeration && b.kind == Val::Kind::enumeration)
      return a.literal == b.literal;
    if (a.numeric() && b.numeric()) {
      if (a.kind == Val::Kind::integer && b.kind == Val::Kind::integer) return a.i == b.i;
      return a.as_double() == b.as_double();
    }
    throw EvaluationError("cannot compare '" + fretish::to_fretish(lhs) + "' with '" +
                          fretish::to_fretish(rhs) + "'");
  }

  Val num(const Expr& e) {
    Val v = eval(e);
    if (!v.numeric()) throw EvaluationError("'" + fretish::to_fretish(e) + "' is not a number");
    return v;
  }

  static bool compare(ExprKind kind, const Val& a, const Val& b) {
    if (a.kind == Val::Kind::integer && b.kind == Val::Kind::integer) {
      switch (kind) {
        case ExprKind::lt: return a.i < b.i;
        case ExprKind::le: return a.i <= b.i;
        case ExprKind::gt: return a.i > b.i;
        default: return a.i >= b.i;
      }
    }
    const double x = a.as_double(), y = b.as_double();
    switch (kind) {
      case ExprKind::lt: return x < y;
      case ExprKind::le: return x <= y;
      case ExprKind::gt: return x > y;
      default: return x >= y;
    }
  }

  static Val arith(ExprKind kind, const Val& a, const Val& b) {
    if (a.kind == Val::Kind::integer && b.kind == Val::Kind::integer) {
      std::int64_t out = 0;
      switch (kind) {
        case ExprKind::add:
          if (__builtin_add_overflow(a.i, b.i, &out)) throw EvaluationError("overflow");
          return integer(out);
        case ExprKind::sub:
          if (__builtin_sub_overflow(a.i, b.i, &out)) throw EvaluationError("overflow");
          return integer(out);
        case ExprKind::mul:
          if (__builtin_mul_overflow(a.i, b.i, &out)) throw EvaluationError("overflow");
          return integer(out);
        case ExprKind::div:
          if (b.i == 0) throw EvaluationError("division by zero");
          return integer(truncated_div(a.i, b.i));
        case ExprKind::mod:
          if (b.i == 0) throw EvaluationError("division by zero");
          return integer(a.i - b.i * truncated_div(a.i, b.i));
        case ExprKind::pow: {
          if (b.i < 0) return real(std::pow(static_cast<double>(a.i), static_cast<double>(b.i)));
          std::int64_t acc = 1;
          for (std::int64_t k = 0; k < b.i; ++k)
            if (__builtin_mul_overflow(acc, a.i, &acc)) throw EvaluationError("overflow");
          return integer(acc);
        }
        default: break;
      }
    }
    if (kind == ExprKind::mod) throw EvaluationError("mod of a real");
    const double x = a.as_double(), y = b.as_double();
    switch (kind) {
      case ExprKind::add: return real(x + y);
      case ExprKind::sub: return real(x - y);
      case ExprKind::mul: return real(x * y);
      case ExprKind::div:
        if (y == 0.0) throw EvaluationError("division by zero");
        return real(x / y);
      default: return real(std::pow(x, y));
    }
  }

  Val call(const Expr& e, const Variable* enum_hint) {
    const std::string& f = e.text;
    if (f == "ite" && e.args.size() == 3)
      return truth(*e.args[0]) ? eval(*e.args[1], enum_hint) : eval(*e.args[2], enum_hint);
    if ((f == "absInt" || f == "absReal") && e.args.size() == 1) {
      const Val v = num(*e.args[0]);
      if (f == "absInt" && v.kind == Val::Kind::integer) {
        if (v.i == INT64_MIN) throw EvaluationError("overflow");
        return integer(v.i < 0 ? -v.i : v.i);
      }
      return real(std::fabs(v.as_double()));
    }
    if ((f == "minInt" || f == "maxInt" || f == "minReal" || f == "maxReal") &&
        e.args.size() == 2) {
      const Val a = num(*e.args[0]), b = num(*e.args[1]);
      const bool is_min = f.starts_with("min");
      if (a.kind == Val::Kind::integer && b.kind == Val::Kind::integer && f.ends_with("Int"))
        return integer(is_min ? std::min(a.i, b.i) : std::max(a.i, b.i));
      return real(is_min ? std::min(a.as_double(), b.as_double())
                         : std::max(a.as_double(), b.as_double()));
    }
    throw EvaluationError("unknown function '" + f + "'");
  }
};

bool within(const Value& value, const Variable& v) {
  const double x =
      value.kind == Value::Kind::integer ? static_cast<double>(value.integer) : value.real;
  auto bound = [](const std::string& text) {
    return std::strtod(text.c_str(), nullptr);  // bounds are plain literals
  };
  auto exact_integer_bound = [](const std::string& text, std::int64_t& out) {
    if (!is_integer_literal(text)) return false;
    out = std::strtoll(text.c_str(), nullptr, 10);
    return true;
  };
  if (!v.lower.empty()) {
    std::int64_t lo;
    if (value.kind == Value::Kind::integer && exact_integer_bound(v.lower, lo)) {
      if (value.integer < lo) return false;
    } else if (x < bound(v.lower)) {
      return false;
    }
  }
  if (!v.upper.empty()) {
    std::int64_t hi;
    if (value.kind == Value::Kind::integer && exact_integer_bound(v.upper, hi)) {
      if (value.integer > hi) return false;
    } else if (x > bound(v.upper)) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool evaluate(const Expr& condition, const fretish::Domain& domain, const State& state) {
  return Evaluator(domain, state).truth(condition);
}

std::optional<bool> try_evaluate(const Expr& condition, const fretish::Domain& domain,
                                 const State& state) {
  try {
    return evaluate(condition, domain, state);
  } catch (const EvaluationError&) {
    return std::nullopt;
  }
}

bool satisfies_domain(const fretish::Domain& domain, const State& state) {
  for (const auto& v : domain.variables) {
    const Value* value = find_value(state, v.name);
    if (value == nullptr) return false;
    switch (v.type) {
      case VarType::boolean:
        if (value->kind != Value::Kind::boolean) return false;
        break;
      case VarType::integer:
        if (value->kind != Value::Kind::integer || !within(*value, v)) return false;
        break;
      case VarType::real:
        if (value->kind != Value::Kind::real || !within(*value, v)) return false;
        break;
      case VarType::enumeration:
        if (value->kind != Value::Kind::enumeration || !has_literal(v, value->text)) return false;
        break;
    }
  }
  for (const auto& a : domain.assumptions)
    if (a.expr && try_evaluate(*a.expr, domain, state) != true) return false;
  return true;
}

}  // namespace uabt::smt
