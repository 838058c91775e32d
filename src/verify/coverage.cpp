#include "verify/coverage.hpp"

#include <map>
#include <set>
#include <string>

#include "smt/atoms.hpp"
#include "smt/evaluate.hpp"
#include "verify/coverage_parts.hpp"
#include "verify/region.hpp"
#include "verify/space.hpp"

namespace uabt::verify::detail {

using fretish::Expr;

Exact exact_of(const Fraction& f) {
  return {f.text(), f.to_double()};
}

Fraction ratio(const Fraction& part, const Fraction& whole) {
  return whole.is_zero() ? Fraction(0) : part / whole;
}

namespace {

// The measure of the states the domain surely and possibly has: taken once per node, since
// measuring costs a pass over the space (with 10,000 guards, once per guard was most of verify).
struct DomainMeasure {
  Fraction sure, maybe;
};

// Certified bounds of a share when some atom is not measured: the part that surely belongs
// over the largest possible domain, and the part that may belong over the smallest.
void bounds(const Space& space, const Truth& part, const DomainMeasure& domain, Exact& lower,
            Exact& upper) {
  const Fraction &dl = domain.sure, &du = domain.maybe;
  lower = exact_of(ratio(space.measure(part.sure), du));
  Fraction hi = dl.is_zero() ? Fraction(1) : space.measure(part.maybe) / dl;
  if (hi > Fraction(1)) hi = Fraction(1);
  upper = exact_of(hi);
}

void conjuncts(const Expr& e, const smt::Typing& typing, std::vector<const Expr*>& out) {
  if (e.kind == fretish::ExprKind::logical_and && smt::is_boolean_structure(e, typing)) {
    for (const auto& a : e.args) conjuncts(*a, typing, out);
    return;
  }
  out.push_back(&e);
}

// A guard as cells of a decision table: each conjunct over one variable goes to its column.
void decision_cells(const Expr& guard, const fretish::Domain& domain, const smt::Typing& typing,
                    const std::vector<std::string>& columns, AlternativeCoverage& alt) {
  std::vector<const Expr*> parts;
  conjuncts(guard, typing, parts);
  std::map<std::string, std::vector<CubeLiteral>> by_variable;
  for (const Expr* p : parts) {
    const Expr* atom = p;
    bool positive = true;
    while (atom->kind == fretish::ExprKind::logical_not &&
           smt::is_boolean_structure(*atom, typing)) {
      atom = atom->args[0].get();
      positive = !positive;
    }
    std::set<std::string> vars;
    variables_of(*atom, typing, vars);
    if (vars.size() == 1 && !smt::is_boolean_structure(*atom, typing)) {
      by_variable[*vars.begin()].push_back({atom, positive});
      continue;
    }
    alt.other_condition += (alt.other_condition.empty() ? "" : " & ") + fretish::to_fretish(*p);
  }
  for (const auto& name : columns) {
    auto it = by_variable.find(name);
    if (it == by_variable.end()) continue;
    std::string cell = render_cube(it->second, domain, typing);
    if (cell == name)
      cell = "true";
    else if (cell == "!" + name)
      cell = "false";
    else if (cell.rfind(name + " ", 0) == 0 && cell.find(" & ") == std::string::npos)
      cell = cell.substr(name.size() + 1);
    alt.cells.emplace_back(name, cell);
  }
}

// Nothing but the reason, the variables and the decision table survive a failed count.
void give_up(Coverage& cov, const std::string& reason) {
  Coverage fresh;
  fresh.adaptable = cov.adaptable;
  fresh.not_counted_reason = fresh.not_measured_reason = reason;
  fresh.variables = cov.variables;
  for (const auto& a : cov.alternatives) {
    AlternativeCoverage b;
    b.name = a.name;
    b.requirement = a.requirement;
    b.cells = a.cells;
    b.other_condition = a.other_condition;
    fresh.alternatives.push_back(std::move(b));
  }
  cov = std::move(fresh);
}

}  // namespace

std::vector<const Expr*> link_assumptions(const std::vector<const Expr*>& assumptions,
                                          const smt::Typing& typing, std::set<std::string>& names,
                                          std::vector<const Expr*>& atoms) {
  std::vector<const Expr*> linked;
  std::vector<bool> used(assumptions.size(), false);
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t k = 0; k < assumptions.size(); ++k) {
      if (used[k]) continue;
      std::set<std::string> own;
      variables_of(*assumptions[k], typing, own);
      bool touches = own.empty();
      for (const auto& n : own) touches = touches || names.count(n) > 0;
      if (!touches) continue;
      used[k] = grew = true;
      linked.push_back(assumptions[k]);
      names.insert(own.begin(), own.end());
      for (const Expr* a : smt::atom_occurrences(*assumptions[k], typing)) atoms.push_back(a);
    }
  }
  return linked;
}

Coverage count_coverage(const std::string& adaptable,
                        const std::vector<const fretish::SelectionRequirement*>& requirements,
                        const std::vector<const Expr*>& assumptions, const fretish::Domain& domain,
                        const smt::Typing& typing, const std::vector<Finding>& findings) {
  Coverage cov;
  cov.adaptable = adaptable;
  for (const auto* r : requirements) {
    AlternativeCoverage a;
    a.name = r->alternative;
    a.requirement = r->id;
    cov.alternatives.push_back(a);
  }
  // The guards' variables, closed under "an assumption links them": other assumptions only
  // constrain other variables and, the domain being consistent, do not change the shares.
  std::set<std::string> names;
  std::vector<const Expr*> atoms;
  for (const auto* r : requirements) {
    if (!r->guard) continue;
    variables_of(*r->guard, typing, names);
    for (const Expr* a : smt::atom_occurrences(*r->guard, typing)) atoms.push_back(a);
  }
  const std::vector<const Expr*> linked = link_assumptions(assumptions, typing, names, atoms);
  for (const auto& v : domain.variables)
    if (names.count(v.name)) cov.variables.push_back(v.name);
  for (const auto& n : names)
    if (domain.find(n) == nullptr) cov.variables.push_back(n);
  for (std::size_t k = 0; k < requirements.size(); ++k)
    if (requirements[k]->guard)
      decision_cells(*requirements[k]->guard, domain, typing, cov.variables, cov.alternatives[k]);

  Space space(domain, typing);
  std::string reason;
  try {
    reason = space.plan(names, atoms);
  } catch (const FractionOverflow& e) {
    reason = e.what();
  }
  if (!reason.empty()) {
    cov.not_counted_reason = cov.not_measured_reason = reason;
    return cov;
  }
  const std::uint64_t size = space.size();
  try {
    NodeTruths t;
    // Enum membership and ranges are built into the enumeration; assumptions are filtered.
    t.domain = Truth::exactly(Bits(size, true), Bits(size, false));
    for (const Expr* a : linked) {
      const Truth at = space.truth(*a);
      if ((t.domain.maybe & at.none).any())
        throw smt::EvaluationError("an assumption has no value in some state (division by zero)");
      t.domain = junction(true, {t.domain, at}, size);
    }
    const DomainMeasure domain_measure{space.measure(t.domain.sure), space.measure(t.domain.maybe)};
    const Truth none_yet = Truth::exactly(Bits(size, false), Bits(size, false));
    Truth any = none_yet, claimed = none_yet;
    t.overlap = none_yet;
    for (std::size_t k = 0; k < requirements.size(); ++k) {
      const auto* r = requirements[k];
      Truth enabled = t.domain;
      if (r->guard) {
        const Truth g = space.truth(*r->guard);
        if ((t.domain.maybe & g.none).any())
          throw smt::EvaluationError("the guard of " + r->id +
                                     " has no value in some state (division by zero)");
        enabled = junction(true, {g, t.domain}, size);
      }
      const Truth selected = junction(true, {enabled, negation(claimed)}, size);
      auto& alt = cov.alternatives[k];
      alt.enabled_states = enabled.sure.count();
      alt.states = selected.sure.count();
      alt.measure = exact_of(space.measure(selected.sure));
      bounds(space, selected, domain_measure, alt.share_lower, alt.share_upper);
      alt.share = alt.share_lower;
      alt.enabled_share = exact_of(ratio(space.measure(enabled.sure), domain_measure.sure));
      t.enabled.push_back(enabled);
      claimed = junction(false, {claimed, enabled}, size);
      if (r->guard) {
        t.overlap = junction(false, {t.overlap, junction(true, {any, enabled}, size)}, size);
        any = junction(false, {any, enabled}, size);
      }
    }
    t.gap = junction(true, {t.domain, negation(claimed)}, size);
    const Fraction& total = domain_measure.sure;
    cov.measure = exact_of(total);
    cov.gap_measure = exact_of(space.measure(t.gap.sure));
    cov.overlap_measure = exact_of(space.measure(t.overlap.sure));
    bounds(space, t.gap, domain_measure, cov.gap_share_lower, cov.gap_share_upper);
    bounds(space, t.overlap, domain_measure, cov.overlap_share_lower, cov.overlap_share_upper);
    cov.gap_share = cov.gap_share_lower;
    cov.overlap_share = cov.overlap_share_lower;
    cov.measured = space.unmeasured().empty();
    cov.bounded = !cov.measured;
    if (!cov.measured) cov.not_measured_reason = space.unmeasured();
    if (!space.has_reals()) {
      cov.counted = true;
      cov.states = t.domain.sure.count();
      cov.gap_states = t.gap.sure.count();
      cov.overlap_states = t.overlap.sure.count();
    } else {
      for (auto& a : cov.alternatives) a.states = a.enabled_states = 0;
      cov.not_counted_reason = "the guards range over the real variable " + space.first_real();
    }
    fill_regions(space, requirements, t, findings, cov);
    fill_map(space, domain, t, requirements.size(), cov);
  } catch (const smt::EvaluationError& e) {
    give_up(cov, e.what());
  } catch (const FractionOverflow& e) {
    give_up(cov, e.what());
  }
  return cov;
}

}  // namespace uabt::verify::detail
