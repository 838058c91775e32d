#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "load/mission.hpp"
#include "monitor/property_set.hpp"
#include "monitor/selection_check.hpp"
#include "runtime/engine.hpp"
#include "runtime/tick_observation.hpp"

namespace uabt::runtime {

// One `violation` trace event: a property that failed, the tick, and what it read.
struct PropertyViolation {
  std::uint64_t tick = 0;
  monitor::PropertyResult result;
};

// Monitors a mission's properties (ARCHITECTURE §10) on every tick of a run, on what the tick shows
// (TickObservation, the rule `uabt prove` reads by too), and judges its selections
// (monitor::SelectionJudge). What nodes return comes through the engine's Observer interface,
// selections through select().
class PropertyMonitor : public Observer {
 public:
  PropertyMonitor(const load::Mission& mission, const Engine& engine);

  void on_status_change(NodeId, NodeStatus, NodeStatus) override {}
  void on_node_ticked(NodeId node, NodeStatus result) override;
  // A selection subtree started `alternative` (the mission's name for it) in this tick, by the
  // branch of `requirement`: judged (monitor::SelectionJudge) on the values its guards read now.
  void select(const std::string& adaptable, const std::string& alternative,
              const std::string& requirement = "");

  // Call after each tick: builds the tick's observables and steps every property; returns the
  // violations that became final at this tick.
  std::vector<PropertyViolation> after_tick(std::uint64_t tick);
  // At the end of the run: properties whose finite-trace verdict is violated but were not
  // reported yet (eventually, finally, …).
  std::vector<PropertyViolation> at_end(std::uint64_t last_tick) const;

  // An uplink swapped `mission` in after tick `last_tick` (its trees are in the engine now):
  // the observables are bound again, to the nodes of the swapped-in trees too, and the
  // properties follow PropertySet::update (kept, stopped, or monitored from the next tick).
  // Returns the stopped properties violated at their last tick, not reported yet.
  std::vector<PropertyViolation> adopt(const load::Mission& mission, std::uint64_t last_tick);

  // The tick's observables as one line of a `uabt monitor` trace, after after_tick(tick):
  // {"tick": t, "state": {name: value, …}} with every name the properties read and the value
  // it had (booleans, numbers and names as JSON booleans, numbers and strings), then "\n".
  // Its tick's selections ride along ("select", with the values their guards read), and
  // before the first line and after an uplink, a {"selection": {…}} line gives each adaptable
  // node's alternatives, its requirements in priority order and each requirement as written
  // ("sentences": text and place), so that `uabt monitor` judges them without the version
  // that ran.
  std::string monitor_trace_line(std::uint64_t tick);

  // The selection requirements' verdicts, then the properties'.
  std::vector<monitor::PropertyResult> results() const;
  bool empty() const { return properties_->size() == 0; }
  // A guarantee violated or not monitored: the run fails.
  bool guarantees_failed() const;

 private:
  // An adaptable node with selection requirements, for judging them.
  struct Selecting {
    std::vector<std::string> requirements;        // priority order
    std::vector<fretish::Requirement> sentences;  // each as written (text, location)
    std::vector<std::string> alternatives;
    std::vector<std::string> reads;  // what its guards read
    std::string running;             // requirement of the branch still running
    std::vector<NodeId> calls;       // SubTree nodes calling its selection tree
  };

  // Binds every name `mission`'s properties and assumptions read to what the engine shows;
  // returns the vocabulary's literals (alternatives, enum values).
  std::set<std::string> bind(const load::Mission& mission);
  // The selection requirements of `mission` (judge_, selecting_); `swapped_after`: the tick
  // after which an uplink swapped `mission` in, whose requirements are judged from then on.
  void bind_selections(const load::Mission& mission, const std::set<std::string>& literals,
                       std::optional<std::uint64_t> swapped_after = std::nullopt);
  // A blackboard entry as a guard reads it (state_value).
  monitor::Val read(const std::string& key);

  const Engine& engine_;
  monitor::Variables variables_;
  monitor::Symbols symbols_;
  std::optional<monitor::PropertySet> properties_;
  std::optional<TickObservation> observation_;  // what each tick shows, of the version running
  std::vector<monitor::Val> frame_;
  std::map<std::string, bool> boolean_variable_;
  std::optional<monitor::SelectionJudge> judge_;
  std::map<std::string, Selecting> selecting_;
  std::vector<monitor::SelectionRecord> selected_;  // this tick's, until after_tick
  std::vector<monitor::SelectionRecord> traced_;    // the last tick's, for its trace line
  bool header_due_ = true;
};

}  // namespace uabt::runtime
