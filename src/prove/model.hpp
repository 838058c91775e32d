#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "load/mission.hpp"
#include "monitor/expression.hpp"
#include "monitor/formula.hpp"
#include "monitor/templates.hpp"
#include "prove/cells.hpp"
#include "prove/choice_world.hpp"
#include "prove/world_model.hpp"
#include "runtime/engine.hpp"
#include "runtime/engine_state.hpp"
#include "runtime/runner.hpp"
#include "runtime/tick_observation.hpp"

namespace uabt::prove {

// A variable of the world's state, with the finite set of values it ranges over.
struct StateVar {
  std::string name;
  std::vector<runtime::ScriptValue> values;
  bool env = true;       // no action writes it: the environment may change it every tick
  bool relevant = true;  // something reads it (else it keeps its first value)
  // One place in the tree reads it (a condition leaf, or a script that reads no other
  // environment variable), and nothing re-ticks the tree within a tick: once that place has
  // read it, the rest of the tick cannot read it again (unless a monitor or an assumption does).
  bool read_once = false;
  runtime::SlotId slot = runtime::kNoSlot;
  int frame = -1;  // its monitor::Variables slot
  // An entry an output port `{key}` writes (ARCHITECTURE §10): its values are those the action may
  // write. `unset_first`: no variable of the domain, so nothing is in it before the first write
  // (a read before then is BT.CPP's error).
  bool port_written = false;
  bool script_written = false;  // an effect or a script of the tree assigns it
  bool unset_first = false;
};

// A numeric environment variable whose cells depend on the mission's own state (ARCHITECTURE
// §10.1): some atom compares it with variables the mission writes (`battery >= reserve`). The
// environment cuts it when it chooses it, at `breaks` and at each atom's breakpoint in the
// state at hand.
struct StateCut {
  const fretish::Variable* declaration = nullptr;
  std::set<verify::detail::Fraction> breaks;  // the constant ones
  struct Atom {
    std::vector<std::pair<std::size_t, verify::detail::Fraction>> terms;  // Model::vars, factor
    verify::detail::Fraction b;  // the breakpoint is -(Σ factor·value + b)
    bool at_tick_start = false;
    std::string where;
  };
  std::vector<Atom> atoms;
};

// A mission property compiled for model checking.
struct Property {
  const fretish::Requirement* requirement = nullptr;
  bool assumption = false;  // component Environment
  monitor::Shape shape;
  std::vector<fretish::ExprPtr> exprs;  // mode, condition, response, stop, trap (or null)
  // The monitor's inputs: boolean expressions of one tick (property_formula.hpp), compiled.
  std::vector<fretish::ExprPtr> atom_exprs;
  std::vector<std::shared_ptr<monitor::CompiledExpression>> atoms;
  int mode_node = -1, condition_node = -1;  // layout nodes of the parts that trigger
  std::unique_ptr<monitor::PastTimeLayout> layout;
  std::size_t offset = 0;  // its words in the monitor state
  std::string unsupported;

  static constexpr std::size_t kMaxAtoms = 16;
  // This tick's atoms on `frame` into `bits` (kMaxAtoms of them), in order, through `reader`
  // when given (CompiledExpression::evaluate); throws ProveError naming the property and `tick`
  // on an evaluation error.
  void read_atoms(const std::vector<monitor::Val>& frame, bool* bits, std::uint64_t tick,
                  monitor::Reader* reader = nullptr) const;
  // Whether the mode and the condition hold, from the node values of the layout's last step.
  bool triggered(const std::vector<char>& values) const {
    return (mode_node < 0 || values[static_cast<std::size_t>(mode_node)]) &&
           (condition_node < 0 || values[static_cast<std::size_t>(condition_node)]);
  }
  bool has_trigger() const { return exprs[0] || exprs[1]; }
};

// `property` as a monitor over atoms of one tick, its names read through `resolve`; without a
// layout when prove cannot read it (`unsupported` says why). Its offset is the caller's.
Property make_property(const fretish::Requirement& property, const monitor::Resolver& resolve);

// The product the explorer walks: the runtime's engine over the compiled tree, the choice
// world, the observables and every property's monitor.
class Environment;

struct Model {
  Model(const load::Mission& mission, const bt::Document& compiled, const WorldModel& world);

  const load::Mission& mission;
  const bt::Document& doc;
  const WorldModel& world;
  std::vector<StateVar> vars;
  std::set<std::string, std::less<>> state_names;
  monitor::Variables variables;
  monitor::Symbols symbols;
  std::unique_ptr<ChoiceWorld> choice;
  std::unique_ptr<runtime::Engine> engine;
  std::unique_ptr<runtime::TickObservation> observables;
  std::unique_ptr<Environment> environment;  // the environment's values, chosen on demand
  std::vector<Property> properties;
  std::vector<std::shared_ptr<monitor::CompiledExpression>> assumptions;
  std::shared_ptr<monitor::CompiledExpression> initial;
  std::size_t monitor_words = 0;
  runtime::EngineState fresh;  // before the first tick, every variable at its first value
  // Why the explicit-state engine cannot enumerate this world ("" when it can): a relevant
  // real or unbounded/wide integer (such a variable has one placeholder value, empty).
  std::string explicit_refusal;
  // Per variable (Model::vars), the variables cut in each state: their cuts.
  std::map<std::size_t, StateCut> state_cuts;
  // The runtime `uabt run` runs, over the compiled tree: built for the first counterexample
  // replayed and restarted for each next one (Runner::restart: exactly a fresh tree).
  std::unique_ptr<runtime::Runner> replay_runner;

  ~Model();

  // Evaluates a state expression (initial, assumption) on the blackboard now.
  bool holds(monitor::CompiledExpression& e, std::vector<monitor::Val>& frame);
  void fill_state(std::vector<monitor::Val>& frame) const;

 private:
  // The values the explicit engine branches over, per relevant variable (cells for numeric
  // environment variables), or why it cannot (explicit_refusal).
  void choose_values(const std::map<std::string, std::string, std::less<>>& unenumerable);
  void mark_read_once();
  std::vector<std::pair<runtime::script::Program, std::string>> tree_scripts;  // and where
  std::vector<std::string> port_reads;  // blackboard keys ports read
  // [first, last) of tree_scripts: the ScriptConditions of a Fallback of a generated selection
  // tree, of which only the disjunction is seen (Cuts::add_any_of).
  std::vector<std::pair<std::size_t, std::size_t>> disjunctions;
  static bool fallback_of_conditions(const bt::Node& n);
  // The declaration an output port's entry that the domain does not declare gets from the
  // port's type (nodes.xml), by entry name.
  std::map<std::string, fretish::Variable, std::less<>> port_entries;

 public:
  // The domain's declaration of a variable, or the one its output port's type gives it.
  const fretish::Variable* declaration(const std::string& name) const;
};

}  // namespace uabt::prove
