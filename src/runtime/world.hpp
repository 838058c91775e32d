#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bt/tree.hpp"
#include "runtime/blackboard.hpp"
#include "runtime/engine.hpp"
#include "runtime/scenario.hpp"
#include "runtime/status.hpp"

namespace uabt::runtime {

// A robot port's direction as nodes.xml declares it (`unknown`: the node has no model there).
enum class PortDirection : std::uint8_t { unknown, input, output, inout };

// One attribute of a robot leaf: a literal (`angle="180"`) or a blackboard key
// (`goal="{target}"`, `{=}` meaning the key named like the port).
struct LeafPort {
  std::string name;
  std::string literal;    // the attribute as written when not a key
  std::string key;        // the blackboard key as written, when a key
  SlotId slot = kNoSlot;  // the entry when a key
  PortDirection direction = PortDirection::unknown;
  bool from_blackboard() const { return slot != kNoSlot; }
  // A `{key}` port the node reads (getInput) or writes (setOutput), by its declared direction.
  bool reads_entry() const {
    return from_blackboard() &&
           (direction == PortDirection::input || direction == PortDirection::inout);
  }
  bool writes_entry() const {
    return from_blackboard() &&
           (direction == PortDirection::output || direction == PortDirection::inout);
  }
};

// "MoveTo(goal=A,speed=2)": a leaf's name qualified by its ports in name order, as world.json
// and scenarios key a leaf; `value` gives a port's value (its literal, or the entry it reads).
std::string qualified_leaf_key(const std::string& name, std::span<const LeafPort> ports,
                               const std::function<std::string(const LeafPort&)>& value);

// What a World learns about a robot leaf once, when it is instantiated.
struct LeafBinding {
  NodeId node;
  const std::string& kind;             // registered name: MoveForward, IsArmInPosition
  const std::string& declared_family;  // "Action"/"Condition" for explicit syntax, else ""
  std::span<const LeafPort> ports;
  const NodeInfo& info;
  Blackboard& blackboard;
};

// What a World gets on every tick or halt of a robot leaf.
struct LeafContext {
  NodeId node;
  std::uint32_t handle;  // what bind_leaf returned for this node
  std::uint64_t tick;    // the engine's root tick number (1 for the first tick)
  std::span<const LeafPort> ports;
  Blackboard& blackboard;

  // The port's value: its blackboard entry (nullptr when that is empty) or, for a literal,
  // nullptr and the text in ports[i].literal.
  const ScriptValue* entry(std::size_t port) const {
    return ports[port].from_blackboard() && !blackboard.value(ports[port].slot).empty()
               ? &blackboard.value(ports[port].slot)
               : nullptr;
  }
};

// The robot side of the engine: every leaf that is not a BT.CPP built-in. tick_leaf returns
// RUNNING, SUCCESS, FAILURE (or SKIPPED); halt_leaf is called only for a leaf that is
// RUNNING, exactly once per halt, as BT.CPP's haltNode.
class World {
 public:
  virtual ~World() = default;
  // Called once per leaf instance (also for instances a hot swap creates). The returned
  // handle comes back in every LeafContext of that node, for O(1) per-tick lookups.
  virtual std::uint32_t bind_leaf(const LeafBinding& leaf) = 0;
  virtual NodeStatus tick_leaf(const LeafContext& leaf) = 0;
  virtual void halt_leaf(const LeafContext& leaf) = 0;
  // For traces: the state entries a condition leaf reads, with their values now (an empty
  // value: not set). Empty for actions; the default knows of no conditions.
  virtual std::vector<std::pair<std::string, ScriptValue>> condition_reads(
      const LeafContext& /*leaf*/) const {
    return {};
  }
};

// What the simulated world did with a leaf on one tick.
enum class LeafEvent : std::uint8_t {
  condition,        // a condition was checked (status: its answer)
  action_started,   // an action's first tick
  action_finished,  // an action completed (status: its result; effects applied)
  action_halted,    // a RUNNING action was halted (it starts over next time)
};
const char* leaf_event_name(LeafEvent event);

struct LeafLogEntry {
  std::uint64_t tick = 0;
  NodeId node = kNoNode;
  std::string leaf;  // the state key or action name used: IsArmInPosition(function=drilling)
  LeafEvent event = LeafEvent::condition;
  NodeStatus status = NodeStatus::idle;
};

// The simulated robot of a scenario (ARCHITECTURE §8). Its state is the engine's root blackboard,
// so scripts (`battery < 20`, `terrain == 'rocks'`) see it and may change it.
//
// Which leaves are conditions, in this order:
//   1. a leaf listed under the scenario's "actions" is an action;
//   2. one declared Condition (explicit <Condition ID=…> or a node model) is a condition,
//      one declared Action is an action;
//   3. one whose state key (below) the scenario sets anywhere (initial, events, effects) is a
//      condition;
//   4. anything else is an action (unlisted: 1 tick, SUCCESS).
// A condition returns SUCCESS iff its state variable holds true (numbers: non-zero); unset is
// false. The SubTree scopes do not matter: the world's state lives in the root scope.
//
// Leaves with ports: `<IsArmInPosition function="drilling"/>` reads the state key
// "IsArmInPosition(function=drilling)" when it is set, else "IsArmInPosition".
// Several ports are listed sorted by name and comma-separated, with the value a `{key}` port
// currently reads. Actions are looked up the same way in "actions".
//
// An action's `ticks`-th consecutive tick applies its effects and returns its result; the
// ticks before return RUNNING. A halted action starts over.
class SimWorld : public World {
 public:
  explicit SimWorld(Scenario scenario, std::vector<bt::NodeModel> robot_nodes = {});
  SimWorld(const SimWorld&) = delete;  // leaves point into scenario_
  SimWorld& operator=(const SimWorld&) = delete;

  // Writes the scenario's initial state into the root scope.
  void apply_initial(Blackboard& blackboard) const;
  // Applies an event's "set" (its uplink is for the manager).
  void apply_event(const ScenarioEvent& event, Blackboard& blackboard) const;

  const Scenario& scenario() const { return scenario_; }
  bool is_condition(std::uint32_t handle) const { return leaves_[handle].condition; }
  const std::vector<LeafLogEntry>& log() const { return log_; }
  void clear_log() { log_.clear(); }
  // Condition checks are logged unless turned off (long runs).
  void log_conditions(bool on) { log_conditions_ = on; }

  std::uint32_t bind_leaf(const LeafBinding& leaf) override;
  NodeStatus tick_leaf(const LeafContext& leaf) override;
  void halt_leaf(const LeafContext& leaf) override;
  std::vector<std::pair<std::string, ScriptValue>> condition_reads(
      const LeafContext& leaf) const override;

 private:
  struct Leaf {
    NodeId node = kNoNode;
    std::string name;
    std::string label;     // qualified key with literal ports; computed per tick otherwise
    bool dynamic = false;  // a port reads the blackboard
    bool condition = false;
    SlotId qualified = kNoSlot, plain = kNoSlot;  // conditions (root scope)
    const ActionSpec* action = nullptr;           // nullptr: unlisted action
    std::vector<std::pair<SlotId, ScriptValue>> effects;
    std::int64_t elapsed = 0;
    const ActionRun* run = nullptr;  // the scripted run of the current start, if any
  };
  std::string qualified_key(const Leaf& leaf, std::span<const LeafPort> ports,
                            const Blackboard& blackboard) const;
  // The value a condition reads now (nullptr: unset); the key it looked up when its ports
  // read the blackboard.
  const ScriptValue* condition_value(const Leaf& leaf, const LeafContext& context,
                                     std::string& dynamic_key) const;

  Scenario scenario_;
  std::vector<bt::NodeModel> robot_nodes_;
  std::vector<Leaf> leaves_;
  std::vector<LeafLogEntry> log_;
  bool log_conditions_ = true;
  std::map<const ActionSpec*, std::size_t> starts_;  // per action with runs: starts so far
};

}  // namespace uabt::runtime
