#include "prove/symbolic.hpp"

#include "prove/symbolic_tick.hpp"

namespace uabt::prove {

namespace {

// Pins a state to fresh constants, so that terms stay one tick deep.
SymState pin(z3::solver& s, SymbolicTick& tick, const SymState& value, const std::string& prefix) {
  SymState fresh = tick.state(prefix);
  s.add(tick.same(fresh, value));
  return fresh;
}

Step step_of(const z3::model& model, SymbolicTick& tick, const Model& m, const TickInputs& in,
             bool first) {
  Step step;
  step.values.resize(m.vars.size());
  for (std::size_t v = 0; v < m.vars.size(); ++v)
    if (m.vars[v].relevant && (first || m.vars[v].env))
      step.values[v] = tick.value(model, in.values[v], v);
  for (const z3::expr& o : in.outcomes)
    step.outcomes.push_back(static_cast<std::int32_t>(model.eval(o, true).get_numeral_int()));
  return step;
}

}  // namespace

SymbolicSearch symbolic_search(Model& m, const Options& options) {
  z3::context ctx;
  SymbolicTick tick(m, ctx);
  const std::uint64_t bound = options.depth != 0 ? options.depth : kSymbolicBound;
  const std::size_t count = m.properties.size();
  SymbolicSearch out;
  out.violations.resize(count);
  out.proved_k.assign(count, 0);
  out.proved.assign(count, false);
  std::vector<std::size_t> open;
  for (std::size_t p = 0; p < count; ++p)
    if (!m.properties[p].assumption && tick.table(p)) open.push_back(p);

  z3::solver bmc(ctx), ind(ctx);
  std::vector<SymState> path{tick.fresh()};
  std::vector<TickInputs> inputs;
  std::vector<SymState> ind_states{tick.state("i0.")};
  std::vector<std::vector<z3::expr>> ind_fails;  // per transition, per property
  ind.add(tick.domain(ind_states[0]) && ind_states[0].started[0]);

  for (std::uint64_t k = 1; k <= bound && !open.empty(); ++k) {
    // Base case: every run of k ticks.
    const std::string t = "t" + std::to_string(k) + ".";
    inputs.push_back(tick.inputs(t));
    TickEncoding enc = tick.encode(path.back(), inputs.back(), k == 1);
    bmc.add(enc.valid);
    path.push_back(pin(bmc, tick, enc.next, "s" + std::to_string(k) + "."));
    if (bmc.check() == z3::unsat) {
      // No run lasts k ticks: every guarantee still open holds on every run.
      for (std::size_t p : open) {
        out.proved[p] = true;
        out.proved_k[p] = k - 1;
      }
      out.depth = k - 1;
      open.clear();
      break;
    }
    std::vector<std::size_t> still;
    for (std::size_t p : open) {
      bmc.push();
      bmc.add(enc.fails[p]);
      if (bmc.check() == z3::sat) {
        const z3::model model = bmc.get_model();
        Finding f;
        f.property = p;
        f.tick = k;
        for (std::size_t j = 0; j < inputs.size(); ++j)
          f.path.push_back(step_of(model, tick, m, inputs[j], j == 0));
        out.violations[p] = std::move(f);
      } else {
        still.push_back(p);
      }
      bmc.pop();
    }
    open = std::move(still);
    out.depth = k;
    if (open.empty()) break;

    // Induction step: k transitions from any state, pairwise distinct sources.
    const std::string u = "i" + std::to_string(k) + ".";
    TickEncoding step = tick.encode(ind_states.back(), tick.inputs(u + "in."), false);
    ind.add(step.valid);
    ind_states.push_back(pin(ind, tick, step.next, u));
    for (std::size_t j = 0; j + 1 < ind_states.size() - 1; ++j)
      ind.add(!tick.same(ind_states[j], ind_states[ind_states.size() - 2]));
    ind_fails.push_back(step.fails);
    out.induction_k = k;
    if (ind.check() == z3::unsat) {
      for (std::size_t p : open) {
        out.proved[p] = true;
        out.proved_k[p] = k;
      }
      open.clear();
      break;
    }
    for (std::size_t p : open) {
      ind.push();
      for (std::size_t j = 0; j + 1 < ind_fails.size(); ++j) ind.add(!ind_fails[j][p]);
      ind.add(ind_fails.back()[p]);
      if (ind.check() == z3::unsat) {
        out.proved[p] = true;
        out.proved_k[p] = k;
      }
      ind.pop();
    }
    std::erase_if(open, [&](std::size_t p) { return out.proved[p]; });
  }
  return out;
}

}  // namespace uabt::prove
