// The targets of a node whose space cannot be enumerated (more states than the coverage stage
// takes, or conditions its cells cannot decide), each solved with Z3 over the node's variables,
// ranges and assumptions: the same targets, ids, texts and reasons as the enumerated ones.
#include <z3++.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "base/number_text.hpp"
#include "campaign/campaign.hpp"
#include "campaign/node.hpp"
#include "fretish/build_expression.hpp"
#include "smt/assign.hpp"
#include "smt/encoder.hpp"
#include "smt/solver.hpp"
#include "verify/linear.hpp"

namespace uabt::campaign {

using verify::detail::Fraction;
using Goal = Model::Node::Goal;

namespace {

constexpr unsigned kTimeoutMs = 10000;
// Each atom costs a few questions, its MC/DC one over all the others: beyond this many the
// node is not solved (no hang).
constexpr std::size_t kMaxAtoms = 2048;

std::optional<Fraction> bound(const std::string& text) {
  if (text.empty()) return std::nullopt;
  return Fraction::parse(text);
}

}  // namespace

// One node's questions: the node's variables, a primed copy of them (MC/DC pairs), the domain,
// the guards and the atoms, lowered once; kept with the node to solve a goal again.
class SolvedQuestions {
 public:
  enum class Answer { sat, unsat, unknown };

  SolvedQuestions(Model::Node& node, const fretish::Domain& dom)
      : node_(node),
        dom_(dom),
        enc_(dom),
        solver_(enc_.context(), kTimeoutMs),
        vars_(enc_.context()),
        primes_(enc_.context()),
        domain_(enc_.context().bool_val(true)),
        sel_(enc_.context().int_val(-1)),
        sel2_(enc_.context().int_val(-1)) {}

  // False (with `reason`) when a condition does not lower.
  bool lower(std::string& reason) {
    std::vector<Finding> ignored;
    z3::context& ctx = enc_.context();
    for (const auto* r : node_.reqs) {
      if (!r->guard) {
        guards_.push_back(ctx.bool_val(true));
        continue;
      }
      auto g = enc_.lower_condition(*r->guard, r->guard_location, ignored);
      if (!g) {
        reason = "the guard of " + r->id + " does not type-check";
        return false;
      }
      guards_.push_back(*g);
    }
    for (const auto* a : node_.atom_expr) {
      auto e = enc_.lower_condition(*a, {}, ignored);
      if (!e) {
        reason = "the atom " + fretish::to_fretish(*a) + " does not type-check";
        return false;
      }
      atoms_.push_back(*e);
    }
    z3::expr_vector parts(ctx);
    for (const auto* a : node_.linked)
      if (auto e = enc_.lower_condition(*a, {}, ignored)) parts.push_back(*e);
    // The ranges of the node's variables ("x in [0, 5]", "t in {p, q}").
    for (const auto& part : enc_.domain_parts(ignored)) {
      const auto space = part.description.find(" in ");
      if (space != std::string::npos && node_.names.count(part.description.substr(0, space)))
        parts.push_back(part.constraint);
    }
    if (!parts.empty()) smt::assign(domain_, z3::mk_and(parts));
    for (const auto& name : order()) {
      const smt::Encoder::Slot* slot = enc_.find_slot(name);
      if (slot == nullptr) continue;
      vars_.push_back(slot->constant);
      primes_.push_back(ctx.constant(("uabt!pair!" + name).c_str(), slot->constant.get_sort()));
    }
    for (std::size_t k = node_.reqs.size(); k-- > 0;) {
      smt::assign(sel_, z3::ite(guards_[k], ctx.int_val(static_cast<int>(k)), sel_));
      smt::assign(sel2_, z3::ite(primed(guards_[k]), ctx.int_val(static_cast<int>(k)), sel2_));
    }
    return true;
  }

  // The node's variables in the domain's declaration order, implicit booleans last by name.
  std::vector<std::string> order() const {
    std::vector<std::string> out;
    for (const auto& v : dom_.variables)
      if (node_.names.count(v.name)) out.push_back(v.name);
    for (const auto& n : node_.names)
      if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    return out;
  }

  z3::expr primed(const z3::expr& e) {
    z3::expr copy = e;
    return copy.substitute(vars_, primes_);
  }

  // Asks whether the formulas hold together with the domain; on sat, the state (and the
  // primed state when `pair`) is added to the node's states, its index in `witness`.
  Answer ask(const std::vector<z3::expr>& formulas, std::vector<std::size_t>* witness = nullptr,
             bool pair = false) {
    solver_.push();
    solver_.add(domain_);
    if (pair) solver_.add(primed(domain_));
    for (const auto& f : formulas) solver_.add(f);
    const z3::check_result r = solver_.check();
    Answer out = r == z3::sat ? Answer::sat : r == z3::unsat ? Answer::unsat : Answer::unknown;
    if (out == Answer::sat && witness != nullptr) {
      const z3::model m = solver_.model();
      witness->push_back(add_state(m, vars_));
      if (pair) witness->push_back(add_state(m, primes_));
    }
    if (out == Answer::unknown) unknown_ = solver_.reason_unknown();
    solver_.pop();
    return out;
  }

  // A real target: first with the variable at a number that reads well.
  Answer ask_real(const std::vector<z3::expr>& formulas, const z3::expr& var,
                  const std::optional<Fraction>& nice, std::vector<std::size_t>& witness) {
    if (nice) {
      std::vector<z3::expr> pinned = formulas;
      pinned.push_back(var == fraction(*nice));
      if (ask(pinned, &witness) == Answer::sat) return Answer::sat;
    }
    return ask(formulas, &witness);
  }

  z3::expr fraction(const Fraction& x) { return enc_.context().real_val(x.text().c_str()); }
  z3::context& ctx() { return enc_.context(); }
  const z3::expr& guard(std::size_t k) const { return guards_[k]; }
  const z3::expr& atom(std::size_t a) const { return atoms_[a]; }
  const z3::expr& sel() const { return sel_; }
  const z3::expr& sel2() const { return sel2_; }
  const smt::Encoder::Slot* slot(const std::string& name) const { return enc_.find_slot(name); }
  const std::string& unknown() const { return unknown_; }

 private:
  std::size_t add_state(const z3::model& m, const z3::expr_vector& vars) {
    State state;
    const auto names = order();
    std::size_t v = 0;
    for (const auto& name : names) {
      const smt::Encoder::Slot* slot = enc_.find_slot(name);
      if (slot == nullptr) continue;
      const z3::expr value = m.eval(vars[static_cast<int>(v++)], true);
      switch (slot->sort) {
        case smt::Sort::boolean: state.emplace_back(name, Value::of_bool(value.is_true())); break;
        case smt::Sort::integer: {
          std::int64_t i = 0;
          if (!value.is_numeral_i64(i))
            throw std::runtime_error("the solver chose a value of " + name +
                                     " beyond 64 bits: " + value.get_decimal_string(0));
          state.emplace_back(name, Value::of_int(i));
          break;
        }
        case smt::Sort::real: {
          std::int64_t n = 0, d = 1;
          if (value.is_numeral() && value.numerator().is_numeral_i64(n) &&
              value.denominator().is_numeral_i64(d) && d != 0)
            state.emplace_back(name, real_value(Fraction::of(n, d)));
          else
            throw std::runtime_error(
                "the solver chose a value of " + name +
                " that is not a 64-bit fraction: " + value.get_decimal_string(12));
          break;
        }
        case smt::Sort::enumeration: {
          std::int64_t i = 0;
          value.is_numeral_i64(i);
          const auto& values = slot->declaration->enum_values;
          state.emplace_back(name,
                             Value::of_enum(i >= 0 && static_cast<std::size_t>(i) < values.size()
                                                ? values[static_cast<std::size_t>(i)]
                                                : values.front()));
          break;
        }
        case smt::Sort::invalid: break;
      }
    }
    node_.solved->states.push_back(std::move(state));
    return node_.solved->states.size() - 1;
  }

  // The n-th try's value of a variable: a bounded number at the n-th point of the van der
  // Corput sequence over its range (1/2, 1/4, 3/4, 1/8, ...), a truth value or a literal other
  // than the last try's.
  std::optional<z3::expr> spread(const std::string& name, const State& last, std::size_t n,
                                 bool primed_copy) {
    const smt::Encoder::Slot* slot = enc_.find_slot(name);
    const Value* before = find_value(last, name);
    if (slot == nullptr || before == nullptr) return std::nullopt;
    const z3::expr var = primed_copy ? primed(slot->constant) : slot->constant;
    if (slot->sort == smt::Sort::boolean) return var == ctx().bool_val(!before->boolean);
    if (slot->sort == smt::Sort::enumeration) {
      const auto& values = slot->declaration->enum_values;
      const auto it = std::find(values.begin(), values.end(), before->text);
      const auto next = (static_cast<std::size_t>(it - values.begin()) + 1) % values.size();
      return var == ctx().int_val(static_cast<int>(next));
    }
    const auto lo = bound(slot->declaration->lower), hi = bound(slot->declaration->upper);
    if (!lo || !hi) return std::nullopt;
    __int128 num = 0, den = 1;
    for (std::size_t m = n; m > 0 && den < (__int128{1} << 60); m /= 2) {
      num = 2 * num + static_cast<__int128>(m % 2);
      den *= 2;
    }
    try {
      const Fraction x = *lo + (*hi - *lo) * Fraction::of(num, den);
      if (slot->sort == smt::Sort::integer) {
        const __int128 i = x.floor();
        if (i < INT64_MIN || i > INT64_MAX) return std::nullopt;
        return var == ctx().int_val(static_cast<std::int64_t>(i));
      }
      return var == fraction(x);
    } catch (const verify::detail::FractionOverflow&) {
      return std::nullopt;
    }
  }

  // A state's values as a formula over the variables (primed: over their copy).
  z3::expr same_as(const State& state, const std::string& name, bool primed_copy) {
    const smt::Encoder::Slot* slot = enc_.find_slot(name);
    const Value* v = find_value(state, name);
    if (slot == nullptr || v == nullptr) return ctx().bool_val(false);
    z3::expr var = primed_copy ? primed(slot->constant) : slot->constant;
    switch (slot->sort) {
      case smt::Sort::boolean: return var == ctx().bool_val(v->boolean);
      case smt::Sort::integer: return var == ctx().int_val(v->integer);
      case smt::Sort::real: return var == ctx().real_val(v->text.c_str());
      case smt::Sort::enumeration: {
        const auto& values = slot->declaration->enum_values;
        const auto it = std::find(values.begin(), values.end(), v->text);
        return var == ctx().int_val(static_cast<int>(it - values.begin()));
      }
      case smt::Sort::invalid: break;
    }
    return ctx().bool_val(false);
  }

 public:
  // Per goal: the formulas its witness satisfies, and whether it is a pair.
  std::vector<std::pair<std::vector<z3::expr>, bool>> goal_questions;

  // Solves goal `k` again away from the excluded states: another state (each side of a pair),
  // spread over the ranges where the goal allows it (a state that did not reach the node may
  // fail for any of its values): each variable at a value the tries have not had, the middle
  // of its range first, then the quarters, ... False when no other state reaches it.
  bool retry(std::size_t k, const std::set<std::uint64_t>& excluded) {
    Goal& goal = node_.solved->goals[k];
    const auto& [formulas, pair] = goal_questions[k];
    std::vector<z3::expr> away = formulas;
    for (std::uint64_t e : excluded) {
      const State avoid = node_.solved->states[e];
      for (bool primed_copy : {false, true}) {
        if (primed_copy && !pair) continue;
        z3::expr_vector differ(ctx());
        for (const auto& name : order()) differ.push_back(!same_as(avoid, name, primed_copy));
        if (!differ.empty()) away.push_back(z3::mk_or(differ));
      }
    }
    const State last = excluded.empty() ? State{} : node_.solved->states[*excluded.rbegin()];
    for (const auto& name : order())
      for (bool primed_copy : {false, true}) {
        if (primed_copy && !pair) continue;
        const auto pin = spread(name, last, excluded.size(), primed_copy);
        if (!pin) continue;
        away.push_back(*pin);
        if (ask(away) != Answer::sat) away.pop_back();
      }
    std::vector<std::size_t> witness;
    if (ask(away, &witness, pair) != Answer::sat) return false;
    goal.witness = witness;
    return true;
  }

 private:
  Model::Node& node_;
  const fretish::Domain& dom_;
  smt::Encoder enc_;
  smt::Solver solver_;
  z3::expr_vector vars_, primes_;
  z3::expr domain_;
  std::vector<z3::expr> guards_, atoms_;
  z3::expr sel_, sel2_;
  std::string unknown_;
};

using Answer = SolvedQuestions::Answer;
using Questions = SolvedQuestions;

namespace {

// The target is not decided: the solver gave no answer.
void undecided(Target& t, const Questions& q) {
  t.reachable = false;
  t.undecided = true;
  t.reason = "the solver gave no answer (" + q.unknown() + ")";
}

}  // namespace

bool Model::Node::solve(const load::Mission& mission, const std::set<Criterion>& criteria,
                        const std::string& why, std::vector<Target>& all, std::string& failure) {
  solved = std::make_unique<Solved>();
  solved->why = why;
  solved->domain = &mission.domain;
  space.reset();
  enabled.clear();
  selected.clear();
  column.clear();
  inverted.clear();
  solved->questions = std::make_shared<SolvedQuestions>(*this, mission.domain);
  Questions& q = *solved->questions;
  std::string reason;
  std::vector<Goal> goals;
  std::vector<Target> targets;
  auto add = [&](Target t, Goal g, Answer answer, std::vector<z3::expr> formulas, bool pair) {
    q.goal_questions.emplace_back(std::move(formulas), pair);
    if (answer == Answer::unknown) undecided(t, q);
    if (answer != Answer::sat) {
      t.reachable = false;
      g.witness.clear();
    }
    for (std::size_t w : g.witness) t.witness.push_back(solved->states[w]);
    g.target = all.size() + targets.size();
    targets.push_back(std::move(t));
    goals.push_back(std::move(g));
  };
  try {
    if (!q.lower(reason)) throw std::runtime_error(reason);
    {
      std::vector<std::size_t> w;
      if (q.ask({}, &w) == Answer::sat) solved->first = solved->states[w.front()];
    }
    // Atoms that hold exactly where another does (or does not) are one column, as enumerated.
    // Only atoms whose variables the assumptions tie together can be one condition, or two
    // atoms that never change: each is compared with those, not with every other.
    if (atom_expr.size() > kMaxAtoms)
      throw std::runtime_error(std::to_string(atom_expr.size()) + " atoms, more than " +
                               std::to_string(kMaxAtoms) + " to solve one by one");
    std::map<std::string, std::string> group;  // variable -> the first of its group
    auto find = [&](std::string v) {
      while (group.count(v) && group[v] != v) v = group[v];
      return v;
    };
    for (const auto* a : linked) {
      std::set<std::string> vars;
      verify::detail::variables_of(*a, typing, vars);
      for (const auto& v : vars) group[find(v)] = find(*vars.begin());
    }
    std::vector<std::set<std::string>> kinds;  // per atom: its variables' groups, or constant
    for (std::size_t a = 0; a < atom_expr.size(); ++a) {
      std::set<std::string> vars, groups;
      verify::detail::variables_of(*atom_expr[a], typing, vars);
      for (const auto& v : vars) groups.insert(find(v));
      if (q.ask({q.atom(a)}) != Answer::sat || q.ask({!q.atom(a)}) != Answer::sat)
        groups = {"\n"};  // no variable name: the atoms that never change
      kinds.push_back(std::move(groups));
    }
    for (std::size_t a = 0; a < atom_expr.size(); ++a) {
      std::size_t c = 0;
      bool flip = false;
      for (; c < solved->column_atom.size(); ++c) {
        if (kinds[solved->column_atom[c]] != kinds[a]) continue;
        const z3::expr& other = q.atom(solved->column_atom[c]);
        if (q.ask({q.atom(a) != other}) == Answer::unsat) break;
        if (q.ask({q.atom(a) == other}) == Answer::unsat) {
          flip = true;
          break;
        }
      }
      if (c == solved->column_atom.size()) solved->column_atom.push_back(a);
      column.push_back(c);
      inverted.push_back(flip);
    }
    if (criteria.count(Criterion::decision)) {
      for (std::size_t k = 0; k < reqs.size(); ++k) {
        Target t = select_target(adaptable, *reqs[k]);
        Goal g;
        g.kind = Goal::Kind::select;
        g.req = k;
        const std::vector<z3::expr> selects{q.sel() == q.ctx().int_val(static_cast<int>(k))};
        const Answer answer = q.ask(selects, &g.witness);
        if (answer == Answer::unsat) {
          const bool guard_holds = q.ask({q.guard(k)}) != Answer::unsat;
          std::vector<std::string> earlier;
          for (std::size_t j = 0; j < k && guard_holds; ++j)
            if (q.ask({q.guard(j), q.guard(k)}) == Answer::sat) earlier.push_back(reqs[j]->id);
          t.reason = unselectable(*reqs[k], guard_holds, earlier);
        }
        add(std::move(t), std::move(g), answer, selects, false);
      }
      for (std::size_t k = 0; k < reqs.size(); ++k) {
        const auto* r = reqs[k];
        if (!r->guard) continue;
        const std::string guard = fretish::to_fretish(*r->guard);
        for (bool value : {true, false}) {
          Target t = guard_target(adaptable, *r, guard, value);
          Goal g;
          g.kind = Goal::Kind::guard;
          g.req = k;
          g.value = value;
          const std::vector<z3::expr> decides{value ? q.guard(k) : !q.guard(k)};
          const Answer answer = q.ask(decides, &g.witness);
          if (answer == Answer::unsat) t.reason = guard_never(value);
          add(std::move(t), std::move(g), answer, decides, false);
        }
      }
    }
    if (criteria.count(Criterion::mcdc)) {
      for (std::size_t k = 0; k < reqs.size(); ++k) {
        const auto* r = reqs[k];
        for (std::size_t a : req_atoms[k]) {
          const std::string& atom = atom_text[a];
          Target t = mcdc_target(adaptable, *r, atom);
          Goal g;
          g.kind = Goal::Kind::pair;
          g.req = k;
          g.atom = a;
          // From the state where the atom is false to its partner.
          const z3::expr holds = q.atom(a);
          std::vector<z3::expr> alone{!holds, q.primed(holds)};
          for (std::size_t c = 0; c < solved->column_atom.size(); ++c) {
            if (c == column[a]) continue;
            const z3::expr& other = q.atom(solved->column_atom[c]);
            alone.push_back(other == q.primed(other));
          }
          std::vector<z3::expr> flips = alone;
          flips.push_back(q.guard(k) != q.primed(q.guard(k)));
          std::vector<z3::expr> differs = flips;
          differs.push_back(q.sel() != q.sel2());
          const Answer answer = q.ask(differs, &g.witness, true);
          if (answer == Answer::unsat) {
            const bool never = q.ask({holds}) == Answer::unsat;
            const bool always = !never && q.ask({!holds}) == Answer::unsat;
            if (always || never) {
              t.reason = no_pair(NoPair::atom_fixed, atom, r->id, always);
            } else if (q.ask(alone, nullptr, true) == Answer::unsat) {
              t.reason = no_pair(NoPair::atom_tied, atom, r->id);
            } else if (q.ask(flips, nullptr, true) == Answer::unsat) {
              const bool guard_true = q.ask({q.guard(k)}) != Answer::unsat;
              const bool guard_false = q.ask({!q.guard(k)}) != Answer::unsat;
              t.reason =
                  no_pair(guard_true && guard_false ? NoPair::guard_masked : NoPair::guard_fixed,
                          atom, r->id, guard_true);
            } else {
              std::vector<std::string> shadowing;
              for (std::size_t j = 0; j < k; ++j) {
                std::vector<z3::expr> same = flips;
                const z3::expr index = q.ctx().int_val(static_cast<int>(j));
                same.push_back(q.sel() == index);
                same.push_back(q.sel2() == index);
                if (q.ask(same, nullptr, true) == Answer::sat) shadowing.push_back(reqs[j]->id);
              }
              std::sort(shadowing.begin(), shadowing.end());
              t.reason = no_pair(NoPair::same_selection, atom, r->id, false, shadowing);
            }
          }
          add(std::move(t), std::move(g), answer, differs, true);
        }
      }
    }
    if (criteria.count(Criterion::boundary)) {
      // Where a linear atom over one variable changes its value: integers between two values,
      // reals at a breakpoint and in the open intervals beside it.
      std::map<std::string, std::set<std::int64_t>> cuts;
      std::map<std::string, std::set<Fraction>> breaks;
      for (const auto* e : atom_expr) {
        const auto linear = verify::detail::linear_atom(*e, typing);
        if (!linear || linear->coefficients.size() != 1) continue;
        const auto& [name, coefficient] = *linear->coefficients.begin();
        const fretish::Variable* v = mission.domain.find(name);
        if (v == nullptr) continue;
        try {
          const Fraction root = -linear->constant / coefficient;
          if (v->type == fretish::VarType::real) {
            breaks[name].insert(root);
            continue;
          }
          if (v->type != fretish::VarType::integer) continue;
          const __int128 f = root.floor();
          for (__int128 x = f - 1; x <= f; ++x) {
            if (x < INT64_MIN || x >= INT64_MAX) continue;
            // An init-capture: clang before 16 cannot capture a structured binding.
            const auto at = [&, &c = coefficient](__int128 value) {
              return linear->holds_at(c * Fraction::of(value, 1) + linear->constant);
            };
            if (at(x) != at(x + 1)) cuts[name].insert(static_cast<std::int64_t>(x));
          }
        } catch (const verify::detail::FractionOverflow&) {
          continue;  // beyond 128 bits: not a boundary a test can sit at
        }
      }
      auto boundary = [&](Target t, Goal g, const z3::expr& var,
                          const std::optional<Fraction>& nice) {
        g.kind = Goal::Kind::boundary;
        std::vector<z3::expr> where;
        const bool integer = var.is_int();
        auto number = [&](const Fraction& x) {
          return integer ? q.ctx().int_val(static_cast<std::int64_t>(x.numerator()))
                         : q.fraction(x);
        };
        if (g.point) {
          where.push_back(var == number(*g.lo));
        } else {
          if (g.lo) where.push_back(var > number(*g.lo));
          if (g.hi) where.push_back(var < number(*g.hi));
        }
        const Answer answer = q.ask_real(where, var, nice, g.witness);
        if (answer == Answer::unsat) t.reason = kNoStateThere;
        add(std::move(t), std::move(g), answer, where, false);
      };
      std::vector<std::string> reals;
      for (const auto& name : q.order()) {
        const fretish::Variable* v = mission.domain.find(name);
        const smt::Encoder::Slot* slot = q.slot(name);
        if (v == nullptr || slot == nullptr) continue;
        if (v->type == fretish::VarType::real) reals.push_back(name);
        if (v->type != fretish::VarType::integer) continue;
        const auto lo = bound(v->lower), hi = bound(v->upper);
        for (std::int64_t x : cuts[name]) {
          if ((lo && Fraction(x) < *lo) || (hi && Fraction(x) + Fraction(1) > *hi)) continue;
          const std::string below = number_text(x), above = number_text(x + 1);
          for (bool under : {true, false}) {
            Goal g;
            g.variable = name;
            g.point = true;
            g.lo = Fraction(under ? x : x + 1);
            boundary(integer_boundary(adaptable, name, below, above, under), g, slot->constant,
                     std::nullopt);
          }
        }
      }
      for (const auto& name : reals) {
        const fretish::Variable* v = mission.domain.find(name);
        const z3::expr var = q.slot(name)->constant;
        const auto lo = bound(v->lower), hi = bound(v->upper);
        std::vector<std::optional<Fraction>> points;
        points.push_back(lo);
        for (const Fraction& b : breaks[name])
          if ((!lo || b > *lo) && (!hi || b < *hi)) points.emplace_back(b);
        points.push_back(hi);
        auto text = [](const std::optional<Fraction>& x, const char* infinite) {
          return x ? x->decimal() : std::string(infinite);
        };
        for (std::size_t b = 1; b + 1 < points.size(); ++b) {
          const Fraction at = *points[b];
          auto target = [&](int side) {
            return real_boundary(adaptable, name, side, text(points[b - 1], "-inf"), at.decimal(),
                                 text(points[b + 1], "inf"));
          };
          Goal g;
          g.variable = name;
          g.lo = points[b - 1];
          g.hi = at;
          boundary(target(-1), g, var,
                   points[b - 1] ? simple_inside(*points[b - 1], at)
                                 : std::optional<Fraction>(Fraction::of(at.floor() - 1, 1)));
          g.point = true;
          g.lo = at;
          g.hi.reset();
          boundary(target(0), g, var, std::nullopt);
          g.point = false;
          g.lo = at;
          g.hi = points[b + 1];
          boundary(target(1), g, var,
                   points[b + 1] ? simple_inside(at, *points[b + 1])
                                 : std::optional<Fraction>(Fraction::of(at.floor() + 1, 1)));
        }
      }
      // Two real variables a linear atom relates: x + b·y + c = 0 (x declared first), the
      // line and each side of it.
      const std::vector<std::string> declared = q.order();
      auto rank = [&](const std::string& name) {
        return std::find(declared.begin(), declared.end(), name) - declared.begin();
      };
      std::set<std::tuple<std::string, std::string, Fraction, Fraction>> lines;
      for (const auto* e : atom_expr) {
        const auto linear = verify::detail::linear_atom(*e, typing);
        if (!linear || linear->coefficients.size() != 2) continue;
        std::pair<std::string, Fraction> x = *linear->coefficients.begin();
        std::pair<std::string, Fraction> y = *std::next(linear->coefficients.begin());
        const fretish::Variable* vx = mission.domain.find(x.first);
        const fretish::Variable* vy = mission.domain.find(y.first);
        if (vx == nullptr || vy == nullptr || vx->type != fretish::VarType::real ||
            vy->type != fretish::VarType::real)
          continue;
        if (rank(y.first) < rank(x.first)) std::swap(x, y);
        try {
          lines.emplace(x.first, y.first, y.second / x.second, linear->constant / x.second);
        } catch (const verify::detail::FractionOverflow&) {
          continue;
        }
      }
      for (const auto& [x, y, b, c] : lines) {
        const std::string text = line_text(x, b, y);
        const std::string rhs = (-c).decimal();
        const z3::expr lhs =
            q.slot(x)->constant + q.fraction(b) * q.slot(y)->constant + q.fraction(c);
        for (int sign = -1; sign <= 1; ++sign) {
          Target t = line_boundary(adaptable, text, rhs, sign);
          Goal g;
          g.kind = Goal::Kind::boundary;
          g.line = true;
          g.variable = x;
          g.variable2 = y;
          g.slope = b;
          g.offset = c;
          g.sign = sign;
          const std::vector<z3::expr> where{sign < 0 ? lhs < 0 : sign == 0 ? lhs == 0 : lhs > 0};
          const Answer answer = q.ask(where, &g.witness);
          if (answer == Answer::unsat) t.reason = kNoStateThere;
          add(std::move(t), std::move(g), answer, where, false);
        }
      }
    }
  } catch (const std::exception& e) {
    // A value a scenario cannot carry, arithmetic beyond 128 bits: no targets rather than some.
    failure = e.what();
    return false;
  }
  for (auto& t : targets) all.push_back(std::move(t));
  solved->goals = std::move(goals);
  return true;
}

std::optional<State> Model::Node::solved_state(const State& state) const {
  State out;
  for (const auto& name : names) {
    const Value* v = find_value(state, name);
    if (v == nullptr) return std::nullopt;
    const fretish::Variable* decl = solved->domain->find(name);
    if (decl != nullptr && decl->declared) {
      const auto lo = bound(decl->lower), hi = bound(decl->upper);
      if (lo && verify::detail::side_of(*v, *lo).value_or(0) < 0) return std::nullopt;
      if (hi && verify::detail::side_of(*v, *hi).value_or(0) > 0) return std::nullopt;
      if (decl->type == fretish::VarType::enumeration &&
          std::find(decl->enum_values.begin(), decl->enum_values.end(), v->text) ==
              decl->enum_values.end())
        return std::nullopt;
    }
    out.emplace_back(name, *v);
  }
  for (const auto* a : linked)
    if (!solved_holds(*a, out)) return std::nullopt;
  return out;
}

bool Model::Node::solved_holds(const fretish::Expr& condition, const State& state) const {
  return smt::try_evaluate(condition, *solved->domain, state).value_or(false);
}

int Model::Node::solved_selection(const State& state) const {
  for (std::size_t k = 0; k < reqs.size(); ++k)
    if (!reqs[k]->guard || solved_holds(*reqs[k]->guard, state)) return static_cast<int>(k);
  return -1;
}

bool Model::Node::solved_reaches(const Goal& goal, const State& state) const {
  switch (goal.kind) {
    case Goal::Kind::select: return solved_selection(state) == static_cast<int>(goal.req);
    case Goal::Kind::guard:
      return reqs[goal.req]->guard && solved_holds(*reqs[goal.req]->guard, state) == goal.value;
    case Goal::Kind::pair: return false;
    case Goal::Kind::boundary: {
      if (goal.line) {
        const Value* vx = find_value(state, goal.variable);
        const Value* vy = find_value(state, goal.variable2);
        const auto x = vx ? verify::detail::exact_value(*vx) : std::nullopt;
        const auto y = vy ? verify::detail::exact_value(*vy) : std::nullopt;
        if (!x || !y) return false;
        try {
          return (*x + goal.slope * *y + goal.offset).sign() == goal.sign;
        } catch (const verify::detail::FractionOverflow&) {
          return false;
        }
      }
      const Value* v = find_value(state, goal.variable);
      if (v == nullptr || !verify::detail::side_of(*v, Fraction(0))) return false;
      auto side = [&](const Fraction& at) { return *verify::detail::side_of(*v, at); };
      if (goal.point) return side(*goal.lo) == 0;
      return (!goal.lo || side(*goal.lo) > 0) && (!goal.hi || side(*goal.hi) < 0);
    }
  }
  return false;
}

bool Model::Node::solved_pair(const Goal& goal, const State& s, const State& u) const {
  const std::size_t a = goal.atom;
  const auto& columns = solved->column_atom;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const bool differ =
        solved_holds(*atom_expr[columns[c]], s) != solved_holds(*atom_expr[columns[c]], u);
    if (differ != (c == column[a])) return false;
  }
  const auto* guard = reqs[goal.req]->guard.get();
  if (guard == nullptr || solved_holds(*guard, s) == solved_holds(*guard, u)) return false;
  return solved_selection(s) != solved_selection(u);
}

bool Model::Node::solved_retry(std::size_t goal, const std::set<std::uint64_t>& excluded) const {
  try {
    return solved->questions->retry(goal, excluded);
  } catch (const std::exception&) {
    return false;  // a value a scenario cannot carry: no other state
  }
}

}  // namespace uabt::campaign
