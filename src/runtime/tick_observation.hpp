// What a tick shows (ARCHITECTURE §10, §14): one rule for `uabt run`'s monitor, `uabt prove`'s
// explicit engine and the replay of its counterexamples; the symbolic engine encodes the same rule
// as terms (prove/symbolic_tick.cpp, over observable_of).
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "load/mission.hpp"
#include "monitor/expression.hpp"
#include "runtime/engine.hpp"

namespace uabt::runtime {

// What a name a property reads is, in a running engine: one rule of ARCHITECTURE §10, in this
// order.
//  - state: a state variable (a domain variable, a condition: the caller's `state`);
//  - status: `<node>.success|failure|running`, the nodes observed_nodes names (named `node`,
//    else of that ID, any of them; not the generated selection trees);
//  - selected: `<adaptable>.selected`, with the SubTree calls of its alternatives in its
//    selection tree in any selection style (SelectionObserver::selector_of);
//  - mode: the mode `<adaptable>`, with the SubTree calls of its selection tree;
//  - literal: `none`, an enum value, an alternative's name.
struct Observable {
  enum class Kind { unknown, state, status, selected, mode, literal };
  Kind kind = Kind::unknown;
  std::vector<NodeId> nodes;                   // status: the nodes; mode: the calls
  NodeStatus status = NodeStatus::idle;        // status: the status it asks about
  std::map<NodeId, std::string> alternatives;  // selected: each call, with its alternative
  bool boolean = true;                         // state: read as a boolean (unset: false)
};
Observable observable_of(const Engine& engine, const load::Mission& mission,
                         const std::set<std::string, std::less<>>& state, const std::string& name);

// The value of a state variable as a property reads it: the blackboard's value; an unset
// entry reads false when the variable is a boolean (a condition, or declared so), else unknown.
monitor::Val state_value(const ScriptValue* value, bool boolean, monitor::Symbols& symbols);

// The observables of one tick, taken from a running engine: at tick t (the state once tick t
// has finished)
//  - a state variable: state_value of the root blackboard's entry;
//  - `<node>.success|failure|running`: what one of its nodes returned last in tick t (a
//    wake-up re-tick returns again; a node halted or reset without a tick returned nothing);
//  - `<adaptable>.selected`: the alternative of the last of its alternative calls ticked in
//    tick t (after a fall-through, the later branch), else `none`;
//  - the mode `<adaptable>`: one of its calls was ticked in tick t.
// Works on any engine, so a run, prove and the replay of a counterexample read the very same
// observables.
class TickObservation : public Observer {
 public:
  // `state` names the state variables (root blackboard keys) a property may read.
  TickObservation(const Engine& engine, const load::Mission& mission,
                  std::set<std::string, std::less<>> state, monitor::Variables& variables,
                  monitor::Symbols& symbols);

  // For monitor::CompiledExpression: registers the observable `name` is (observable_of); a
  // name that is none reads the slot the caller gave it, else resolves to nothing.
  monitor::Resolved resolve(const std::string& name);

  void begin_tick();  // call before each tick
  void on_status_change(NodeId, NodeStatus, NodeStatus) override {}
  void on_node_ticked(NodeId node, NodeStatus result) override;
  // The frame after the tick: every slot resolve() registered.
  void fill(std::vector<monitor::Val>& frame) const;
  // What this tick has recorded so far, as bytes: every node ticked with the status it last
  // returned, and the alternatives selected. With the engine's state it decides how the rest
  // of the tick goes and what the monitors see (a model checker's mid-tick state).
  void append_tick_key(std::string& out) const;
  // What the tick has recorded up to a point within it, and going back there.
  struct Mark {
    std::size_t touched = 0;
    std::vector<NodeId> open;
    std::vector<int> alternatives;
  };
  void mark(Mark& out) const;
  void undo(const Mark& mark);
  // Whether to keep what append_tick_key needs (off: nobody asks, and it costs per node tick).
  void track_open(bool on) { track_open_ = on; }

  static monitor::Val value_of(const ScriptValue& v, monitor::Symbols& symbols);

 private:
  struct StateObs {
    std::string key;
    int slot;
    bool boolean;
  };
  struct StatusObs {
    std::vector<NodeId> nodes;
    NodeStatus status;
    int slot;
  };
  struct SelectedObs {
    int slot;
    std::vector<int> alternative_of_call;  // per engine node: symbol of its alternative, -1
  };
  struct ModeObs {
    std::vector<NodeId> calls;
    int slot;
  };
  const Engine& engine_;
  const load::Mission& mission_;
  std::set<std::string, std::less<>> state_;
  monitor::Variables& variables_;
  monitor::Symbols& symbols_;
  std::map<std::string, monitor::Resolved, std::less<>> resolved_;
  std::vector<StateObs> states_;
  std::vector<StatusObs> statuses_;
  std::vector<SelectedObs> selected_;
  std::vector<ModeObs> modes_;
  std::vector<NodeStatus> last_;  // per node, this tick (idle: not ticked)
  std::vector<NodeId> touched_;
  std::vector<NodeStatus> before_;            // per touched_: what last_ had before
  std::vector<NodeId> open_;                  // ticked, and their parent has not returned since
  std::vector<NodeId> parent_;                // per node
  std::vector<char> is_open_;                 // per node: in open_
  std::vector<std::uint32_t> open_children_;  // per node: its children in open_
  void count_open(NodeId node, bool open);
  void set_open(const std::vector<NodeId>& open);
  bool track_open_ = false;
  std::vector<NodeId> observed_;       // nodes whose returns a property reads
  std::vector<int> last_alternative_;  // per SelectedObs: symbol, -1 for none
};

}  // namespace uabt::runtime
