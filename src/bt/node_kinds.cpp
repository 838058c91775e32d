#include "bt/node_kinds.hpp"

#include <algorithm>

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

const std::vector<BuiltinNode>& builtin_nodes() {
  // BehaviorTreeFactory's constructor in BT.CPP 4.x (src/bt_factory.cpp), plus the v3 names
  // that 3.8 registered. SwitchN needs N cases + a default; IfThenElse/WhileDoElse 2-3.
  static const std::vector<BuiltinNode> table = {
      // Controls
      {"Sequence", Family::control, 1, -1},
      {"SequenceWithMemory", Family::control, 1, -1},
      {"ReactiveSequence", Family::control, 1, -1},
      {"Fallback", Family::control, 1, -1},
      {"ReactiveFallback", Family::control, 1, -1},
      {"Parallel", Family::control, 1, -1},
      {"ParallelAll", Family::control, 1, -1},
      {"IfThenElse", Family::control, 2, 3},
      {"WhileDoElse", Family::control, 2, 3},
      {"TryCatch", Family::control, 1, -1},
      {"Switch2", Family::control, 3, 3},
      {"Switch3", Family::control, 4, 4},
      {"Switch4", Family::control, 5, 5},
      {"Switch5", Family::control, 6, 6},
      {"Switch6", Family::control, 7, 7},
      {"ManualSelector", Family::control, 1, -1},
      {"SequenceStar", Family::control, 1, -1},  // v3 name of SequenceWithMemory
      // Decorators
      {"Inverter", Family::decorator, 1, 1},
      {"ForceSuccess", Family::decorator, 1, 1},
      {"ForceFailure", Family::decorator, 1, 1},
      {"Repeat", Family::decorator, 1, 1},
      {"RetryUntilSuccessful", Family::decorator, 1, 1},
      {"KeepRunningUntilFailure", Family::decorator, 1, 1},
      {"RunOnce", Family::decorator, 1, 1},
      {"Delay", Family::decorator, 1, 1},
      {"Timeout", Family::decorator, 1, 1},
      {"Precondition", Family::decorator, 1, 1},
      {"LoopInt", Family::decorator, 1, 1},
      {"LoopBool", Family::decorator, 1, 1},
      {"LoopDouble", Family::decorator, 1, 1},
      {"LoopString", Family::decorator, 1, 1},
      {"SkipUnlessUpdated", Family::decorator, 1, 1},
      {"WaitValueUpdate", Family::decorator, 1, 1},
      {"RetryUntilSuccesful", Family::decorator, 1, 1},  // v3 spelling (sic)
      {"BlackboardCheckInt", Family::decorator, 1, 1},   // v3
      {"BlackboardCheckDouble", Family::decorator, 1, 1},
      {"BlackboardCheckString", Family::decorator, 1, 1},
      // Actions (WasEntryUpdated is a SyncActionNode in BT.CPP, used as a condition)
      {"AlwaysSuccess", Family::action, 0, 0},
      {"AlwaysFailure", Family::action, 0, 0},
      {"Script", Family::action, 0, 0},
      {"SetBlackboard", Family::action, 0, 0},
      {"UnsetBlackboard", Family::action, 0, 0},
      {"Sleep", Family::action, 0, 0},
      {"WasEntryUpdated", Family::action, 0, 0},
      // Conditions
      {"ScriptCondition", Family::condition, 0, 0},
      // Subtrees
      {"SubTree", Family::subtree, 0, 0},
      {"SubTreePlus", Family::subtree, 0, 0},  // v3
  };
  return table;
}

const BuiltinNode* find_builtin(const std::string& name) {
  const auto& table = builtin_nodes();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const BuiltinNode& node) { return name == node.name; });
  return it == table.end() ? nullptr : &*it;
}

bool is_valid_id(const std::string& id) {
  static constexpr std::string_view kForbidden = " \t\n\r<>&\"'/\\:*?|.";
  if (id.empty()) return false;
  return id.find_first_of(kForbidden) == std::string::npos;
}

}  // namespace uabt::bt
