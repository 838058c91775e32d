#include "verify/impact.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "base/number_fit.hpp"
#include "smt/assign.hpp"
#include "smt/encoder.hpp"
#include "smt/evaluate.hpp"
#include "smt/solver.hpp"

namespace uabt::verify {

namespace {

constexpr std::uint64_t kMaxCountedStates = std::uint64_t{1} << 24;

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

// First enabled choice in a state, evaluated without the solver (for counting).
std::optional<std::size_t> selected(const std::vector<Choice>& choices,
                                    const fretish::Domain& domain, const State& state) {
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i].guard == nullptr) return i;
    auto holds = smt::try_evaluate(*choices[i].guard, domain, state);
    if (holds.value_or(false)) return i;
  }
  return std::nullopt;
}

// Exact counts by enumeration over the discrete variables the two versions read.
void count_changes(const std::vector<Choice>& old_choices, const std::vector<Choice>& new_choices,
                   const fretish::Domain& domain, NodeImpact& impact) {
  std::set<std::string> used;
  auto collect = [&](const fretish::Expr& e) {
    for (const auto& name : fretish::identifiers_of(e))
      if (domain.find(name) != nullptr) used.insert(name);
  };
  for (const auto& c : old_choices)
    if (c.guard) collect(*c.guard);
  for (const auto& c : new_choices)
    if (c.guard) collect(*c.guard);
  for (const auto& a : domain.assumptions)
    if (a.expr) collect(*a.expr);

  struct Axis {
    const fretish::Variable* variable;
    std::vector<Value> values;
  };
  std::vector<Axis> axes;
  std::uint64_t total = 1;
  for (const auto& v : domain.variables) {
    if (!used.count(v.name)) continue;
    Axis axis{&v, {}};
    switch (v.type) {
      case fretish::VarType::boolean:
        axis.values = {Value::of_bool(false), Value::of_bool(true)};
        break;
      case fretish::VarType::enumeration:
        for (const auto& lit : v.enum_values) axis.values.push_back(Value::of_enum(lit));
        break;
      case fretish::VarType::integer: {
        if (v.lower.empty() || v.upper.empty()) {
          impact.not_counted_reason = "'" + v.name + "' is an unbounded integer";
          return;
        }
        long long lo = 0, hi = 0;
        try {
          lo = std::stoll(v.lower);
          hi = std::stoll(v.upper);
        } catch (...) {
          impact.not_counted_reason = "the bounds of '" + v.name + "' are not integers";
          return;
        }
        const std::optional<std::uint64_t> size = integer_range_size(lo, hi);
        if (!size || *size > kMaxCountedStates) {
          impact.not_counted_reason = "'" + v.name + "' has too many values to count";
          return;
        }
        for (std::uint64_t i = 0; i < *size; ++i)
          axis.values.push_back(Value::of_int(lo + static_cast<long long>(i)));
        break;
      }
      case fretish::VarType::real:
        impact.not_counted_reason = "'" + v.name + "' is a real number";
        return;
    }
    if (axis.values.empty()) return;
    total *= axis.values.size();
    if (total > kMaxCountedStates) {
      impact.not_counted_reason = "more than 2^24 states";
      return;
    }
    axes.push_back(std::move(axis));
  }

  std::map<std::pair<std::string, std::string>, std::uint64_t> counts;
  std::vector<std::size_t> index(axes.size(), 0);
  State state;
  for (const auto& axis : axes) state.push_back({axis.variable->name, axis.values[0]});
  std::uint64_t states = 0, changed = 0;
  for (std::uint64_t n = 0; n < total; ++n) {
    for (std::size_t k = 0; k < axes.size(); ++k) state[k].second = axes[k].values[index[k]];
    bool in_domain = true;
    for (const auto& a : domain.assumptions)
      if (a.expr && !smt::try_evaluate(*a.expr, domain, state).value_or(false)) in_domain = false;
    if (in_domain) {
      ++states;
      auto o = selected(old_choices, domain, state);
      auto w = selected(new_choices, domain, state);
      const std::string from = o ? old_choices[*o].alternative : "";
      const std::string to = w ? new_choices[*w].alternative : "";
      if (from != to) {
        ++changed;
        ++counts[{from, to}];
      }
    }
    for (std::size_t k = 0; k < axes.size(); ++k) {  // odometer
      if (++index[k] < axes[k].values.size()) break;
      index[k] = 0;
    }
  }
  impact.counted = true;
  impact.states = states;
  impact.changed_states = changed;
  for (auto& change : impact.changes) change.states = counts[{change.from, change.to}];
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
    count_changes(old_choices, new_choices, domain, impact);
    result.nodes.push_back(std::move(impact));
  }
  result.findings.insert(result.findings.end(), type_findings.begin(), type_findings.end());
  return result;
}

}  // namespace uabt::verify
