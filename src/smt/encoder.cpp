#include "smt/encoder.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>

#include "fretish/integer_ranges.hpp"
#include "smt/assign.hpp"
#include "smt/division.hpp"
#include "smt/rational.hpp"

namespace uabt::smt {

using fretish::Expr;
using fretish::ExprKind;
using fretish::VarType;
using Overrides = std::unordered_map<const Expr*, z3::expr>;

namespace {

Sort sort_of(VarType t) {
  switch (t) {
    case VarType::boolean: return Sort::boolean;
    case VarType::integer: return Sort::integer;
    case VarType::real: return Sort::real;
    case VarType::enumeration: return Sort::enumeration;
  }
  return Sort::boolean;
}

// Exponents up to this are expanded into products, which Z3's arithmetic handles far better
// than its power operator.
constexpr unsigned long kMaxExpandedExponent = 64;

}  // namespace

Encoder::Encoder(const fretish::Domain& domain) : domain_(domain) {
  for (const auto& v : domain_.variables) {
    if (slot_index_.count(v.name)) continue;  // a duplicate declaration: the loader reports it
    const Sort sort = sort_of(v.type);
    z3::expr constant = sort == Sort::boolean ? context_.bool_const(v.name.c_str())
                        : sort == Sort::real  ? context_.real_const(v.name.c_str())
                                              : context_.int_const(v.name.c_str());
    slot_index_[v.name] = slots_.size();
    slots_.push_back(Slot{v.name, sort, &v, constant});
  }
}

const Encoder::Slot* Encoder::find_slot(const std::string& name) const {
  const auto it = slot_index_.find(name);
  return it == slot_index_.end() ? nullptr : &slots_[it->second];
}

z3::expr Encoder::fresh_literal(const char* prefix) {
  Z3_ast a = Z3_mk_fresh_const(context_, prefix, context_.bool_sort());
  context_.check_error();
  return z3::expr(context_, a);
}

z3::expr Encoder::implicit_boolean(const std::string& name) {
  if (const Slot* s = find_slot(name)) return s->constant;
  slot_index_[name] = slots_.size();
  slots_.push_back(Slot{name, Sort::boolean, nullptr, context_.bool_const(name.c_str())});
  return slots_.back().constant;
}

std::optional<z3::expr> Encoder::lower_condition(const Expr& condition, const SourceLocation& where,
                                                 std::vector<Finding>& findings) {
  if (!check_condition(condition, domain_, where, typing_, findings)) return std::nullopt;
  return lower(condition);
}

z3::expr Encoder::lower(const Expr& condition, const Overrides& overrides) {
  return lower_term(condition, overrides).e;
}

z3::expr Encoder::as_real(const Term& t) {
  return t.sort == Sort::integer ? z3::to_real(t.e) : t.e;
}

Encoder::Term Encoder::lower_term(const Expr& e, const Overrides& overrides) {
  if (!overrides.empty()) {
    const auto it = overrides.find(&e);
    if (it != overrides.end()) return {it->second, Sort::boolean};
  }
  const TypeInfo& info = typing_.at(e);
  const Sort sort = info.sort;
  // Operands of a real-valued operation are lifted to Real; integer ones stay Int.
  auto operand = [&](const Expr& arg, Sort target) {
    Term t = lower_term(arg, overrides);
    return target == Sort::real ? as_real(t) : t.e;
  };
  auto common_sort = [&](const Expr& a, const Expr& b) {
    const Sort sa = typing_.at(a).sort, sb = typing_.at(b).sort;
    return sa == Sort::real || sb == Sort::real ? Sort::real : sa;
  };
  switch (e.kind) {
    case ExprKind::bool_literal: return {context_.bool_val(e.bool_value), sort};
    case ExprKind::number: {
      const std::string text = parse_rational(e.text)->text();
      return {
          sort == Sort::integer ? context_.int_val(text.c_str()) : context_.real_val(text.c_str()),
          sort};
    }
    case ExprKind::identifier: {
      if (info.enum_index >= 0) return {context_.int_val(info.enum_index), sort};
      if (info.implicit_boolean) return {implicit_boolean(e.text), sort};
      return {find_slot(e.text)->constant, sort};
    }
    case ExprKind::call: {
      if (e.text == "ite") {
        const z3::expr c = lower_term(*e.args[0], overrides).e;
        return {z3::ite(c, operand(*e.args[1], sort), operand(*e.args[2], sort)), sort};
      }
      if (e.args.size() == 1) {  // absInt, absReal
        const z3::expr x = operand(*e.args[0], sort);
        return {z3::ite(x >= 0, x, -x), sort};
      }
      const z3::expr a = operand(*e.args[0], sort), b = operand(*e.args[1], sort);
      const bool is_min = e.text.starts_with("min");
      return {z3::ite(is_min ? a <= b : a >= b, a, b), sort};
    }
    case ExprKind::logical_not: return {!lower_term(*e.args[0], overrides).e, sort};
    case ExprKind::logical_or:
      if (e.args.size() >= fretish::kMinRangeRun) return {lower_disjunction(e, overrides), sort};
      [[fallthrough]];
    case ExprKind::logical_and: {
      z3::expr_vector parts(context_);
      for (const auto& arg : e.args) parts.push_back(lower_term(*arg, overrides).e);
      return {e.kind == ExprKind::logical_and ? z3::mk_and(parts) : z3::mk_or(parts), sort};
    }
    case ExprKind::logical_xor:
    case ExprKind::iff: {
      z3::expr acc = lower_term(*e.args[0], overrides).e;
      for (std::size_t i = 1; i < e.args.size(); ++i) {
        const z3::expr next = lower_term(*e.args[i], overrides).e;
        smt::assign(acc, e.kind == ExprKind::logical_xor ? (acc ^ next) : (acc == next));
      }
      return {acc, sort};
    }
    case ExprKind::implies: {  // right-associative: a -> b -> c is a -> (b -> c)
      z3::expr acc = lower_term(*e.args.back(), overrides).e;
      for (std::size_t i = e.args.size() - 1; i-- > 0;)
        smt::assign(acc, z3::implies(lower_term(*e.args[i], overrides).e, acc));
      return {acc, sort};
    }
    case ExprKind::eq:
    case ExprKind::ne:
    case ExprKind::lt:
    case ExprKind::le:
    case ExprKind::gt:
    case ExprKind::ge: {
      const Sort target = common_sort(*e.args[0], *e.args[1]);
      const z3::expr a = operand(*e.args[0], target), b = operand(*e.args[1], target);
      switch (e.kind) {
        case ExprKind::eq: return {a == b, sort};
        case ExprKind::ne: return {a != b, sort};
        case ExprKind::lt: return {a < b, sort};
        case ExprKind::le: return {a <= b, sort};
        case ExprKind::gt: return {a > b, sort};
        default: return {a >= b, sort};
      }
    }
    case ExprKind::negate: return {-operand(*e.args[0], sort), sort};
    case ExprKind::add:
    case ExprKind::sub:
    case ExprKind::mul: {
      z3::expr acc = operand(*e.args[0], sort);
      for (std::size_t i = 1; i < e.args.size(); ++i) {
        const z3::expr next = operand(*e.args[i], sort);
        smt::assign(acc, e.kind == ExprKind::add   ? acc + next
                         : e.kind == ExprKind::sub ? acc - next
                                                   : acc * next);
      }
      return {acc, sort};
    }
    case ExprKind::div: {
      // Int / Int truncates toward zero as FRET's targets do; anything else is real division.
      const Sort target = common_sort(*e.args[0], *e.args[1]);
      const z3::expr a = operand(*e.args[0], target), b = operand(*e.args[1], target);
      if (!a.is_int() || !b.is_int()) return {a / b, sort};
      return {smt::truncated_quotient(a, b), sort};
    }
    case ExprKind::mod: {
      // The remainder of the truncated quotient: it has the sign of the dividend.
      const z3::expr a = operand(*e.args[0], sort), b = operand(*e.args[1], sort);
      return {smt::truncated_remainder(a, b), sort};
    }
    case ExprKind::pow: {
      const Expr& exponent = *e.args[1];
      if (fretish::is_natural_numeral(exponent) && exponent.text.size() <= 2 &&
          std::stoul(exponent.text) <= kMaxExpandedExponent) {
        const unsigned long n = std::stoul(exponent.text);
        const z3::expr base = operand(*e.args[0], sort);
        z3::expr acc = sort == Sort::integer ? context_.int_val(1) : context_.real_val(1);
        for (unsigned long i = 0; i < n; ++i) acc = i == 0 ? base : acc * base;
        return {acc, sort};
      }
      return {z3::pw(operand(*e.args[0], Sort::real), operand(exponent, Sort::real)), Sort::real};
    }
  }
  throw std::logic_error("unhandled expression kind");
}

std::optional<z3::expr> Encoder::bound(const Slot& slot, const std::string& text, bool is_lower,
                                       std::vector<Finding>& findings) {
  const auto r = parse_rational(text);
  if (!r) {
    findings.push_back(make_finding("ref-type-mismatch",
                                    "the " + std::string(is_lower ? "lower" : "upper") +
                                        " bound '" + text + "' of " + slot.name +
                                        " is not a number",
                                    slot.declaration->location));
    return std::nullopt;
  }
  const bool integer_bound = slot.sort == Sort::integer && r->is_integer();
  const z3::expr value =
      integer_bound ? context_.int_val(r->text().c_str()) : context_.real_val(r->text().c_str());
  const z3::expr x =
      integer_bound || slot.sort == Sort::real ? slot.constant : z3::to_real(slot.constant);
  return is_lower ? x >= value : x <= value;
}

std::vector<Encoder::DomainPart> Encoder::domain_parts(std::vector<Finding>& findings) {
  std::vector<DomainPart> parts;
  // Copy: implicit booleans met while lowering assumptions may grow slots_.
  const std::vector<Slot> declared = slots_;
  for (const Slot& slot : declared) {
    const fretish::Variable* v = slot.declaration;
    // An invalid declaration is reported as domain-invalid; its empty range or refused values
    // are no part of the domain (no check is made over it until it is fixed).
    if (v == nullptr || !v->invalid.empty()) continue;
    if (slot.sort == Sort::enumeration) {
      const int n = static_cast<int>(v->enum_values.size());
      std::string values;
      for (const auto& l : v->enum_values) values += (values.empty() ? "" : ", ") + l;
      parts.push_back(
          {v->name + " in {" + values + "}", slot.constant >= 0 && slot.constant < n, v->location});
      continue;
    }
    if (slot.sort != Sort::integer && slot.sort != Sort::real) continue;
    if (v->lower.empty() && v->upper.empty()) continue;
    z3::expr_vector range(context_);
    if (!v->lower.empty())
      if (auto b = bound(slot, v->lower, true, findings)) range.push_back(*b);
    if (!v->upper.empty())
      if (auto b = bound(slot, v->upper, false, findings)) range.push_back(*b);
    if (range.empty()) continue;
    parts.push_back({v->name + " in [" + (v->lower.empty() ? "-inf" : v->lower) + ", " +
                         (v->upper.empty() ? "inf" : v->upper) + "]",
                     z3::mk_and(range), v->location});
  }
  for (const auto& a : domain_.assumptions) {
    if (!a.expr) continue;
    if (auto e = lower_condition(*a.expr, a.location, findings))
      parts.push_back({"assumption " + (a.name.empty() ? fretish::to_fretish(*a.expr) : a.name), *e,
                       a.location});
  }
  return parts;
}

namespace {

// A rational numeral as people write it: a decimal where it has one (256/125 as 2.048),
// else the fraction (1/3).
std::string exact_real_text(const z3::expr& value) {
  const std::string fraction = Z3_get_numeral_string(value.ctx(), value);
  std::uint64_t q = 0;
  if (fraction.find('/') == std::string::npos || !value.denominator().is_numeral_u64(q))
    return fraction;
  // p/q in lowest terms has a finite decimal exactly when q = 2^a 5^b; it has max(a, b)
  // decimal places.
  int twos = 0, fives = 0;
  for (; q % 2 == 0; q /= 2) ++twos;
  for (; q % 5 == 0; q /= 5) ++fives;
  return q == 1 ? value.get_decimal_string(std::max(twos, fives)) : fraction;
}

}  // namespace

State Encoder::state_of(const z3::model& model) const {
  State state;
  state.reserve(slots_.size());
  for (const Slot& slot : slots_) {
    const z3::expr value = model.eval(slot.constant, true);
    switch (slot.sort) {
      case Sort::boolean: state.emplace_back(slot.name, Value::of_bool(value.is_true())); break;
      case Sort::integer: {
        std::int64_t i = 0;
        if (!value.is_numeral_i64(i))
          throw std::runtime_error("the solver chose a value of " + slot.name +
                                   " beyond 64 bits: " + value.get_decimal_string(0));
        state.emplace_back(slot.name, Value::of_int(i));
        break;
      }
      case Sort::real: {
        if (value.is_algebraic()) {
          // An irrational root: Z3 prints a decimal approximation ending in '?'.
          const std::string text = value.get_decimal_string(12);
          std::string digits = text;
          if (!digits.empty() && digits.back() == '?') digits.pop_back();
          state.emplace_back(slot.name, Value::of_real(std::stod(digits), text));
        } else {
          state.emplace_back(slot.name, Value::of_real(value.as_double(), exact_real_text(value)));
        }
        break;
      }
      case Sort::enumeration: {
        std::int64_t i = 0;
        value.is_numeral_i64(i);
        const auto& values = slot.declaration->enum_values;
        const std::string literal =
            i >= 0 && static_cast<std::size_t>(i) < values.size() ? values[i] : "?";
        state.emplace_back(slot.name, Value::of_enum(literal));
        break;
      }
      case Sort::invalid: break;
    }
  }
  return state;
}

z3::expr Encoder::lower_disjunction(const Expr& e, const Overrides& overrides) {
  z3::expr_vector parts(context_);
  // The comparisons of each integer variable with a numeral, as ranges (integer_ranges.hpp).
  auto [ranges, rest] =
      fretish::integer_runs(e, [&](const Expr& arg, const fretish::IntegerComparison& c) {
        return !overrides.contains(&arg) && typing_.at(*c.variable).sort == Sort::integer &&
               find_slot(c.variable->text) != nullptr;
      });
  auto bound = [&](__int128 b) { return context_.int_val(static_cast<std::int64_t>(b)); };
  for (const auto& [name, allowed] : ranges) {
    const z3::expr x = find_slot(name)->constant;
    for (const fretish::IntegerRange& r : fretish::merged(allowed)) {
      if (!r.lo && !r.hi) return context_.bool_val(true);
      if (r.lo && r.hi && *r.lo == *r.hi)
        parts.push_back(x == bound(*r.lo));
      else if (r.lo && r.hi)
        parts.push_back(bound(*r.lo) <= x && x <= bound(*r.hi));
      else
        parts.push_back(r.lo ? x >= bound(*r.lo) : x <= bound(*r.hi));
    }
  }
  for (const Expr* a : rest) parts.push_back(lower_term(*a, overrides).e);
  return z3::mk_or(parts);
}

}  // namespace uabt::smt
