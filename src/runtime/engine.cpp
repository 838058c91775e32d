// The tick loop's dispatch, halting, and the Engine's read-only API.
#include "runtime/engine.hpp"

#include <algorithm>
#include <charconv>

#include "runtime/core.hpp"
#include "runtime/smart_selection.hpp"

namespace uabt::runtime {

namespace detail {

void Core::notify(NodeId id, NodeStatus previous, NodeStatus next) {
  for (Observer* observer : observers) observer->on_status_change(id, previous, next);
}

void Core::notify_ticked(NodeId id, NodeStatus result) {
  for (Observer* observer : observers) observer->on_node_ticked(id, result);
}

NodeStatus Core::execute_tick(NodeId id) {
  ++stats.node_ticks;
  if (trail != nullptr) {
    trail->log(nodes, id);
    trail->path.push_back(id);
  }
  NodeStatus s = NodeStatus::idle;
  if (nodes[id].conditions == RtNode::kNoConditions) {
    s = tick_kind(id);
  } else {
    // BT.CPP's executeTick: a pre-condition may replace the tick; post-conditions follow a
    // completed one.
    s = check_preconditions(id);
    if (s == NodeStatus::idle) s = tick_kind(id);
    if (is_completed(s)) s = run_postconditions(id, s);
  }
  if (s == NodeStatus::idle) fail(id, "returned IDLE, which a tick must not");
  // A skipped node stays IDLE; only its parent hears SKIPPED (BT.CPP's executeTick).
  if (s != NodeStatus::skipped) set_status(id, s);
  if (!observers.empty()) notify_ticked(id, s);
  if (trail != nullptr) trail->path.pop_back();
  return s;
}

NodeStatus Core::tick_kind(NodeId id) {
  NodeStatus s = NodeStatus::failure;
  switch (nodes[id].kind) {
    case Kind::sequence: s = tick_sequence(*this, id); break;
    case Kind::sequence_with_memory: s = tick_sequence_with_memory(*this, id); break;
    case Kind::reactive_sequence: s = tick_reactive_sequence(*this, id); break;
    case Kind::fallback: s = tick_fallback(*this, id); break;
    case Kind::reactive_fallback: s = tick_reactive_fallback(*this, id); break;
    case Kind::parallel: s = tick_parallel(*this, id); break;
    case Kind::parallel_all: s = tick_parallel_all(*this, id); break;
    case Kind::if_then_else: s = tick_if_then_else(*this, id); break;
    case Kind::while_do_else: s = tick_while_do_else(*this, id); break;
    case Kind::inverter: s = tick_inverter(*this, id); break;
    case Kind::force_success: s = tick_force_success(*this, id); break;
    case Kind::force_failure: s = tick_force_failure(*this, id); break;
    case Kind::repeat: s = tick_repeat(*this, id); break;
    case Kind::retry_until_successful: s = tick_retry_until_successful(*this, id); break;
    case Kind::keep_running_until_failure: s = tick_keep_running_until_failure(*this, id); break;
    case Kind::run_once: s = tick_run_once(*this, id); break;
    case Kind::subtree: s = tick_subtree(*this, id); break;
    case Kind::always_success: s = tick_always_success(*this, id); break;
    case Kind::always_failure: s = tick_always_failure(*this, id); break;
    case Kind::script: s = tick_script(*this, id); break;
    case Kind::script_condition: s = tick_script_condition(*this, id); break;
    case Kind::robot: s = tick_world_leaf(*this, id); break;
    default: break;  // the builder refuses the built-ins the runtime does not run
  }
  return s;
}

void Core::run_condition_script(NodeId id, std::int32_t program, const char* attribute,
                                bool* truth) {
  script::Program& p = programs[static_cast<std::size_t>(program)];
  const ScriptValue* result = nullptr;
  try {
    result = &p.run(bb);
  } catch (const script::ScriptError& e) {
    fail(id, std::string(attribute) + ": " + script_error(p, e), p.code());
  }
  if (truth != nullptr && !script_truth(*result, *truth))
    fail(id,
         std::string(attribute) + ": the result of `" + p.code() + "` is not a boolean: '" +
             result->to_string() + "'",
         p.code());
}

NodeStatus Core::check_preconditions(NodeId id) {
  using C = ConditionScripts;
  static constexpr const char* kNames[] = {"_failureIf", "_successIf", "_skipIf", "_while"};
  const C& c = conditions[nodes[id].conditions];
  for (int pre = 0; pre < C::pre_count; ++pre) {
    if (c.pre[pre] < 0) continue;
    const NodeStatus status = nodes[id].status;
    bool truth = false;
    if (status == NodeStatus::idle) {
      // Checked when the node starts, not while it runs.
      run_condition_script(id, c.pre[pre], kNames[pre], &truth);
      if (truth) {
        if (pre == C::failure_if) return NodeStatus::failure;
        if (pre == C::success_if) return NodeStatus::success;
        if (pre == C::skip_if) return NodeStatus::skipped;
      } else if (pre == C::while_true) {
        return NodeStatus::skipped;
      }
    } else if (status == NodeStatus::running && pre == C::while_true) {
      // _while is checked on every tick: false halts the running node.
      run_condition_script(id, c.pre[pre], kNames[pre], &truth);
      if (!truth) {
        halt_node(id);
        return NodeStatus::skipped;
      }
    }
  }
  return NodeStatus::idle;
}

NodeStatus Core::run_postconditions(NodeId id, NodeStatus status) {
  using C = ConditionScripts;
  const C& c = conditions[nodes[id].conditions];
  const std::int32_t specific =
      status == NodeStatus::success ? c.post[C::on_success] : c.post[C::on_failure];
  const char* name = status == NodeStatus::success ? "_onSuccess" : "_onFailure";
  if (specific >= 0) run_condition_script(id, specific, name, nullptr);
  if (c.post[C::always] >= 0) run_condition_script(id, c.post[C::always], "_post", nullptr);
  return status;
}

void Core::halt_node(NodeId id) {
  if (trail != nullptr) trail->log(nodes, id);
  RtNode& n = nodes[id];
  switch (n.kind) {
    case Kind::sequence:
    case Kind::fallback:
      n.current_child_idx() = 0;
      n.skipped_count() = 0;
      break;
    case Kind::if_then_else: n.child_idx() = 0; break;
    case Kind::repeat: n.repeat_count() = 0; break;
    case Kind::retry_until_successful: n.try_count() = 0; break;
    case Kind::parallel: halt_parallel(*this, id); break;
    case Kind::parallel_all: halt_parallel_all(*this, id); break;
    case Kind::robot:
      if (n.status == NodeStatus::running) halt_world_leaf(*this, id);
      break;
    // SequenceWithMemory keeps its index and RunOnce its memory (BT.CPP); the others have
    // no state of their own.
    default: break;
  }
  reset_children(id);
  set_status(id, NodeStatus::idle);
  if (n.conditions != RtNode::kNoConditions) {
    const std::int32_t on_halted = conditions[n.conditions].post[ConditionScripts::on_halted];
    if (on_halted >= 0) run_condition_script(id, on_halted, "_onHalted", nullptr);
  }
}

void Core::fail(NodeId id, const std::string& message, const std::string& script) {
  ++stats.errors;
  const NodeInfo& i = info[id];
  TickError error{tick, id, i.place() + ": " + message, instance_path(id), script};
  if (errors.size() < options.max_recorded_errors) errors.push_back(error);
  throw TickException(std::move(error));
}

std::string Core::tree_path(NodeId node) const {
  std::vector<NodeId> chain;
  const std::uint32_t instance = info[node].instance;
  for (NodeId n = node; n != kNoNode && info[n].instance == instance; n = info[n].parent)
    chain.push_back(n);
  std::string path = info[node].tree_id;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const NodeInfo& i = info[*it];
    path += "/" + i.tag;
    if (it != chain.rbegin()) path += "[" + std::to_string(i.child_index) + "]";
  }
  return path;
}

std::string Core::instance_path(NodeId node) const {
  const Instance& inst = instances[info[node].instance];
  const std::string own = tree_path(node);
  return inst.call == kNoNode ? own : instance_path(inst.call) + "/" + own;
}

namespace {

bool int_from_value(const ScriptValue& v, std::int64_t& out) {
  switch (v.kind) {
    case ScriptValue::Kind::integer: out = v.integer; return true;
    case ScriptValue::Kind::real:
      if (v.real != static_cast<double>(static_cast<std::int64_t>(v.real))) return false;
      out = static_cast<std::int64_t>(v.real);
      return true;
    case ScriptValue::Kind::string: {
      const char* last = v.text.data() + v.text.size();
      const auto [end, ec] = std::from_chars(v.text.data(), last, out);
      return ec == std::errc() && end == last && !v.text.empty();
    }
    default: return false;
  }
}

}  // namespace

bool Core::try_read_int(const Input& input, std::int64_t& out) const {
  if (!input.present) return false;
  if (input.slot == kNoSlot) {
    out = input.value;
    return true;
  }
  std::int64_t v = 0;
  if (!int_from_value(bb.read(input.slot), v)) return false;
  out = v;
  return true;
}

std::int64_t Core::read_int(NodeId id, const Input& input, const char* port) {
  std::int64_t out = 0;
  if (try_read_int(input, out)) return out;
  if (!input.present) fail(id, std::string("missing required input [") + port + "]");
  const ScriptValue& v = bb.read(input.slot);
  if (v.empty())
    fail(id, std::string("input [") + port + "] reads blackboard key '" + bb.key(input.slot) +
                 "', which is not set");
  fail(id, std::string("input [") + port + "]: '" + v.to_string() + "' (key '" +
               bb.key(input.slot) + "') is not an integer");
}

bool Core::try_read_bool(const Input& input, bool& out) const {
  if (!input.present) return false;
  if (input.slot == kNoSlot) {
    out = input.value != 0;
    return true;
  }
  const ScriptValue& v = bb.read(input.slot);
  std::int64_t i = 0;
  if (v.kind == ScriptValue::Kind::boolean) {
    out = v.boolean;
  } else if (v.is_string() && (v.text == "true" || v.text == "false")) {
    out = v.text == "true";
  } else if (!v.empty() && int_from_value(v, i) && (i == 0 || i == 1)) {
    out = i == 1;
  } else {
    return false;
  }
  return true;
}

}  // namespace detail

Engine::Engine(std::unique_ptr<detail::Core> core) : core_(std::move(core)) {}
Engine::Engine(Engine&&) noexcept = default;
Engine& Engine::operator=(Engine&&) noexcept = default;
Engine::~Engine() = default;

NodeStatus Engine::tick() {
  detail::Core& c = *core_;
  ++c.tick;
  ++c.stats.root_ticks;
  return tick_root();
}

NodeStatus Engine::resume_tick() {
  return tick_root();
}

NodeStatus Engine::tick_root() {
  detail::Core& c = *core_;
  c.in_wake_up_loop = false;
  if (c.trail != nullptr) c.trail->path.clear();
  NodeStatus s = c.execute_tick(c.root);
  if (s == NodeStatus::running && c.wake_up) s = wake_up_loop();
  c.last_result = s;
  if (is_completed(s)) c.set_status(c.root, NodeStatus::idle);  // BT.CPP's resetStatus()
  apply_pending_swaps();
  return s;
}

// Tree::tickRoot's inner loop: the flag is tested (and cleared) only while the root runs.
NodeStatus Engine::wake_up_loop() {
  detail::Core& c = *core_;
  NodeStatus s = NodeStatus::running;
  std::uint32_t reticks = 0;
  c.in_wake_up_loop = true;
  while (s == NodeStatus::running && c.wake_up) {
    c.wake_up = false;
    if (reticks++ == c.options.max_wakeup_reticks)
      c.fail(c.wake_up_node,
             "asked for a wake-up re-tick " + std::to_string(reticks) +
                 " times within one tick: BehaviorTree.CPP's tickOnce() would never return");
    ++c.stats.wakeup_reticks;
    s = c.execute_tick(c.root);
  }
  c.in_wake_up_loop = false;
  return s;
}

void Engine::halt() {
  // BT.CPP's Tree::haltTree: halt the root, then call halt on every node (so each node's
  // own state is reset and every _onHalted runs, also on IDLE nodes), root first, children
  // in order; a robot leaf hears halt only while it is RUNNING.
  core_->halt_node(core_->root);
  std::vector<NodeId> stack{core_->root};
  while (!stack.empty()) {
    const NodeId n = stack.back();
    stack.pop_back();
    core_->halt_node(n);
    const auto kids = children(n);
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back(*it);
  }
}

NodeId Engine::root() const {
  return core_->root;
}
NodeStatus Engine::status() const {
  return core_->nodes[core_->root].status;
}
NodeStatus Engine::last_result() const {
  return core_->last_result;
}
NodeStatus Engine::status(NodeId node) const {
  return core_->nodes.at(node).status;
}
std::size_t Engine::node_count() const {
  return core_->nodes.size();
}
const NodeInfo& Engine::info(NodeId node) const {
  return core_->info.at(node);
}

std::span<const NodeId> Engine::children(NodeId node) const {
  const detail::RtNode& n = core_->nodes.at(node);
  return {core_->children.data() + n.first_child, n.child_count};
}

std::string Engine::tree_path(NodeId node) const {
  info(node);  // range check
  return core_->tree_path(node);
}

std::string Engine::instance_path(NodeId node) const {
  info(node);  // range check
  return core_->instance_path(node);
}

NodeId Engine::find_path(std::string_view path) const {
  for (NodeId id = 0; id < core_->nodes.size(); ++id)
    if (core_->nodes[id].alive && instance_path(id) == path) return id;
  return kNoNode;
}

std::vector<NodeId> Engine::find_by_name(std::string_view name) const {
  std::vector<NodeId> out;
  for (NodeId id = 0; id < core_->nodes.size(); ++id)
    if (core_->nodes[id].alive && core_->info[id].name == name) out.push_back(id);
  return out;
}

std::vector<NodeId> Engine::subtree_calls(std::string_view tree_id) const {
  std::vector<NodeId> out;
  for (const detail::Instance& inst : core_->instances)
    if (inst.alive && inst.call != kNoNode && inst.tree_id == tree_id) out.push_back(inst.call);
  return out;
}

std::vector<std::pair<std::string, ScriptValue>> Engine::condition_reads(NodeId node) const {
  (void)core_->nodes.at(node);  // range check
  return detail::condition_reads(*core_, node);
}

void Engine::add_observer(Observer* observer) {
  core_->observers.push_back(observer);
}

void Engine::remove_observer(Observer* observer) {
  auto& list = core_->observers;
  list.erase(std::remove(list.begin(), list.end(), observer), list.end());
}

Blackboard& Engine::blackboard() {
  return core_->bb;
}
const Blackboard& Engine::blackboard() const {
  return core_->bb;
}
ScopeId Engine::scope(NodeId node) const {
  return core_->instances[info(node).instance].scope;
}

std::uint64_t Engine::tick_count() const {
  return core_->tick;
}
const Stats& Engine::stats() const {
  return core_->stats;
}
const std::vector<TickError>& Engine::errors() const {
  return core_->errors;
}

}  // namespace uabt::runtime
