#include "verify/linear.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;

Affine Affine::of_variable(const std::string& name) {
  Affine out;
  out.terms[name] = Fraction(1);
  return out;
}

Affine Affine::of_constant(const Fraction& value) {
  Affine out;
  out.constant = value;
  return out;
}

Affine Affine::scaled(const Fraction& k) const {
  Affine out = of_constant(constant * k);
  if (!k.is_zero())
    for (const auto& [name, a] : terms) out.terms[name] = a * k;
  return out;
}

Affine Affine::plus(const Affine& other, int sign) const {
  Affine out = *this;
  for (const auto& [name, a] : other.terms) {
    Fraction& t = out.terms[name];
    t += sign > 0 ? a : -a;
    if (t.is_zero()) out.terms.erase(name);
  }
  out.constant += sign > 0 ? other.constant : -other.constant;
  return out;
}

std::optional<Affine> product(const std::optional<Affine>& l, const std::optional<Affine>& r) {
  if (!l || !r) return std::nullopt;
  if (l->is_constant()) return r->scaled(l->constant);
  if (r->is_constant()) return l->scaled(r->constant);
  return std::nullopt;  // a product of variables
}

std::optional<Affine> quotient(const std::optional<Affine>& l, const std::optional<Affine>& r) {
  if (!l || !r || !r->is_constant() || r->constant.is_zero()) return std::nullopt;
  return l->scaled(Fraction(1) / r->constant);
}

std::optional<Affine> affine_form(const Expr& e, const AffineReading& reading) {
  switch (e.kind) {
    case ExprKind::number: {
      const auto f = Fraction::parse(e.text);
      return f ? std::optional(Affine::of_constant(*f)) : std::nullopt;
    }
    case ExprKind::identifier:
      return reading.variable(e) ? std::optional(Affine::of_variable(e.text)) : std::nullopt;
    case ExprKind::negate:
      return product(affine_form(*e.args[0], reading), Affine::of_constant(-1));
    case ExprKind::add:
    case ExprKind::sub:
    case ExprKind::mul: {
      std::optional<Affine> acc = affine_form(*e.args[0], reading);
      for (std::size_t k = 1; k < e.args.size() && acc; ++k) {
        const auto a = affine_form(*e.args[k], reading);
        if (e.kind == ExprKind::mul)
          acc = product(acc, a);
        else
          acc = a ? std::optional(acc->plus(*a, e.kind == ExprKind::add ? 1 : -1)) : std::nullopt;
      }
      return acc;
    }
    case ExprKind::div:
      if (e.args.size() != 2 || reading.truncates(e)) return std::nullopt;
      return quotient(affine_form(*e.args[0], reading), affine_form(*e.args[1], reading));
    default: return std::nullopt;
  }
}

bool LinearAtom::holds_at(const Fraction& value) const {
  switch (op) {
    case ExprKind::eq: return value.is_zero();
    case ExprKind::ne: return !value.is_zero();
    case ExprKind::lt: return value.sign() < 0;
    case ExprKind::le: return value.sign() <= 0;
    case ExprKind::gt: return value.sign() > 0;
    default: return value.sign() >= 0;
  }
}

bool LinearAtom::holds(const std::map<std::string, Fraction>& values) const {
  Fraction sum = constant;
  for (const auto& [v, c] : coefficients) sum += c * values.at(v);
  return holds_at(sum);
}

std::optional<LinearAtom> linear_atom(const Expr& atom, const smt::Typing& typing) {
  if (!fretish::is_relation(atom.kind) || atom.args.size() != 2) return std::nullopt;
  try {
    auto numeric = [&](const Expr& e) {
      const smt::TypeInfo* t = typing.find(e);
      return t != nullptr && (t->sort == smt::Sort::integer || t->sort == smt::Sort::real);
    };
    const AffineReading reading{
        [&](const Expr& e) { return numeric(e) && typing.find(e)->variable; },
        [&](const Expr& e) { return !numeric(e) || typing.find(e)->sort != smt::Sort::real; }};
    auto lhs = affine_form(*atom.args[0], reading), rhs = affine_form(*atom.args[1], reading);
    if (!lhs || !rhs) return std::nullopt;
    const Affine d = lhs->plus(*rhs, -1);
    LinearAtom out;
    out.coefficients = d.terms;
    out.constant = d.constant;
    out.op = atom.kind;
    return out;
  } catch (const FractionOverflow&) {
    return std::nullopt;
  }
}

}  // namespace uabt::verify::detail
