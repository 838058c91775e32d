#pragma once
#include <optional>
#include <string>
#include <vector>

#include "conform/context.hpp"

namespace uabt::conform {

// One child of a selection tree's Fallback: [condition-checking subtree, alternative call] or
// [alternative call].
struct Branch {
  std::size_t index = 0;
  const bt::Node* node = nullptr;
  std::string path;
  std::string name;                 // its name attribute (uabt writes the requirement id)
  bool well_formed = false;         // the shape above; otherwise its guard is not compared
  const bt::Node* guard = nullptr;  // nullptr: no guard (a default's branch)
  std::string guard_path;
  const bt::Node* call = nullptr;  // the last child, when it is a SubTree call
  std::string call_path;
  // Names of the adaptable's alternatives the call runs (by tree ID, else by a tree equal to
  // the alternative's main tree); empty when it runs none of them.
  std::vector<std::string> alternatives;
};

struct Selector {
  const bt::TreeDef* tree = nullptr;
  std::string root_path;
  std::vector<Branch> branches;
  // The adaptable node's call(s) in the fixed part all share the parent's blackboard.
  bool blackboard_visible = true;
};

// compiled-selector-shape: finds the selection tree of `adaptable` and reads its branches.
// nullopt when there is no usable selection tree (the reason is reported).
std::optional<Selector> read_selector(Context& ctx, const std::string& adaptable);

}  // namespace uabt::conform
