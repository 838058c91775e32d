// Script (`code`, returns SUCCESS) and ScriptCondition (`code`, returns the result's truth).
// The script was compiled and its keys resolved at instantiation. A script error (an
// undefined key, a type error) is what BT.CPP throws at tick: the tick stops with it.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

std::string script_error(const script::Program& program, const script::ScriptError& e) {
  std::string message = e.what();
  message += " in `" + program.code() + "`";
  if (e.column() > 0) message += " (column " + std::to_string(e.column()) + ")";
  return message;
}

NodeStatus tick_script(Core& core, NodeId id) {
  script::Program& program = core.programs[core.params[core.nodes[id].params].program];
  try {
    program.run(core.bb);
  } catch (const script::ScriptError& e) {
    core.fail(id, script_error(program, e), program.code());
  }
  return NodeStatus::success;
}

bool script_truth(const ScriptValue& value, bool& truth) {
  switch (value.kind) {
    case ScriptValue::Kind::boolean: truth = value.boolean; return true;
    case ScriptValue::Kind::integer:  // BT.CPP's cast<bool>: only 0 and 1
      if (value.integer != 0 && value.integer != 1) return false;
      truth = value.integer == 1;
      return true;
    case ScriptValue::Kind::real: truth = value.real != 0.0; return true;
    case ScriptValue::Kind::string:
      if (value.text == "true" || value.text == "1" || value.text == "false" || value.text == "0") {
        truth = value.text == "true" || value.text == "1";
        return true;
      }
      return false;
    case ScriptValue::Kind::empty: return false;
  }
  return false;
}

NodeStatus tick_script_condition(Core& core, NodeId id) {
  script::Program& program = core.programs[core.params[core.nodes[id].params].program];
  const ScriptValue* result = nullptr;
  try {
    result = &program.run(core.bb);
  } catch (const script::ScriptError& e) {
    core.fail(id, script_error(program, e), program.code());
  }
  bool truth = false;
  if (!script_truth(*result, truth))
    core.fail(
        id,
        "the result of `" + program.code() + "` is not a boolean: '" + result->to_string() + "'",
        program.code());
  return truth ? NodeStatus::success : NodeStatus::failure;
}

}  // namespace uabt::runtime::detail
