#include "smt/evaluate.hpp"

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "fretish/evaluate.hpp"

#include "smt/rational.hpp"

namespace uabt::smt {

using fretish::Expr;
using fretish::Variable;
using fretish::VarType;

namespace {

bool has_literal(const Variable& v, const std::string& name) {
  for (const auto& l : v.enum_values)
    if (l == name) return true;
  return false;
}

// The state's values as fretish::evaluate reads names; enum literals are interned by name.
fretish::Val evaluate_in(const Expr& condition, const fretish::Domain& domain, const State& state) {
  std::vector<std::string> symbols;
  const auto symbol = [&](const std::string& literal) {
    for (std::size_t k = 0; k < symbols.size(); ++k)
      if (symbols[k] == literal) return fretish::Val::of_symbol(static_cast<int>(k));
    symbols.push_back(literal);
    return fretish::Val::of_symbol(static_cast<int>(symbols.size() - 1));
  };
  const auto is_literal = [&](const std::string& name) {
    for (const auto& v : domain.variables)
      if (v.type == VarType::enumeration && has_literal(v, name)) return true;
    return false;
  };
  return fretish::evaluate(condition, [&](const std::string& name, bool prefer_literal) {
    if (prefer_literal && is_literal(name)) return symbol(name);
    if (const Value* value = find_value(state, name)) {
      switch (value->kind) {
        case Value::Kind::boolean: return fretish::Val::of_bool(value->boolean);
        case Value::Kind::integer: return fretish::Val::of_whole(value->integer);
        case Value::Kind::real: return fretish::Val::of_number(value->real);
        case Value::Kind::enumeration: return symbol(value->text);
      }
    }
    if (is_literal(name)) return symbol(name);
    return fretish::Val::none(fretish::Val::Fault::unset);
  });
}

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
  const fretish::Val v = evaluate_in(condition, domain, state);
  if (v.fault != fretish::Val::Fault::none)
    throw EvaluationError("'" + fretish::to_fretish(condition) +
                          "' has no value in this state: " + fretish::fault_text(v.fault));
  if (v.kind != fretish::Val::Kind::boolean)
    throw EvaluationError("'" + fretish::to_fretish(condition) + "' is not a condition");
  return v.truth();
}

std::optional<bool> try_evaluate(const Expr& condition, const fretish::Domain& domain,
                                 const State& state) {
  const fretish::Val v = evaluate_in(condition, domain, state);
  if (!v.known() || v.kind != fretish::Val::Kind::boolean) return std::nullopt;
  return v.truth();
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
