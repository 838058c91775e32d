#include "bt/node_kinds.hpp"

#include <cctype>
#include <unordered_map>

namespace uabt::bt {

const char* family_name(Family f) {
  // The element names <TreeNodesModel> uses for each family.
  switch (f) {
    case Family::control: return "Control";
    case Family::decorator: return "Decorator";
    case Family::action: return "Action";
    case Family::condition: return "Condition";
    case Family::subtree: return "SubTree";
    case Family::unknown: return "Unknown";
  }
  return "Unknown";
}

Family family_named(std::string_view name) {
  for (const Family f :
       {Family::control, Family::decorator, Family::action, Family::condition, Family::subtree})
    if (name == family_name(f)) return f;
  return Family::unknown;
}

bool is_explicit_family_tag(std::string_view tag) {
  const Family f = family_named(tag);
  return f != Family::subtree && f != Family::unknown;
}

bool is_port_attribute(std::string_view attribute) {
  return !attribute.empty() && std::isalpha(static_cast<unsigned char>(attribute.front())) &&
         attribute != "name" && attribute != "ID";
}

namespace {

Port in(std::string name, std::string type, std::string default_value = {}) {
  return {"input_port", std::move(name), std::move(type), std::move(default_value), {}};
}
Port out(std::string name, std::string type) {
  return {"output_port", std::move(name), std::move(type), {}, {}};
}
Port inout(std::string name, std::string type) {
  return {"inout_port", std::move(name), std::move(type), {}, {}};
}

std::vector<Port> switch_ports(int cases) {
  std::vector<Port> ports{in("variable", "std::string")};
  for (int k = 1; k <= cases; ++k) ports.push_back(in("case_" + std::to_string(k), "std::string"));
  return ports;
}

std::vector<Port> loop_ports(const std::string& type) {
  return {inout("queue", ""), in("if_empty", "BT::NodeStatus", "SUCCESS"), out("value", type)};
}

std::vector<Port> check_ports() {
  return {in("value_A", ""), in("value_B", ""),
          in("return_on_mismatch", "BT::NodeStatus", "FAILURE")};
}

BuiltinNode control(const char* name, NodeKind kind, std::vector<Port> ports = {},
                    bool reactive = false, bool memory = false) {
  return {name, kind, Family::control, 1, -1, std::move(ports), reactive, memory};
}
BuiltinNode decorator(const char* name, NodeKind kind, std::vector<Port> ports = {}) {
  return {name, kind, Family::decorator, 1, 1, std::move(ports)};
}
BuiltinNode leaf(const char* name, NodeKind kind, Family family, std::vector<Port> ports = {}) {
  return {name, kind, family, 0, 0, std::move(ports)};
}
BuiltinNode v3(BuiltinNode node) {
  node.v3 = true;
  return node;
}

}  // namespace

const std::vector<BuiltinNode>& builtin_nodes() {
  // BehaviorTreeFactory's constructor in BT.CPP 4.10 (src/bt_factory.cpp) with each node's
  // providedPorts(), plus the v3 names that 3.8 registered. SwitchN needs N cases + a default;
  // IfThenElse/WhileDoElse 2-3.
  using K = NodeKind;
  constexpr bool reactive = true, memory = true;
  static const std::vector<BuiltinNode> table = {
      // Controls
      control("Sequence", K::sequence, {}, !reactive, memory),
      control("SequenceWithMemory", K::sequence_with_memory, {}, !reactive, memory),
      control("ReactiveSequence", K::reactive_sequence, {}, reactive),
      control("Fallback", K::fallback, {}, !reactive, memory),
      control("ReactiveFallback", K::reactive_fallback, {}, reactive),
      control("AsyncSequence", K::async_sequence, {}, !reactive, memory),
      control("AsyncFallback", K::async_fallback, {}, !reactive, memory),
      {"Parallel",
       K::parallel,
       Family::control,
       1,
       -1,
       {in("success_count", "int", "-1"), in("failure_count", "int", "1")},
       !reactive,
       !memory,
       {"success_threshold", "failure_threshold"}},
      control("ParallelAll", K::parallel_all, {in("max_failures", "int", "1")}),
      {"IfThenElse", K::if_then_else, Family::control, 2, 3, {}, !reactive, memory},
      {"WhileDoElse", K::while_do_else, Family::control, 2, 3, {}, reactive},
      control("TryCatch", K::try_catch, {in("catch_on_halt", "bool", "false")}, !reactive, memory),
      {"Switch2", K::switch2, Family::control, 3, 3, switch_ports(2)},
      {"Switch3", K::switch3, Family::control, 4, 4, switch_ports(3)},
      {"Switch4", K::switch4, Family::control, 5, 5, switch_ports(4)},
      {"Switch5", K::switch5, Family::control, 6, 6, switch_ports(5)},
      {"Switch6", K::switch6, Family::control, 7, 7, switch_ports(6)},
      control("ManualSelector", K::manual_selector, {in("repeat_last_selection", "bool", "false")},
              !reactive, memory),
      v3(control("SequenceStar", K::sequence_with_memory, {}, !reactive, memory)),
      // Decorators
      decorator("Inverter", K::inverter),
      decorator("ForceSuccess", K::force_success),
      decorator("ForceFailure", K::force_failure),
      decorator("Repeat", K::repeat, {in("num_cycles", "int")}),
      decorator("RetryUntilSuccessful", K::retry_until_successful, {in("num_attempts", "int")}),
      decorator("KeepRunningUntilFailure", K::keep_running_until_failure),
      decorator("RunOnce", K::run_once, {in("then_skip", "bool", "true")}),
      decorator("Delay", K::delay, {in("delay_msec", "unsigned int")}),
      decorator("Timeout", K::timeout, {in("msec", "unsigned int")}),
      decorator("Precondition", K::precondition,
                {in("if", "std::string"), in("else", "BT::NodeStatus", "FAILURE")}),
      decorator("LoopInt", K::loop_int, loop_ports("int")),
      decorator("LoopBool", K::loop_bool, loop_ports("bool")),
      decorator("LoopDouble", K::loop_double, loop_ports("double")),
      decorator("LoopString", K::loop_string, loop_ports("std::string")),
      decorator("SkipUnlessUpdated", K::skip_unless_updated, {in("entry", "")}),
      decorator("WaitValueUpdate", K::wait_value_update, {in("entry", "")}),
      v3(decorator("RetryUntilSuccesful", K::retry_until_successful, {in("num_attempts", "int")})),
      v3(decorator("BlackboardCheckInt", K::blackboard_check_int, check_ports())),
      v3(decorator("BlackboardCheckDouble", K::blackboard_check_double, check_ports())),
      v3(decorator("BlackboardCheckString", K::blackboard_check_string, check_ports())),
      // Actions (WasEntryUpdated is a SyncActionNode in BT.CPP, used as a condition)
      leaf("AlwaysSuccess", K::always_success, Family::action),
      leaf("AlwaysFailure", K::always_failure, Family::action),
      leaf("Script", K::script, Family::action, {in("code", "std::string")}),
      leaf("SetBlackboard", K::set_blackboard, Family::action,
           {in("value", ""), inout("output_key", "")}),
      leaf("UnsetBlackboard", K::unset_blackboard, Family::action, {in("key", "std::string")}),
      leaf("Sleep", K::sleep, Family::action, {in("msec", "unsigned int")}),
      leaf("WasEntryUpdated", K::was_entry_updated, Family::action, {in("entry", "")}),
      // Conditions (ScriptCondition's code port has no type: InputPort("code", …))
      leaf("ScriptCondition", K::script_condition, Family::condition, {in("code", "")}),
      // Subtrees: their remapping is free, no ports here
      leaf("SubTree", K::subtree, Family::subtree),
      v3(leaf("SubTreePlus", K::subtree, Family::subtree)),
  };
  return table;
}

const BuiltinNode* find_builtin(std::string_view name) {
  static const auto by_name = [] {
    std::unordered_map<std::string_view, const BuiltinNode*> map;
    for (const auto& node : builtin_nodes()) map.emplace(node.name, &node);
    return map;
  }();
  const auto it = by_name.find(name);
  return it == by_name.end() ? nullptr : it->second;
}

NodeKind node_kind(std::string_view name) {
  const BuiltinNode* node = find_builtin(name);
  return node == nullptr ? NodeKind::robot : node->kind;
}

const BuiltinNode& builtin(NodeKind kind) {
  static const auto by_kind = [] {
    std::vector<const BuiltinNode*> v(static_cast<std::size_t>(NodeKind::robot) + 1, nullptr);
    for (const auto& node : builtin_nodes())
      if (!node.v3 || v[static_cast<std::size_t>(node.kind)] == nullptr)
        v[static_cast<std::size_t>(node.kind)] = &node;
    return v;
  }();
  return *by_kind[static_cast<std::size_t>(kind)];
}

const char* kind_name(NodeKind kind) {
  return builtin(kind).name;
}

bool is_valid_id(const std::string& id) {
  static constexpr std::string_view kForbidden = " \t\n\r<>&\"'/\\:*?|.";
  if (id.empty()) return false;
  return id.find_first_of(kForbidden) == std::string::npos;
}

}  // namespace uabt::bt
