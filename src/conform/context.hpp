#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"
#include "load/mission.hpp"

namespace uabt::conform {

// Paths as compile's trace writes them: `<tree>/<RootTag>/<Tag>[i]/…`.
std::string root_path(const bt::TreeDef& tree);
using bt::child_path;

// The remapping attribute a SubTree call may carry: `_autoremap="true"` (v4) or
// `__shared_blackboard="true"` (v3). Anything else on the call is a port remapping.
bool is_remap_attribute(const std::string& name, int bt_format);
// True when the call shares its parent's blackboard.
bool shares_blackboard(const bt::Node& subtree_call, int bt_format);
// The attributes of a SubTree call beyond its ID, its name and a remapping attribute set to
// "true", as key="value": each one stops the call passing its parent's blackboard unchanged.
std::vector<std::string> remapping_attributes(const bt::Node& subtree_call, int bt_format);
// The first attribute a control node of a selector carries besides its kind (an explicit ID of
// <Control ID="Fallback">) and its name, as key="value".
std::optional<std::string> extra_attribute(const bt::Node& n);

// What every rule needs: the mission, the compiled document, and where findings go.
class Context {
 public:
  Context(const load::Mission& mission, const bt::Document& compiled);

  const load::Mission& mission() const { return mission_; }
  const bt::Document& compiled() const { return compiled_; }

  // A finding located at `node` in the compiled file.
  Finding& report(const std::string& check, std::string message, const bt::Node& node,
                  const std::string& path);
  // A finding at a tree's <BehaviorTree> element (or the document's root when tree is null).
  Finding& report_at_tree(const std::string& check, std::string message, const bt::TreeDef* tree,
                          const std::string& path);
  std::vector<Finding>& findings() { return findings_; }

  // The alternatives of `adaptable` the compiled tree `tree_id` runs: those with that tree ID,
  // else those whose tree it equals (the paper's generator or a hand edit may rename a tree).
  std::vector<std::string> alternatives_called(const std::string& adaptable,
                                               const std::string& tree_id) const;

  // Family of a node the robot or the files declare: "Action", "Condition", "Control",
  // "Decorator"; "" when unknown.
  std::string declared_family(const std::string& kind) const;

 private:
  const load::Mission& mission_;
  const bt::Document& compiled_;
  std::vector<Finding> findings_;
  std::map<std::string, std::string> families_;
};

}  // namespace uabt::conform
