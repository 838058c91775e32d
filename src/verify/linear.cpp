#include "verify/linear.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;

namespace {

struct Form {
  std::map<std::string, Fraction> coefficients;
  Fraction constant;

  bool is_constant() const { return coefficients.empty(); }
  Form scaled(const Fraction& k) const {
    Form out;
    out.constant = constant * k;
    if (k.is_zero()) return out;
    for (const auto& [v, c] : coefficients) out.coefficients[v] = c * k;
    return out;
  }
  Form plus(const Form& o) const {
    Form out = *this;
    out.constant += o.constant;
    for (const auto& [v, c] : o.coefficients) {
      const Fraction sum = out.coefficients[v] + c;
      if (sum.is_zero())
        out.coefficients.erase(v);
      else
        out.coefficients[v] = sum;
    }
    return out;
  }
};

std::optional<Form> form_of(const Expr& e, const smt::Typing& typing) {
  const smt::TypeInfo* t = typing.find(e);
  if (t == nullptr || (t->sort != smt::Sort::integer && t->sort != smt::Sort::real))
    return std::nullopt;
  switch (e.kind) {
    case ExprKind::number: {
      auto f = Fraction::parse(e.text);
      if (!f) return std::nullopt;
      Form out;
      out.constant = *f;
      return out;
    }
    case ExprKind::identifier: {
      if (t->variable == nullptr) return std::nullopt;
      Form out;
      out.coefficients[e.text] = Fraction(1);
      return out;
    }
    case ExprKind::negate: {
      auto a = form_of(*e.args[0], typing);
      if (!a) return std::nullopt;
      return a->scaled(Fraction(-1));
    }
    case ExprKind::add:
    case ExprKind::sub: {
      std::optional<Form> acc;
      for (std::size_t k = 0; k < e.args.size(); ++k) {
        auto a = form_of(*e.args[k], typing);
        if (!a) return std::nullopt;
        if (k > 0 && e.kind == ExprKind::sub) a = a->scaled(Fraction(-1));
        acc = acc ? acc->plus(*a) : *a;
      }
      return acc;
    }
    case ExprKind::mul: {
      std::optional<Form> acc;
      for (const auto& arg : e.args) {
        auto a = form_of(*arg, typing);
        if (!a) return std::nullopt;
        if (!acc)
          acc = a;
        else if (a->is_constant())
          acc = acc->scaled(a->constant);
        else if (acc->is_constant())
          acc = a->scaled(acc->constant);
        else
          return std::nullopt;  // a product of variables
      }
      return acc;
    }
    case ExprKind::div: {
      // Integer division truncates: not linear.
      if (t->sort != smt::Sort::real || e.args.size() != 2) return std::nullopt;
      auto a = form_of(*e.args[0], typing), b = form_of(*e.args[1], typing);
      if (!a || !b || !b->is_constant() || b->constant.is_zero()) return std::nullopt;
      return a->scaled(Fraction(1) / b->constant);
    }
    default: return std::nullopt;
  }
}

}  // namespace

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
    auto lhs = form_of(*atom.args[0], typing), rhs = form_of(*atom.args[1], typing);
    if (!lhs || !rhs) return std::nullopt;
    const Form d = lhs->plus(rhs->scaled(Fraction(-1)));
    LinearAtom out;
    out.coefficients = d.coefficients;
    out.constant = d.constant;
    out.op = atom.kind;
    return out;
  } catch (const FractionOverflow&) {
    return std::nullopt;
  }
}

}  // namespace uabt::verify::detail
