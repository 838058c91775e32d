#include "verify/impact.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "smt/assign.hpp"
#include "smt/atoms.hpp"
#include "smt/encoder.hpp"
#include "smt/evaluate.hpp"
#include "smt/solver.hpp"
#include "verify/coverage_parts.hpp"
#include "verify/space.hpp"

namespace uabt::verify {

namespace {

struct Choice {
  const fretish::Expr* guard;  // nullptr: default
  std::string alternative;
  std::string requirement;
};

std::vector<Choice> choices_of(const load::Mission& m, const std::string& adaptable) {
  std::vector<Choice> out;
  for (const auto* s : m.selections_for(adaptable))
    out.push_back({s->guard.get(), s->alternative, s->id});
  return out;
}

fretish::Domain merged_domain(const load::Mission& before, const load::Mission& after) {
  fretish::Domain d = after.domain;
  for (const auto& v : before.domain.variables)
    if (d.find(v.name) == nullptr) d.variables.push_back(v);
  return d;
}

using detail::Bits;

// Where each alternative is selected (the first choice whose guard holds) within `domain`;
// "": where none holds and the node fails. A guard that has no value in a state (a division
// by zero) does not hold there.
std::map<std::string, Bits> selected(detail::Space& space, const std::vector<Choice>& choices,
                                     const Bits& domain) {
  const std::uint64_t size = space.size();
  std::map<std::string, Bits> out;
  Bits claimed(size, false);
  for (const auto& c : choices) {
    const Bits enabled = c.guard ? space.truth(*c.guard).sure : Bits(size, true);
    Bits& at = out.try_emplace(c.alternative, size, false).first->second;
    at = at | (enabled & domain & ~claimed);
    claimed = claimed | enabled;
  }
  Bits& none = out.try_emplace("", size, false).first->second;
  none = none | (domain & ~claimed);
  return out;
}

// Counts (discrete variables) or measures (real ones) the states whose selection changes, over
// the space of the variables both versions' guards and the assumptions read, cut at the
// boundaries of all their atoms.
void measure_changes(const std::vector<Choice>& old_choices, const std::vector<Choice>& new_choices,
                     const fretish::Domain& domain, const smt::Typing& typing, NodeImpact& impact) {
  std::set<std::string> names;
  std::vector<const fretish::Expr*> atoms, assumptions;
  auto read = [&](const fretish::Expr& e) {
    detail::variables_of(e, typing, names);
    for (const fretish::Expr* a : smt::atom_occurrences(e, typing)) atoms.push_back(a);
  };
  for (const auto* choices : {&old_choices, &new_choices})
    for (const auto& c : *choices)
      if (c.guard) read(*c.guard);
  for (const auto& a : domain.assumptions) {
    const smt::TypeInfo* t = a.expr ? typing.find(*a.expr) : nullptr;
    if (t == nullptr || t->sort != smt::Sort::boolean) continue;
    assumptions.push_back(a.expr.get());
    read(*a.expr);
  }
  detail::Space space(domain, typing);
  NodeImpact out = impact;  // filled in full, or not at all
  try {
    std::string reason = space.plan(names, atoms);
    if (reason.empty()) reason = space.unmeasured();
    if (!reason.empty()) {
      impact.not_counted_reason = reason;
      return;
    }
    Bits in_domain(space.size(), true);
    for (const fretish::Expr* a : assumptions) in_domain = in_domain & space.truth(*a).sure;
    const detail::Fraction whole = space.measure(in_domain);
    if (space.has_reals() && whole.is_zero()) {
      impact.not_counted_reason =
          "the domain has measure zero over the real variable " + space.first_real();
      return;
    }
    const auto from = selected(space, old_choices, in_domain);
    const auto to = selected(space, new_choices, in_domain);
    Bits kept(space.size(), false);
    for (const auto& [alternative, set] : from)
      if (const auto it = to.find(alternative); it != to.end()) kept = kept | (set & it->second);
    const Bits changed = in_domain & ~kept;
    out.measured = true;
    out.changed_share = detail::exact_of(detail::ratio(space.measure(changed), whole));
    for (auto& change : out.changes) {
      const auto f = from.find(change.from), t = to.find(change.to);
      const Bits moved =
          f != from.end() && t != to.end() ? f->second & t->second : Bits(space.size(), false);
      change.share = detail::exact_of(detail::ratio(space.measure(moved), whole));
      if (!space.has_reals()) change.states = moved.count();
    }
    if (space.has_reals()) {
      out.not_counted_reason = "the guards range over the real variable " + space.first_real();
    } else {
      out.counted = true;
      out.states = in_domain.count();
      out.changed_states = changed.count();
    }
  } catch (const detail::FractionOverflow& e) {
    impact.not_counted_reason = e.what();
    return;
  } catch (const smt::EvaluationError& e) {
    impact.not_counted_reason = e.what();
    return;
  }
  impact = std::move(out);
}

}  // namespace

Impact selection_impact(const load::Mission& before, const load::Mission& after,
                        const Options& options) {
  Impact result;
  std::vector<std::string> ids;
  auto add_ids = [&](const load::Mission& m) {
    for (const auto& site : m.adaptables)
      if (!site.id.empty() && std::find(ids.begin(), ids.end(), site.id) == ids.end())
        ids.push_back(site.id);
  };
  add_ids(after);
  add_ids(before);

  const fretish::Domain domain = merged_domain(before, after);
  smt::Encoder encoder(domain);
  z3::context& ctx = encoder.context();
  std::vector<Finding> type_findings;
  const auto parts = encoder.domain_parts(type_findings);

  for (const auto& id : ids) {
    NodeImpact impact;
    impact.adaptable = id;
    const auto old_choices = choices_of(before, id);
    const auto new_choices = choices_of(after, id);
    if (old_choices.empty() && new_choices.empty()) continue;
    if (old_choices.empty() || new_choices.empty()) {
      impact.status = old_choices.empty() ? "added" : "removed";
      result.nodes.push_back(std::move(impact));
      continue;
    }

    // The alternative each version selects, as an integer term: -1 when none.
    std::map<std::string, int> code;
    auto code_of = [&](const std::string& alt) {
      return code.emplace(alt, static_cast<int>(code.size())).first->second;
    };
    bool lowered = true;
    auto selection_term = [&](const load::Mission& m, const std::vector<Choice>& choices) {
      z3::expr term = ctx.int_val(-1);
      for (std::size_t i = choices.size(); i-- > 0;) {
        const Choice& c = choices[i];
        z3::expr value = ctx.int_val(code_of(c.alternative));
        if (c.guard == nullptr) {
          term = value;
          continue;
        }
        const auto* s = m.selections_for(id)[i];
        auto g = encoder.lower_condition(*c.guard, s->guard_location, result.findings);
        if (!g) {
          lowered = false;
          continue;
        }
        smt::assign(term, z3::ite(*g, value, term));
      }
      return term;
    };
    z3::expr old_sel = selection_term(before, old_choices);
    z3::expr new_sel = selection_term(after, new_choices);
    if (!lowered) {
      impact.status = "changed";
      impact.not_counted_reason = "a guard is ill-typed over the new domain";
      result.nodes.push_back(std::move(impact));
      continue;
    }
    std::map<int, std::string> name_of;
    for (const auto& [alt, n] : code) name_of[n] = alt;
    auto requirement_of = [](const std::vector<Choice>& choices, const std::string& alt) {
      for (const auto& c : choices)
        if (c.alternative == alt) return c.requirement;
      return std::string();
    };

    smt::Solver solver(ctx, options.timeout_ms);
    for (const auto& part : parts) solver.add(part.constraint);
    solver.add(old_sel != new_sel);
    // Each answer names one (from, to) pair; blocking it asks for the next.
    for (;;) {
      const z3::check_result answer = solver.check();
      if (answer == z3::unsat) break;
      if (answer == z3::unknown) {
        Finding f = make_finding("verification-inconclusive",
                                 "the impact of the uplink on '" + id +
                                     "' could not be decided: " + solver.reason_unknown(),
                                 {after.requirements_file, 0, 0});
        f.adaptable = id;
        result.findings.push_back(std::move(f));
        break;
      }
      z3::model model = solver.model();
      const int from = model.eval(old_sel, true).get_numeral_int();
      const int to = model.eval(new_sel, true).get_numeral_int();
      SelectionChange change;
      change.from = from < 0 ? "" : name_of[from];
      change.to = to < 0 ? "" : name_of[to];
      change.from_requirement = requirement_of(old_choices, change.from);
      change.to_requirement = requirement_of(new_choices, change.to);
      change.example = encoder.state_of(model);
      impact.changes.push_back(std::move(change));
      solver.add(!(old_sel == ctx.int_val(from) && new_sel == ctx.int_val(to)));
    }
    std::sort(impact.changes.begin(), impact.changes.end(),
              [](const SelectionChange& a, const SelectionChange& b) {
                return std::tie(a.from, a.to) < std::tie(b.from, b.to);
              });
    impact.status = impact.changes.empty() ? "unchanged" : "changed";
    measure_changes(old_choices, new_choices, domain, encoder.typing(), impact);
    result.nodes.push_back(std::move(impact));
  }
  result.findings.insert(result.findings.end(), type_findings.begin(), type_findings.end());
  return result;
}

}  // namespace uabt::verify
