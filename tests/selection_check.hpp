#pragma once
// Condition ticks per selection, counted by ticking a compiled selection tree in the runtime
// engine once in a state of every cell of the node's state space; and whether it started the
// alternative the requirements select there.
#include <algorithm>
#include <string>

#include "compile/compile.hpp"
#include "compile/selection_space.hpp"
#include "load/mission.hpp"
#include "runtime/selection_probe.hpp"

namespace uabt::testing {

struct EngineCount {
  compile::SelectionCost cost;
  std::size_t cells = 0;
  std::string mismatch;  // "" when every cell started the required alternative
};

inline EngineCount engine_count(const load::Mission& m, const bt::Document& doc,
                                const std::string& adaptable) {
  EngineCount out;
  const auto reqs = m.selections_for(adaptable);
  std::vector<fretish::ExprPtr> guards;
  for (const auto* r : reqs) guards.push_back(r->guard);
  const auto space = compile::build_selection_space(guards, m.domain);
  if (!space) {
    out.mismatch = "no state space";
    return out;
  }
  out.cells = space->cells();
  double total = 0, weighted = 0, plain = 0;
  for (std::size_t c = 0; c < space->cells(); ++c) {
    const auto state = compile::cell_state(*space, c);
    if (!state) {
      out.mismatch = "a cell without a state";
      return out;
    }
    const auto probe = runtime::probe_selection(doc, adaptable, *state);
    std::string expected;
    if (space->label[c] >= 0) {
      const auto* req = reqs[static_cast<std::size_t>(space->label[c])];
      const auto* alt = m.find_alternative(adaptable, req->alternative);
      expected = alt ? alt->tree_id : req->alternative;
    }
    if (probe.first_call != expected && out.mismatch.empty()) {
      out.mismatch = "cell " + std::to_string(c) + ": started '" + probe.first_call +
                     "', required '" + expected + "'";
    }
    const auto n = static_cast<int>(probe.conditions);
    out.cost.worst = std::max(out.cost.worst, n);
    total += space->weight[c];
    weighted += space->weight[c] * n;
    plain += n;
  }
  if (total > 0)
    out.cost.average = weighted / total;
  else if (space->cells() > 0)
    out.cost.average = plain / static_cast<double>(space->cells());
  return out;
}

}  // namespace uabt::testing
