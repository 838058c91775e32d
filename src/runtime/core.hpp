// Internal to the runtime: the engine's data and the per-family tick functions
// (controls/, decorators/, leaves/). Not for use outside src/runtime.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bt/node_kinds.hpp"
#include "runtime/blackboard.hpp"
#include "runtime/engine.hpp"
#include "runtime/script/program.hpp"
#include "runtime/world.hpp"

namespace uabt::runtime::detail {

// A node's kind from the node catalogue; a robot's leaf is Kind::robot.
using Kind = bt::NodeKind;

// An integer or boolean input port of a built-in node: a literal, or `{key}` read on every
// tick (BT.CPP's getInput). Absent and without default: an error at tick, as in BT.CPP.
struct Input {
  bool present = false;
  SlotId slot = kNoSlot;
  std::int64_t value = 0;
};

// Hot per-node data.
struct RtNode {
  Kind kind = Kind::always_success;
  NodeStatus status = NodeStatus::idle;
  bool alive = true;
  std::uint32_t first_child = 0;  // into Core::children
  std::uint32_t child_count = 0;
  std::uint32_t params = 0;                  // into Core::params, for kinds that have some
  std::uint32_t conditions = kNoConditions;  // into Core::conditions
  // What the node remembers between ticks, in three words saved and restored in this order,
  // under the names BT.CPP's node gives them (Parallel's completed flags: Core::child_done).
  std::array<std::int32_t, 3> memory{};
  std::int32_t& current_child_idx() { return memory[0]; }  // Sequence, Fallback, *WithMemory
  std::int32_t current_child_idx() const { return memory[0]; }
  std::int32_t& child_idx() { return memory[0]; }     // IfThenElse: branch being run (0: condition)
  std::int32_t& repeat_count() { return memory[0]; }  // Repeat
  std::int32_t& try_count() { return memory[0]; }     // RetryUntilSuccessful
  std::int32_t& already_ticked() { return memory[0]; }   // RunOnce (0/1)
  std::int32_t& skipped_count() { return memory[1]; }    // Sequence, Fallback, *WithMemory
  std::int32_t& success_count() { return memory[1]; }    // Parallel
  std::int32_t& returned_status() { return memory[1]; }  // RunOnce
  std::int32_t& failure_count() { return memory[2]; }    // Parallel, ParallelAll
  static constexpr std::uint32_t kNoConditions = UINT32_MAX;
};

// BT.CPP 4.x pre-/post-condition scripts of one node (into Core::programs, -1: none), in
// BT.CPP's order of evaluation.
struct ConditionScripts {
  enum Pre { failure_if, success_if, skip_if, while_true, pre_count };
  enum Post { on_halted, on_failure, on_success, always, post_count };
  std::int32_t pre[pre_count] = {-1, -1, -1, -1};
  std::int32_t post[post_count] = {-1, -1, -1, -1};
};

struct NodeParams {
  Input in0, in1;             // Parallel: success_count, failure_count; ParallelAll: max_failures;
                              // Repeat: num_cycles; Retry: num_attempts; RunOnce: then_skip
  std::uint32_t program = 0;  // Script, ScriptCondition: into Core::programs
  std::uint32_t world_handle = 0;                  // robot leaf: World::bind_leaf's answer
  std::uint32_t ports_begin = 0, ports_count = 0;  // robot leaf: into Core::leaf_ports
  std::uint32_t instance = 0;                      // SubTree: the instance it calls
};

struct Instance {
  std::string tree_id;
  NodeId call = kNoNode;  // the SubTree node; kNoNode for the main tree
  NodeId root = kNoNode;
  ScopeId scope = Blackboard::kRootScope;
  bool alive = true;
  std::shared_ptr<const bt::TreeDef> pending;  // a deferred swap
};

struct SmartSelection;

// A model checker's undo log inside a tick (TickTrail, engine_state.hpp): each node's state
// as it was before its first change since the last checkpoint, and the execute_tick frames
// now open. Every change of a node's state happens in its own execute_tick or halt_node, or
// in set_status: those log it.
struct Trail {
  struct Entry {
    NodeId id;
    NodeStatus status;
    std::array<std::int32_t, 3> memory;
  };
  std::vector<Entry> entries;
  std::vector<std::uint32_t> stamp;  // per node: the epoch it was last logged in
  std::uint32_t epoch = 1;           // a new one at every checkpoint and every restore
  std::vector<NodeId> path;          // root first

  void log(const std::vector<RtNode>& nodes, NodeId id) {
    if (stamp[id] == epoch) return;
    stamp[id] = epoch;
    const RtNode& n = nodes[id];
    entries.push_back({id, n.status, n.memory});
  }
};

struct Core {
  World* world = nullptr;
  EngineOptions options;
  std::shared_ptr<SmartSelection> smart;  // EngineOptions::smart_selection (smart_selection.hpp)

  Blackboard bb;
  std::vector<RtNode> nodes;
  std::vector<NodeId> children;
  std::vector<std::uint8_t> child_done;  // Parallel*: completed flag per child slot
  std::vector<NodeInfo> info;
  std::vector<NodeParams> params;
  std::vector<LeafPort> leaf_ports;
  std::vector<script::Program> programs;
  std::vector<ConditionScripts> conditions;
  std::vector<Instance> instances;

  std::map<std::string, std::shared_ptr<const bt::TreeDef>, std::less<>> defs;
  // The robot's port directions (the document's <TreeNodesModel>): node ID -> port -> direction.
  std::map<std::string, std::map<std::string, PortDirection, std::less<>>, std::less<>>
      port_directions;
  std::vector<std::shared_ptr<const bt::TreeDef>> retired;  // replaced, still referenced
  std::string file;  // the document's displayed path, for trees without their own
  int format = 4;    // the document's BTCPP_format (3: v3 SubTree attributes apply)
  NodeId root = kNoNode;

  std::string tree_path(NodeId node) const;
  std::string instance_path(NodeId node) const;

  std::vector<Observer*> observers;
  std::vector<TickError> errors;
  Stats stats;
  std::uint64_t tick = 0;
  NodeStatus last_result = NodeStatus::idle;

  // BT.CPP's WakeUpSignal: set by a node that wants the root ticked again within this tick;
  // cleared only when Engine::tick() tests it, so one set in a tick that completes carries
  // into the next tick (as in BT.CPP).
  bool wake_up = false;
  NodeId wake_up_node = kNoNode;  // the node that emitted it last (for the loop guard)
  bool in_wake_up_loop = false;   // the root is being ticked again within the tick
  Trail* trail = nullptr;         // TickTrail's log, when one is attached
  void emit_wake_up(NodeId id) {
    wake_up = true;
    wake_up_node = id;
  }

  NodeId child(NodeId parent, std::uint32_t i) const {
    return children[nodes[parent].first_child + i];
  }

  void set_status(NodeId id, NodeStatus s) {
    NodeStatus& current = nodes[id].status;
    if (current == s) return;
    if (trail != nullptr) trail->log(nodes, id);
    const NodeStatus previous = current;
    current = s;
    if (!observers.empty()) notify(id, previous, s);
  }
  void notify(NodeId id, NodeStatus previous, NodeStatus next);

  NodeStatus execute_tick(NodeId id);
  void notify_ticked(NodeId id, NodeStatus result);
  NodeStatus tick_kind(NodeId id);  // the node's own tick(), without its conditions
  // _failureIf/_successIf/_skipIf/_while: the status they impose, or idle for "tick it".
  NodeStatus check_preconditions(NodeId id);
  // _onSuccess/_onFailure/_post after a completed tick; FAILURE if a script fails.
  NodeStatus run_postconditions(NodeId id, NodeStatus status);
  // Runs one condition script; its truth in *truth when asked. Throws (fail) when the script
  // fails or has no truth value.
  void run_condition_script(NodeId id, std::int32_t program, const char* attribute, bool* truth);
  // BT.CPP's haltNode(): the kind's halt (its state and its children), then IDLE.
  void halt_node(NodeId id);
  // ControlNode::haltChild / resetChildren: halt if RUNNING, then IDLE.
  void halt_child(NodeId parent, std::uint32_t i) {
    const NodeId c = child(parent, i);
    if (nodes[c].status == NodeStatus::running) halt_node(c);
    set_status(c, NodeStatus::idle);
  }
  void reset_children(NodeId parent) {
    for (std::uint32_t i = 0; i < nodes[parent].child_count; ++i) halt_child(parent, i);
  }

  // What BT.CPP throws at tick: records it and throws TickException. `script` is the code of
  // the script that failed, if any.
  [[noreturn]] void fail(NodeId id, const std::string& message, const std::string& script = {});
  // An Input's value now (BT.CPP's getInput). The throwing form fails when it is absent or
  // not an integer/boolean; try_read_* leaves `out` alone then, as BT.CPP's nodes that ignore
  // getInput's answer do.
  std::int64_t read_int(NodeId id, const Input& input, const char* port);
  bool try_read_int(const Input& input, std::int64_t& out) const;
  bool try_read_bool(const Input& input, bool& out) const;

  // Binds a robot leaf to `world` (World::bind_leaf) and keeps its handle.
  void bind_world_leaf(NodeId id);

  LeafContext leaf_context(NodeId id) {
    const NodeParams& p = params[nodes[id].params];
    return LeafContext{id, p.world_handle, tick,
                       std::span<const LeafPort>(leaf_ports.data() + p.ports_begin, p.ports_count),
                       bb};
  }
};

// Node families (BT.CPP's class per file). tick_* is the node's tick(); halt_* its halt()
// where it has state to reset (the core then resets its children and status).
NodeStatus tick_sequence(Core& core, NodeId id);
NodeStatus tick_sequence_with_memory(Core& core, NodeId id);
NodeStatus tick_reactive_sequence(Core& core, NodeId id);
NodeStatus tick_fallback(Core& core, NodeId id);
NodeStatus tick_reactive_fallback(Core& core, NodeId id);
NodeStatus tick_parallel(Core& core, NodeId id);
void halt_parallel(Core& core, NodeId id);
NodeStatus tick_parallel_all(Core& core, NodeId id);
void halt_parallel_all(Core& core, NodeId id);
NodeStatus tick_if_then_else(Core& core, NodeId id);
NodeStatus tick_while_do_else(Core& core, NodeId id);

NodeStatus tick_inverter(Core& core, NodeId id);
NodeStatus tick_force_success(Core& core, NodeId id);
NodeStatus tick_force_failure(Core& core, NodeId id);
NodeStatus tick_repeat(Core& core, NodeId id);
NodeStatus tick_retry_until_successful(Core& core, NodeId id);
NodeStatus tick_keep_running_until_failure(Core& core, NodeId id);
NodeStatus tick_run_once(Core& core, NodeId id);
NodeStatus tick_subtree(Core& core, NodeId id);

NodeStatus tick_always_success(Core& core, NodeId id);
NodeStatus tick_always_failure(Core& core, NodeId id);
NodeStatus tick_script(Core& core, NodeId id);
NodeStatus tick_script_condition(Core& core, NodeId id);
NodeStatus tick_world_leaf(Core& core, NodeId id);
void halt_world_leaf(Core& core, NodeId id);

// The truth of a script result as BT.CPP's cast<bool>: booleans, numbers (non-zero), and the
// strings "true"/"false"/"1"/"0". False when it has none.
bool script_truth(const ScriptValue& value, bool& truth);
// "<error> in `<code>` (column N)".
std::string script_error(const script::Program& program, const script::ScriptError& e);

// Instantiation (build.cpp). `bind_world` false: a dry run that validates a definition.
struct Builder {
  explicit Builder(Core& c, bool bind = true) : core(c), bind_world(bind) {}

  Core& core;
  bool bind_world;
  std::vector<std::string> call_stack;  // tree ids being instantiated (cycles, nesting)

  // Instantiates `def` as instance `instance` (already in core.instances).
  NodeId instantiate_tree(const std::shared_ptr<const bt::TreeDef>& def, std::uint32_t instance,
                          NodeId parent);

 private:
  NodeId instantiate_node(const bt::Node& xml, const bt::TreeDef& def, std::uint32_t instance,
                          NodeId parent, std::uint32_t child_index, int depth);
};

// Everything created after a point, for undoing a failed instantiation.
struct CoreMark {
  std::size_t nodes, children, params, leaf_ports, programs, conditions, instances;
  Blackboard::Mark bb;
};
CoreMark mark(const Core& core);
void rollback(Core& core, const CoreMark& mark);

}  // namespace uabt::runtime::detail
