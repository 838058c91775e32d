#pragma once
#include <z3++.h>

#include <memory>
#include <string>
#include <vector>

#include "prove/model.hpp"
#include "prove/monitor_table.hpp"
#include "prove/symbolic_value.hpp"

namespace uabt::prove {

// The state between two ticks as terms: what runtime::EngineState, ChoiceWorld::elapsed and
// the monitors hold, plus whether the run is over and whether it has started.
// Statuses, counters, elapsed ticks and monitor states are integers although each takes a few
// values. Measured with Z3 4.8.12, finite sorts are slower: as bit-vectors of the width their
// range needs, BMC took 2.5x as long on checklist 10 (the statuses alone 2.4x) and BMC with
// k-induction 2.9x on msl_curiosity, whose guarantees IC3/PDR then no longer proved within
// its first frames; the statuses as an enumeration sort cost 1.4-1.5x on both.
struct SymState {
  std::vector<z3::expr> status;   // per engine node: NodeStatus as an integer
  std::vector<z3::expr> counter;  // per engine node: RtNode::a where its kind uses it, else 0
  std::vector<z3::expr> elapsed;  // per ChoiceWorld leaf
  std::vector<z3::expr> values;   // per Model::vars (a constant where the state does not keep it)
  std::vector<z3::expr> monitor;  // per property: its MonitorTable state (0 without a monitor)
  std::vector<z3::expr> done, started;  // one term each
  std::vector<z3::expr> wake;           // the wake-up signal carried into the next tick
  // Per Model::vars: whether the entry holds a value (false only for an entry an output port
  // writes that the domain does not declare, until its first write).
  std::vector<z3::expr> written;
};

// What the world chooses for one tick.
struct TickInputs {
  std::vector<z3::expr> values;  // per Model::vars: its value before the tick, where chosen
  // Per ChoiceWorld leaf, per time it is ticked within the tick (wake-up re-ticks and Repeat
  // rounds tick a leaf again): -1 runs on, k ends with result k.
  std::vector<std::vector<z3::expr>> outcomes;
  // Per ChoiceWorld leaf, per output port, per time it is ticked: what it writes if it ends.
  std::vector<std::vector<std::vector<z3::expr>>> outputs;
};

struct TickEncoding {
  SymState next;
  z3::expr root;  // what the root returned
  std::vector<z3::expr>
      returned;                  // per engine node: what it returned this tick, idle if not ticked
  std::vector<z3::expr> inputs;  // per property: its monitor's atoms (Property::atom_exprs)
  z3::expr valid;                // a step the world model allows from a state where the run goes on
  std::vector<z3::expr> fails;   // per property: a guarantee violated at this tick
  z3::expr overflow;             // the wake-up loop wants more re-ticks than the encoding unrolls
  std::vector<z3::expr> leaf_ticks;  // per leaf: how often it was ticked
  // With named terms: the constants `valid` defines (existential, like the inputs).
  std::vector<z3::expr> locals;
  // The tick stops with an error (a read of a blackboard entry nothing has written yet, which
  // BT.CPP throws on): the run ends there, as in `uabt run`; no monitor reads the tick.
  z3::expr error;
  // Per property: its trigger (its mode and its condition) holds at this tick (false without a
  // trigger, and at a tick that stops with an error).
  std::vector<z3::expr> triggered;
};

// One tick of the runtime's engine (Engine::tick on the ChoiceWorld) as a formula, written
// node kind by node kind after src/runtime/controls, decorators and leaves, over the subset
// of BT.CPP the compiled missions use. Throws SymbolicUnsupported for anything else.
class SymbolicTick {
 public:
  SymbolicTick(Model& model, z3::context& ctx);
  ~SymbolicTick();

  SymState fresh() const;                           // before the first tick
  SymState state(const std::string& prefix) const;  // fresh constants
  TickInputs inputs(const std::string& prefix) const;
  z3::expr domain(const SymState& s) const;  // ranges every reachable state lies in
  z3::expr same(const SymState& a, const SymState& b) const;
  // Every component of a state in one order (constants where state() has them too).
  static std::vector<z3::expr> flatten(const SymState& s);
  // `named`: intermediate terms become constants that `valid` defines, which keeps the formula
  // linear in the tree for a solver; without it every term is a closed expression over the
  // state and inputs (what a test evaluates).
  TickEncoding encode(const SymState& s, const TickInputs& in, bool first, bool named = false);

  // The runtime value of variable `var` in a model of the solver.
  runtime::ScriptValue value(const z3::model& m, const z3::expr& e, std::size_t var) const;
  bool tracked(std::size_t var) const;  // part of the state or chosen by the environment
  SymType type(std::size_t var) const;
  const MonitorTable* table(std::size_t property) const;
  // Whether some tick may stop with an error (TickEncoding::error is not always false).
  bool may_stop() const;
  SymbolCodes& codes();
  z3::context& context();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace uabt::prove
