#pragma once
#include <string>
#include <vector>

namespace uabt::bt {

enum class Family { control, decorator, action, condition, subtree, unknown };

const char* family_name(Family f);

// A node BehaviorTree.CPP 4.x registers itself (plus the v3 spellings it still accepts).
struct BuiltinNode {
  const char* name;
  Family family;
  int min_children;  // load-time rule: decorator exactly 1, control >= 1, leaves 0
  int max_children;  // -1: unbounded
};

const BuiltinNode* find_builtin(const std::string& name);
const std::vector<BuiltinNode>& builtin_nodes();

// BT.CPP's ID rule: no space, tab, newline, < > & " ' / \ : * ? | .
bool is_valid_id(const std::string& id);

}  // namespace uabt::bt
