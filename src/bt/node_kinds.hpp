#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bt/tree.hpp"

namespace uabt::bt {

enum class Family { control, decorator, action, condition, subtree, unknown };

const char* family_name(Family f);
// The family a <TreeNodesModel> element name stands for; unknown for any other name.
Family family_named(std::string_view name);
// <Action|Condition|Control|Decorator ID="…">: the explicit form of a node.
bool is_explicit_family_tag(std::string_view tag);
// BT.CPP: an attribute that starts with a letter and is not `name` or `ID` sets a port
// (_autoremap, _skipIf, _description, … do not).
bool is_port_attribute(std::string_view attribute);

// The node catalogue: every kind of node BehaviorTree.CPP 4.10 registers itself (plus the v3
// spellings uabt still reads). The one place that knows a built-in by its name: everything else
// asks by NodeKind or by property. Values are stable; a new kind goes before `robot`, which
// stands for none of them: a node the robot registers. BlackboardCheck* are v3 only.
enum class NodeKind : std::uint8_t {
  sequence,
  sequence_with_memory,
  reactive_sequence,
  fallback,
  reactive_fallback,
  async_sequence,
  async_fallback,
  parallel,
  parallel_all,
  if_then_else,
  while_do_else,
  try_catch,
  switch2,
  switch3,
  switch4,
  switch5,
  switch6,
  manual_selector,
  inverter,
  force_success,
  force_failure,
  repeat,
  retry_until_successful,
  keep_running_until_failure,
  run_once,
  delay,
  timeout,
  precondition,
  loop_int,
  loop_bool,
  loop_double,
  loop_string,
  skip_unless_updated,
  wait_value_update,
  blackboard_check_int,
  blackboard_check_double,
  blackboard_check_string,
  always_success,
  always_failure,
  script,
  set_blackboard,
  unset_blackboard,
  sleep,
  was_entry_updated,
  script_condition,
  subtree,
  robot
};

struct BuiltinNode {
  const char* name;  // as registered; a v3 spelling names the same kind as its v4 name
  NodeKind kind;
  Family family;
  int min_children;         // load-time rule: decorator exactly 1, control >= 1, leaves 0
  int max_children;         // -1: unbounded
  std::vector<Port> ports;  // providedPorts(), as BT.CPP 4.10 declares them
  bool reactive = false;    // ticks its earlier children again while a later one runs
  bool memory = false;      // a running run resumes at the child that was running
  std::vector<std::string> v3_ports = {};  // other port names BT.CPP 3.8 read
  bool v3 = false;                         // a v3 spelling
};

const std::vector<BuiltinNode>& builtin_nodes();
// The entry named `name` (either spelling); nullptr for a name that is not built in.
const BuiltinNode* find_builtin(std::string_view name);
// `name`'s kind; NodeKind::robot when it is not built in.
NodeKind node_kind(std::string_view name);
// The v4 entry of a kind (not robot), and its registered name, as compiled trees write it.
const BuiltinNode& builtin(NodeKind kind);
const char* kind_name(NodeKind kind);
// A SubTree call (SubTree, or v3's SubTreePlus).
inline bool is_subtree(std::string_view name) {
  return node_kind(name) == NodeKind::subtree;
}

// BT.CPP's ID rule: no space, tab, newline, < > & " ' / \ : * ? | .
bool is_valid_id(const std::string& id);

}  // namespace uabt::bt
