#include "prove/symbolic.hpp"

#include <algorithm>

#include "prove/symbolic_tick.hpp"
#include "smt/assign.hpp"

namespace uabt::prove {

namespace {

// Pins a state to fresh constants, so that terms stay one tick deep.
SymState pin(z3::solver& s, SymbolicTick& tick, const SymState& value, const std::string& prefix) {
  SymState fresh = tick.state(prefix);
  s.add(tick.same(fresh, value));
  return fresh;
}

Step step_of(const z3::model& model, SymbolicTick& tick, const Model& m, const TickInputs& in,
             const std::vector<z3::expr>& leaf_ticks, bool first) {
  Step step;
  step.values.resize(m.vars.size());
  for (std::size_t v = 0; v < m.vars.size(); ++v)
    if (m.vars[v].relevant && (first || m.vars[v].env))
      step.values[v] = tick.value(model, in.values[v], v);
  for (std::size_t l = 0; l < in.outcomes.size(); ++l) {
    step.outcomes.emplace_back();
    const int ticked = model.eval(leaf_ticks[l], true).get_numeral_int();
    for (int k = 0; k < ticked; ++k)
      step.outcomes.back().push_back(static_cast<std::int32_t>(
          model.eval(in.outcomes[l][static_cast<std::size_t>(k)], true).get_numeral_int()));
    step.outputs.emplace_back();
    for (int k = 0; k < ticked; ++k) {
      step.outputs.back().emplace_back();
      const auto& outputs = m.choice->leaves()[l].outputs;
      for (std::size_t p = 0; p < in.outputs[l].size(); ++p) {
        const runtime::SlotId slot = outputs[p].slot;
        std::size_t var = 0;
        while (var + 1 < m.vars.size() && m.vars[var].slot != slot) ++var;
        step.outputs.back().back().push_back(
            tick.value(model, in.outputs[l][p][static_cast<std::size_t>(k)], var));
      }
    }
  }
  return step;
}

// What the search looks for, by index: a guarantee's violation (the property's index), a tick
// that stops with an error (kError after them), or a guarantee's trigger (after that). Each is
// a term that holds at a bad tick: BMC finds its shortest tick, k-induction and IC3/PDR prove
// that no run reaches it.
class Goals {
 public:
  explicit Goals(std::size_t properties) : count_(properties) {}
  std::size_t size() const { return 2 * count_ + 1; }
  std::size_t error() const { return count_; }
  std::size_t trigger(std::size_t property) const { return count_ + 1 + property; }
  bool is_guarantee(std::size_t goal) const { return goal < count_; }
  bool is_trigger(std::size_t goal) const { return goal > count_; }
  std::size_t property_of_trigger(std::size_t goal) const { return goal - count_ - 1; }
  z3::expr bad(const TickEncoding& e, std::size_t goal) const {
    if (goal < count_) return e.fails[goal];
    if (goal == count_) return e.error;
    return e.triggered[goal - count_ - 1];
  }

 private:
  std::size_t count_;
};

bool is_variable(const z3::expr& e) {
  return e.is_app() && e.num_args() == 0 && e.decl().decl_kind() == Z3_OP_UNINTERPRETED;
}

// The search's resource budget (Options::symbolic_resources), read off Z3's count of the context's
// steps, which every solver's statistics report.
class Budget {
 public:
  Budget(z3::context& ctx, z3::solver& meter, std::uint64_t total)
      : ctx_(ctx), meter_(meter), total_(total) {}
  std::uint64_t left() const {
    const z3::stats stats = meter_.statistics();
    std::uint64_t spent = 0;
    for (unsigned i = 0; i < stats.size(); ++i)
      if (stats.key(i) == "rlimit count") spent = stats.uint_value(i);
    return spent < total_ ? total_ - spent : 0;
  }
  // The check `s` runs next may spend at most what is left; false when nothing is (Z3 reads a
  // limit of 0 as none, so the check must not run). `params` are the solver's own: setting
  // parameters again resets those not given.
  bool limit(z3::solver& s, z3::params& params) const {
    const unsigned resources = limit_now();
    if (resources == 0) return false;
    params.set("rlimit", resources);
    s.set(params);
    return true;
  }
  // The same for IC3/PDR, whose queries read the context's limit while it is set.
  struct Scoped {
    z3::context& ctx;
    Scoped(z3::context& c, unsigned resources) : ctx(c) {
      ctx.set("rlimit", std::to_string(resources).c_str());
    }
    ~Scoped() { ctx.set("rlimit", "0"); }
    Scoped(const Scoped&) = delete;
    Scoped& operator=(const Scoped&) = delete;
  };
  unsigned limit_now() const {
    return static_cast<unsigned>(std::min<std::uint64_t>(left(), UINT32_MAX));
  }
  std::uint64_t total() const { return total_; }

 private:
  z3::context& ctx_;
  z3::solver& meter_;
  std::uint64_t total_;
};

// IC3/PDR (Z3's Spacer) on the goals k-induction could not prove: Horn clauses over an
// invariant of the states between ticks, with at most `levels` frames (deterministic, unlike a
// timeout). One query asks whether any of them can be reached; only when one can is each asked
// alone. A proof is trusted; a reachable goal is left to BMC, which finds its shortest run.
struct PdrAnswers {
  std::vector<bool> proved, reachable;  // per goal
  unsigned queries = 0;
};

PdrAnswers spacer_answers(z3::context& ctx, SymbolicTick& tick, const Goals& goals,
                          const std::vector<std::size_t>& open, unsigned levels,
                          const Budget& budget) {
  PdrAnswers out;
  out.proved.assign(goals.size(), false);
  out.reachable.assign(goals.size(), false);
  const SymState cur = tick.state("pdr.");
  std::vector<z3::expr> flat = SymbolicTick::flatten(cur);
  std::vector<std::size_t> positions;
  z3::sort_vector sorts(ctx);
  z3::expr_vector state_vars(ctx);
  for (std::size_t i = 0; i < flat.size(); ++i)
    if (is_variable(flat[i])) {
      positions.push_back(i);
      sorts.push_back(flat[i].get_sort());
      state_vars.push_back(flat[i]);
    }
  z3::func_decl inv = ctx.function("Inv", sorts, ctx.bool_sort());
  auto holds = [&](const SymState& s) {
    const std::vector<z3::expr> f = SymbolicTick::flatten(s);
    z3::expr_vector args(ctx);
    for (std::size_t i : positions) args.push_back(f[i]);
    return inv(args);
  };
  const TickInputs first_in = tick.inputs("pdr.first."), in = tick.inputs("pdr.in.");
  // Named terms: the transition stays linear in the tree (measured: Spacer 18x faster on a
  // binary tree of 24 nodes than over the closed terms).
  TickEncoding start = tick.encode(tick.fresh(), first_in, true, true);
  TickEncoding step = tick.encode(cur, in, false, true);
  auto quantified = [&](const TickInputs& x, bool with_state) {
    z3::expr_vector vars(ctx);
    if (with_state)
      for (unsigned i = 0; i < state_vars.size(); ++i) vars.push_back(state_vars[i]);
    for (const auto& v : x.values) vars.push_back(v);
    for (const auto& per_leaf : x.outcomes)
      for (const auto& o : per_leaf) vars.push_back(o);
    for (const auto& per_leaf : x.outputs)
      for (const auto& per_port : per_leaf)
        for (const auto& o : per_port) vars.push_back(o);
    for (const auto& l : with_state ? step.locals : start.locals) vars.push_back(l);
    return vars;
  };
  // Whether one of `which` can fail: unsat, sat, or unknown when the frames run out.
  auto query = [&](const std::vector<std::size_t>& which) {
    z3::fixedpoint fp(ctx);
    z3::params params(ctx);
    params.set("engine", "spacer");
    params.set("spacer.max_level", levels);
    fp.set(params);
    fp.register_relation(inv);
    const std::string name = "Bad" + std::to_string(out.queries++);
    z3::func_decl bad = ctx.function(name.c_str(), 0, nullptr, ctx.bool_sort());
    fp.register_relation(bad);
    z3::expr fails0 = start.overflow, fails1 = step.overflow;
    for (std::size_t g : which) {
      smt::assign(fails0, fails0 || goals.bad(start, g));
      smt::assign(fails1, fails1 || goals.bad(step, g));
    }
    z3::expr r0 =
        z3::forall(quantified(first_in, false), z3::implies(start.valid, holds(start.next)));
    z3::expr r1 =
        z3::forall(quantified(in, true), z3::implies(holds(cur) && step.valid, holds(step.next)));
    z3::expr b0 =
        z3::forall(quantified(first_in, false), z3::implies(start.valid && fails0, bad()));
    z3::expr b1 =
        z3::forall(quantified(in, true), z3::implies(holds(cur) && step.valid && fails1, bad()));
    fp.add_rule(r0, ctx.str_symbol("init"));
    fp.add_rule(r1, ctx.str_symbol("tick"));
    fp.add_rule(b0, ctx.str_symbol("bad0"));
    fp.add_rule(b1, ctx.str_symbol("bad"));
    z3::expr goal = bad();
    const unsigned resources = budget.limit_now();
    if (resources == 0) return z3::unknown;
    const Budget::Scoped limit(ctx, resources);
    try {
      return fp.query(goal);
    } catch (const z3::exception&) {
      return z3::unknown;  // resource limit: no answer here
    }
  };
  if (open.size() > 1 && query(open) == z3::unsat) {
    for (std::size_t p : open) out.proved[p] = true;
    return out;
  }
  for (std::size_t p : open) {
    const z3::check_result r = query({p});
    out.proved[p] = r == z3::unsat;
    out.reachable[p] = r == z3::sat;
  }
  return out;
}

}  // namespace

SymbolicSearch symbolic_search(Model& m, const Options& options) {
  z3::context ctx;
  SymbolicTick tick(m, ctx);
  const std::uint64_t bound = options.depth != 0 ? options.depth : kSymbolicBound;
  const std::size_t count = m.properties.size();
  const Goals goals(count);
  SymbolicSearch out;
  out.violations.resize(count);
  out.proved_k.assign(count, 0);
  out.proved.assign(count, false);
  out.by_pdr.assign(count, false);
  out.first_trigger.assign(count, 0);
  out.trigger_decided.assign(count, false);
  // Per goal: proved unreachable (with the k of its induction, or by IC3/PDR), or reached.
  std::vector<bool> proved(goals.size(), false), by_pdr(goals.size(), false);
  std::vector<std::uint64_t> proved_k(goals.size(), 0);
  std::vector<bool> wanted(goals.size(), false);
  std::vector<std::size_t> open;  // goals neither proved nor reached yet
  for (std::size_t p = 0; p < count; ++p)
    if (!m.properties[p].assumption && tick.table(p)) open.push_back(p);
  if (tick.may_stop()) open.push_back(goals.error());
  // A guarantee's trigger matters for a proof: one that holds on no run proves nothing.
  for (std::size_t p = 0; p < count; ++p)
    if (!m.properties[p].assumption && tick.table(p) && m.properties[p].has_trigger())
      open.push_back(goals.trigger(p));
  for (std::size_t g : open) wanted[g] = true;
  // Per goal: IC3/PDR found a run that reaches it. Induction cannot prove it unreachable, so it
  // is left to BMC, which finds the shortest such run (or reaches its bound).
  std::vector<bool> reachable(goals.size(), false);

  // Z3's SMT core, incremental; each question is asked under assumption literals rather than
  // in a push/pop scope, so what the solver learns stays for the next question and depth.
  z3::solver bmc(ctx, z3::solver::simple()), ind(ctx, z3::solver::simple());
  // Z3's older arithmetic solver: the control state is integers compared with constants, and
  // it propagates those equalities with less work (measured, whole process: sample_drilling
  // 37% faster, checklist 10 8%, the other bench missions 3-6%, none slower).
  z3::params arithmetic(ctx);
  arithmetic.set("arith.solver", 2u);
  bmc.set(arithmetic);
  ind.set(arithmetic);
  unsigned literals = 0;
  auto literal = [&](z3::solver& s, const z3::expr& meaning) {
    const z3::expr l = ctx.bool_const(("q!" + std::to_string(literals++)).c_str());
    s.add(l == meaning);
    return l;
  };
  const Budget budget(ctx, bmc, options.symbolic_resources);
  // A check without an answer (the budget spent, or one Z3 cannot decide) stops the search:
  // BMC cannot go deeper, and k-induction needs every shallower depth checked.
  struct NoAnswer {
    std::string why;
  };
  auto no_answer = [&](z3::solver& s, std::uint64_t k) {
    if (budget.left() == 0)
      return NoAnswer{"the symbolic engine spent its budget (" + std::to_string(budget.total()) +
                      " of Z3's resource units) at tick " + std::to_string(k)};
    return NoAnswer{"Z3 could not decide a check at tick " + std::to_string(k) + " (" +
                    s.reason_unknown() + ")"};
  };
  auto holds_under = [&](z3::solver& s, std::initializer_list<z3::expr> assumptions) {
    z3::expr_vector a(ctx);
    for (const z3::expr& e : assumptions) a.push_back(e);
    ++(&s == &bmc ? out.bmc_checks : out.induction_checks);
    if (!budget.limit(s, arithmetic)) throw no_answer(s, out.depth + 1);
    const z3::check_result r = s.check(a);
    if (r == z3::unknown) throw no_answer(s, out.depth + 1);
    return r == z3::sat;
  };
  std::vector<SymState> path{tick.fresh()};
  std::vector<TickInputs> inputs;
  std::vector<std::vector<z3::expr>> leaf_ticks;  // per tick, per leaf
  // BMC has reached a tick no run goes past: no first tick, a deadlock, or every run over.
  bool stopped = false;

  // BMC one tick deeper: the open goals a run of out.depth + 1 ticks reaches, at their
  // shortest tick since every shorter depth was asked first.
  auto bmc_tick = [&]() {
    const std::uint64_t k = out.depth + 1;
    const std::string t = "t" + std::to_string(k) + ".";
    inputs.push_back(tick.inputs(t));
    TickEncoding enc = tick.encode(path.back(), inputs.back(), k == 1, true);
    leaf_ticks.push_back(enc.leaf_ticks);
    bmc.add(enc.valid);
    path.push_back(pin(bmc, tick, enc.next, "s" + std::to_string(k) + "."));
    if (!enc.overflow.simplify().is_false() && holds_under(bmc, {literal(bmc, enc.overflow)}))
      throw SymbolicUnsupported("at tick " + std::to_string(k) +
                                " the wake-up loop re-ticks the root more often than the "
                                "symbolic engine unrolls it");
    auto run_of = [&](const z3::model& model) {
      Finding f;
      f.tick = k;
      for (std::size_t j = 0; j < inputs.size(); ++j)
        f.path.push_back(step_of(model, tick, m, inputs[j], leaf_ticks[j], j == 0));
      return f;
    };
    std::vector<std::size_t> still, violated;
    for (std::size_t g : open) {
      if (!holds_under(bmc, {literal(bmc, goals.bad(enc, g))})) {
        still.push_back(g);
      } else if (goals.is_guarantee(g)) {
        out.violations[g] = run_of(bmc.get_model());
        out.violations[g]->property = g;
        violated.push_back(g);
      } else if (g == goals.error()) {
        out.error = run_of(bmc.get_model());
      } else {
        out.first_trigger[goals.property_of_trigger(g)] = k;
        out.trigger_decided[goals.property_of_trigger(g)] = true;
      }
    }
    const bool reached = still.size() < open.size();
    open = std::move(still);
    // A violated guarantee's trigger no longer matters.
    std::erase_if(open, [&](std::size_t g) {
      return goals.is_trigger(g) && out.violations[goals.property_of_trigger(g)];
    });
    if (open.empty()) {
      out.depth = k;
      return;
    }
    // Every run over by tick k: nothing is left to reach (cheaper than any induction).
    if (!holds_under(bmc, {literal(bmc, !path.back().done[0])})) {
      // No run lasting k ticks either (asked only now: measured, that question cost half of
      // BMC on a binary tree of 24 nodes): tick k - 1 left one going (else the search would
      // have stopped there), yet it cannot go on; it is stuck, and a proof would be vacuous.
      if (!reached && !holds_under(bmc, {})) {
        if (k == 1)
          out.no_first_tick = true;
        else
          out.deadlock_after = k - 1;
        out.depth = k - 1;
        stopped = true;
        return;
      }
      for (std::size_t g : open) {
        proved[g] = true;
        proved_k[g] = k;
      }
      open.clear();
      stopped = true;
    }
    out.depth = k;
  };
  auto bmc_to = [&](std::uint64_t depth) {
    while (!stopped && !open.empty() && out.depth < depth) bmc_tick();
  };
  // IC3/PDR on the open goals it has not found reachable; `guarantees_only`: not on the
  // errors and triggers, which a run usually reaches (BMC finds them at less cost).
  auto ask_pdr = [&](unsigned levels, bool guarantees_only) {
    std::vector<std::size_t> asked;
    for (std::size_t g : open)
      if (!reachable[g] && (!guarantees_only || goals.is_guarantee(g))) asked.push_back(g);
    if (asked.empty()) return;
    const PdrAnswers pdr = spacer_answers(ctx, tick, goals, asked, levels, budget);
    if (budget.left() == 0) throw no_answer(bmc, out.depth + 1);
    out.pdr_queries += pdr.queries;
    for (std::size_t g : asked) {
      proved[g] = pdr.proved[g];
      by_pdr[g] = pdr.proved[g];
      reachable[g] = pdr.reachable[g];
    }
    std::erase_if(open, [&](std::size_t g) { return proved[g]; });
  };

  std::vector<SymState> ind_states{tick.state("i0.")};
  std::vector<std::vector<z3::expr>> ind_fails;  // per transition, per goal: a literal
  ind.add(tick.domain(ind_states[0]) && ind_states[0].started[0]);
  const std::uint64_t pdr_k = std::min<std::uint64_t>(bound, kInductionBeforePdr);
  try {
    for (std::uint64_t k = 1; k <= bound; ++k) {
      // Base case: every run of k ticks.
      bmc_to(k);
      if (stopped || open.empty()) break;

      // Induction step: k transitions from any state, pairwise distinct sources.
      const std::string u = "i" + std::to_string(k) + ".";
      TickEncoding step = tick.encode(ind_states.back(), tick.inputs(u + "in."), false, true);
      ind.add(step.valid);
      ind_states.push_back(pin(ind, tick, step.next, u));
      // A proof must also rule out a wake-up loop deeper than the encoding.
      std::vector<z3::expr> fails;
      for (std::size_t g = 0; g < goals.size(); ++g)
        fails.push_back(wanted[g] ? literal(ind, goals.bad(step, g) || step.overflow)
                                  : ctx.bool_val(false));
      ind_fails.push_back(std::move(fails));
      for (std::size_t g : open) {
        if (reachable[g]) continue;
        out.induction_k = k;
        z3::expr_vector a(ctx);
        for (std::size_t j = 0; j + 1 < ind_fails.size(); ++j) a.push_back(!ind_fails[j][g]);
        a.push_back(ind_fails.back()[g]);
        // The simple-path constraints (sources pairwise distinct), added lazily: only for
        // the pairs a counterexample to induction repeats. The answer is the one all pairs
        // give: unsat under some of them is unsat under all, and a model that repeats no
        // pair satisfies all of them.
        for (;;) {
          ++out.induction_checks;
          if (!budget.limit(ind, arithmetic)) throw no_answer(ind, out.depth + 1);
          const z3::check_result r = ind.check(a);
          if (r == z3::unsat) {
            proved[g] = true;
            proved_k[g] = k;
            break;
          }
          // Undecided: not proved at this k (or, the budget spent, at all).
          if (r == z3::unknown) {
            if (budget.left() == 0) throw no_answer(ind, out.depth + 1);
            break;
          }
          const z3::model model = ind.get_model();
          bool repeated = false;
          for (std::size_t x = 0; x + 1 < k; ++x)
            for (std::size_t y = x + 1; y < k; ++y) {
              const z3::expr same = tick.same(ind_states[x], ind_states[y]);
              if (model.eval(same, true).is_true()) {
                ind.add(!same);
                repeated = true;
              }
            }
          if (!repeated) break;
        }
      }
      std::erase_if(open, [&](std::size_t g) { return proved[g]; });
      if (k != pdr_k || open.empty()) continue;
      // What k-induction has not proved by now it will rarely prove later. IC3/PDR is asked
      // first with a few frames, which proves most guarantees; BMC then runs ahead, so that a
      // guarantee a short run violates, or a trigger a short run reaches, costs neither
      // IC3/PDR's full search nor deeper induction; IC3/PDR with all its frames takes what is
      // still open.
      ask_pdr(kPdrFirstLevels, true);
      bmc_to(std::min(bound, kBmcBeforePdr));
      if (stopped || open.empty()) break;
      ask_pdr(kPdrMaxLevel, false);
    }
  } catch (const NoAnswer& e) {
    out.stopped_early = e.why;
  }
  for (std::size_t p = 0; p < count; ++p) {
    out.proved[p] = proved[p];
    out.proved_k[p] = proved_k[p];
    out.by_pdr[p] = by_pdr[p];
    if (proved[goals.trigger(p)]) out.trigger_decided[p] = true;
  }
  out.error_decided = !wanted[goals.error()] || out.error || proved[goals.error()];
  return out;
}

}  // namespace uabt::prove
