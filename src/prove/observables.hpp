#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "load/mission.hpp"
#include "monitor/expression.hpp"
#include "runtime/engine.hpp"

namespace uabt::prove {

// What a mission property may read at tick t (ARCHITECTURE §10), taken from a running engine:
// state variables (the root blackboard), `<node>.success|failure|running` (the status the node
// returned in tick t), `<adaptable>.selected` (the alternative whose SubTree the selection
// ticked last in tick t, else `none`) and the mode `<adaptable>` (its SubTree was ticked).
// Works on any engine built from the compiled tree, so prove and the replay of a
// counterexample read the very same observables.
// The nodes `<node>.success|failure|running` reads: runtime::observed_nodes, the rule `uabt run`
// monitors by (named `node`, else of that ID, any of them; not the generated selection trees).
std::vector<runtime::NodeId> status_nodes(const runtime::Engine& engine,
                                          const load::Mission& mission, const std::string& node);
// The SubTree calls of the alternatives of `adaptable` in its selection tree, in any selection
// style (runtime::SelectionObserver::selector_of), with the alternative each one calls.
std::map<runtime::NodeId, std::string> alternative_calls(const runtime::Engine& engine,
                                                         const load::Mission& mission,
                                                         const std::string& adaptable);

class Observables : public runtime::Observer {
 public:
  // `state` names the state variables (root blackboard keys) a property may read.
  Observables(const runtime::Engine& engine, const load::Mission& mission,
              std::set<std::string, std::less<>> state, monitor::Variables& variables,
              monitor::Symbols& symbols);

  // For monitor::CompiledExpression: registers the observables a property names.
  monitor::Resolved resolve(const std::string& name);

  void begin_tick();  // call before each tick
  void on_status_change(runtime::NodeId, runtime::NodeStatus, runtime::NodeStatus) override {}
  void on_node_ticked(runtime::NodeId node, runtime::NodeStatus result) override;
  // The frame after the tick, one value per variable slot.
  void fill(std::vector<monitor::Val>& frame) const;
  // What this tick has recorded so far, as bytes: every node ticked with the status it last
  // returned, and the alternatives selected. With the engine's state it decides how the rest
  // of the tick goes and what the monitors see (a model checker's mid-tick state).
  void append_tick_key(std::string& out) const;
  // What the tick has recorded up to a point within it, and going back there.
  struct Mark {
    std::size_t touched = 0;
    std::vector<runtime::NodeId> open;
    std::vector<int> alternatives;
  };
  void mark(Mark& out) const;
  void undo(const Mark& mark);
  // Whether to keep what append_tick_key needs (off: nobody asks, and it costs per node tick).
  void track_open(bool on) { track_open_ = on; }

  static monitor::Val value_of(const runtime::ScriptValue& v, monitor::Symbols& symbols);

 private:
  struct StateObs {
    std::string key;
    int slot;
  };
  struct StatusObs {
    std::vector<runtime::NodeId> nodes;
    runtime::NodeStatus status;
    int slot;
  };
  struct SelectedObs {
    int slot;
    std::vector<int> alternative_of_call;  // per engine node: symbol of its alternative, -1
  };
  struct ModeObs {
    std::vector<runtime::NodeId> calls;
    int slot;
  };
  const runtime::Engine& engine_;
  const load::Mission& mission_;
  std::set<std::string, std::less<>> state_;
  monitor::Variables& variables_;
  monitor::Symbols& symbols_;
  std::vector<StateObs> states_;
  std::vector<StatusObs> statuses_;
  std::vector<SelectedObs> selected_;
  std::vector<ModeObs> modes_;
  std::vector<runtime::NodeStatus> last_;  // per node, this tick (idle: not ticked)
  std::vector<runtime::NodeId> touched_;
  std::vector<runtime::NodeStatus> before_;  // per touched_: what last_ had before
  std::vector<runtime::NodeId> open_;        // ticked, and their parent has not returned since
  std::vector<runtime::NodeId> parent_;      // per node
  bool track_open_ = false;
  std::vector<runtime::NodeId> observed_;  // nodes whose returns a property reads
  std::vector<int> last_alternative_;      // per SelectedObs: symbol, -1 for none
};

}  // namespace uabt::prove
