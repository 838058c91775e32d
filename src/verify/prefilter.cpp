#include "verify/prefilter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "fretish/relation.hpp"
#include "smt/rational.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;
using smt::Sort;

namespace {

// A literal whose double is order-faithful: at most 15 significant digits round-trip, so two
// different such literals never compare equal as doubles.
std::optional<std::pair<double, std::string>> exact_number(const Expr& e) {
  if (e.kind == ExprKind::negate && e.args.size() == 1) {
    auto inner = exact_number(*e.args[0]);
    if (!inner) return std::nullopt;
    return std::make_pair(-inner->first, "-" + inner->second);
  }
  if (e.kind != ExprKind::number) return std::nullopt;
  const auto r = smt::parse_rational(e.text);
  if (!r || r->numerator.size() > 15 || r->denominator.size() > 16) return std::nullopt;
  return std::make_pair(std::strtod(e.text.c_str(), nullptr), e.text);
}

bool intersect(VariableConstraint& into, const VariableConstraint& c) {
  if (into.kind != c.kind) return true;  // mixed kinds cannot happen for one variable
  switch (c.kind) {
    case VariableConstraint::Kind::boolean: return into.polarity == c.polarity;
    case VariableConstraint::Kind::values: {
      bool any = false;
      for (std::size_t i = 0; i < into.allowed.size() && i < c.allowed.size(); ++i) {
        into.allowed[i] = into.allowed[i] && c.allowed[i];
        any = any || into.allowed[i];
      }
      return any;
    }
    case VariableConstraint::Kind::interval: {
      if (c.lower > into.lower || (c.lower == into.lower && c.lower_strict)) {
        into.lower = c.lower;
        into.lower_strict = c.lower_strict;
      }
      if (c.upper < into.upper || (c.upper == into.upper && c.upper_strict)) {
        into.upper = c.upper;
        into.upper_strict = c.upper_strict;
      }
      if (into.lower > into.upper) return false;
      return !(into.lower == into.upper && (into.lower_strict || into.upper_strict));
    }
  }
  return true;
}

// The constraint one conjunct puts on one variable, if it is that simple.
std::optional<std::pair<std::string, VariableConstraint>> literal_constraint(
    const Expr& e, const smt::Typing& typing) {
  const Expr* atom = &e;
  bool polarity = true;
  if (e.kind == ExprKind::logical_not && e.args.size() == 1) {
    atom = e.args[0].get();
    polarity = false;
  }
  const smt::TypeInfo* t = typing.find(*atom);
  if (t == nullptr) return std::nullopt;
  if (atom->kind == ExprKind::identifier && t->sort == Sort::boolean && t->enum_index < 0) {
    VariableConstraint c;
    c.polarity = polarity;
    return std::make_pair(atom->text, c);
  }
  if (!polarity) return std::nullopt;
  if ((e.kind == ExprKind::eq || e.kind == ExprKind::ne) && e.args.size() == 2) {
    const smt::TypeInfo* a = typing.find(*e.args[0]);
    const smt::TypeInfo* b = typing.find(*e.args[1]);
    if (a && b && a->sort == Sort::enumeration && b->sort == Sort::enumeration) {
      const Expr* var = a->variable ? e.args[0].get() : e.args[1].get();
      const smt::TypeInfo* vt = a->variable ? a : b;
      const smt::TypeInfo* lt = a->variable ? b : a;
      if (var->kind == ExprKind::identifier && vt->variable && lt->enum_index >= 0 &&
          vt->enum_type != nullptr) {
        VariableConstraint c;
        c.kind = VariableConstraint::Kind::values;
        c.allowed.assign(vt->enum_type->enum_values.size(), e.kind == ExprKind::ne);
        c.allowed[static_cast<std::size_t>(lt->enum_index)] = e.kind == ExprKind::eq;
        return std::make_pair(var->text, c);
      }
      return std::nullopt;
    }
  }
  const auto b = bound_of(e, typing);
  if (!b || b->op == ExprKind::ne) return std::nullopt;
  VariableConstraint c;
  c.kind = VariableConstraint::Kind::interval;
  switch (b->op) {
    case ExprKind::eq: c.lower = c.upper = b->value; break;
    case ExprKind::lt:
      c.upper = b->value;
      c.upper_strict = true;
      break;
    case ExprKind::le: c.upper = b->value; break;
    case ExprKind::gt:
      c.lower = b->value;
      c.lower_strict = true;
      break;
    default: c.lower = b->value; break;
  }
  if (b->integer_variable) {  // integers: close the interval on whole numbers
    if (c.upper_strict)
      c.upper = std::ceil(c.upper) - 1;
    else
      c.upper = std::floor(c.upper);
    if (c.lower_strict)
      c.lower = std::floor(c.lower) + 1;
    else
      c.lower = std::ceil(c.lower);
    c.upper_strict = c.lower_strict = false;
  }
  return std::make_pair(b->variable, c);
}

void collect(const Expr& e, const smt::Typing& typing, Signature& s) {
  if (e.kind == ExprKind::logical_and) {
    for (const auto& arg : e.args) collect(*arg, typing, s);
    return;
  }
  if (e.kind == ExprKind::bool_literal && !e.bool_value) {
    s.contradictory = true;
    return;
  }
  auto c = literal_constraint(e, typing);
  if (!c) return;
  auto [it, inserted] = s.constraints.emplace(c->first, c->second);
  if (!inserted && !intersect(it->second, c->second)) s.contradictory = true;
}

}  // namespace

std::optional<Bound> bound_of(const Expr& e, const smt::Typing& typing) {
  if (e.args.size() != 2 ||
      !(e.kind == ExprKind::eq || e.kind == ExprKind::ne || e.kind == ExprKind::lt ||
        e.kind == ExprKind::le || e.kind == ExprKind::gt || e.kind == ExprKind::ge))
    return std::nullopt;
  for (int side = 0; side < 2; ++side) {
    const Expr& var = *e.args[side];
    const Expr& num = *e.args[1 - side];
    const smt::TypeInfo* t = typing.find(var);
    if (var.kind != ExprKind::identifier || t == nullptr || t->variable == nullptr ||
        (t->sort != Sort::integer && t->sort != Sort::real))
      continue;
    const auto n = exact_number(num);
    if (!n) continue;
    Bound b;
    b.variable = var.text;
    b.op = side == 0 ? e.kind : fretish::mirrored_relation(e.kind);
    b.value = n->first;
    b.text = n->second;
    b.integer_variable = t->sort == Sort::integer;
    return b;
  }
  return std::nullopt;
}

Signature signature_of(const Expr& guard, const smt::Typing& typing) {
  Signature s;
  collect(guard, typing, s);
  return s;
}

bool disjoint(const Signature& a, const Signature& b) {
  if (a.contradictory || b.contradictory) return true;
  for (const auto& [name, ca] : a.constraints) {
    const auto it = b.constraints.find(name);
    if (it == b.constraints.end()) continue;
    VariableConstraint meet = ca;
    if (!intersect(meet, it->second)) return true;
  }
  return false;
}

namespace {

// The variable constrained by the most signatures ("" when none is constrained twice).
std::string pivot_variable(const std::vector<const Signature*>& sigs) {
  std::map<std::string, std::size_t> uses;
  for (const Signature* s : sigs)
    if (!s->contradictory)
      for (const auto& [name, c] : s->constraints) ++uses[name];
  std::string best;
  std::size_t most = 1;
  for (const auto& [name, n] : uses) {
    if (n > most) {
      best = name;
      most = n;
    }
  }
  return best;
}

}  // namespace

std::vector<std::vector<std::size_t>> meeting_candidates(
    const std::vector<const Signature*>& sigs) {
  const std::size_t n = sigs.size();
  std::vector<std::vector<std::size_t>> meets(n);
  // Pairs (i, j) that share a bucket (or are swept together) are only candidates: `disjoint`
  // has the last word on each, once.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  auto consider = [&](std::size_t i, std::size_t j) {
    if (i != j) pairs.emplace_back(std::min(i, j), std::max(i, j));
  };
  const std::string pivot = pivot_variable(sigs);
  std::vector<std::size_t> free;  // signatures that leave the pivot unconstrained
  std::map<std::size_t, std::vector<std::size_t>> buckets;  // value (or polarity) → signatures
  std::vector<std::size_t> intervals;
  for (std::size_t i = 0; i < n; ++i) {
    if (sigs[i]->contradictory) continue;  // meets nothing
    const auto it = pivot.empty() ? sigs[i]->constraints.end() : sigs[i]->constraints.find(pivot);
    if (it == sigs[i]->constraints.end()) {
      free.push_back(i);
      continue;
    }
    const VariableConstraint& c = it->second;
    switch (c.kind) {
      case VariableConstraint::Kind::boolean: buckets[c.polarity ? 1 : 0].push_back(i); break;
      case VariableConstraint::Kind::values:
        for (std::size_t v = 0; v < c.allowed.size(); ++v)
          if (c.allowed[v]) buckets[v].push_back(i);
        break;
      case VariableConstraint::Kind::interval: intervals.push_back(i); break;
    }
  }
  for (const std::size_t i : free)
    for (std::size_t j = 0; j < n; ++j)
      if (!sigs[j]->contradictory) consider(i, j);
  for (const auto& [value, members] : buckets)
    for (std::size_t a = 0; a < members.size(); ++a)
      for (std::size_t b = a + 1; b < members.size(); ++b) consider(members[a], members[b]);
  // Sorted by lower end, an interval can only meet those after it that start before it ends.
  auto interval_of = [&](std::size_t i) -> const VariableConstraint& {
    return sigs[i]->constraints.at(pivot);
  };
  std::sort(intervals.begin(), intervals.end(), [&](std::size_t a, std::size_t b) {
    return interval_of(a).lower < interval_of(b).lower;
  });
  for (std::size_t a = 0; a < intervals.size(); ++a) {
    const double upper = interval_of(intervals[a]).upper;
    for (std::size_t b = a + 1; b < intervals.size() && interval_of(intervals[b]).lower <= upper;
         ++b)
      consider(intervals[a], intervals[b]);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& [i, j] : pairs) {
    if (disjoint(*sigs[i], *sigs[j])) continue;
    meets[i].push_back(j);
    meets[j].push_back(i);
  }
  for (auto& m : meets) std::sort(m.begin(), m.end());
  return meets;
}

}  // namespace uabt::verify::detail
