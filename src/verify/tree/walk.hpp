#pragma once
// What the whole-tree checks share: the robot's registered nodes, and one node of a tree as a
// check sees it (with the path from its <BehaviorTree>).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "base/finding.hpp"
#include "bt/node_kinds.hpp"
#include "bt/tree.hpp"
#include "load/mission.hpp"

namespace uabt::verify::tree {

// The nodes the robot registers: nodes.xml, then the documents' <TreeNodesModel>s (nodes.xml
// wins), and BehaviorTree.CPP's built-ins.
class Registry {
 public:
  explicit Registry(const load::Mission& mission);
  // The registered model of an ID (not the built-ins); nullptr when none.
  const bt::NodeModel* model(const std::string& id) const;
  // Registered family of an ID: a built-in's, else its model's; unknown when neither.
  bt::Family family(const std::string& id) const;
  // A variable of the domain (declared, or a condition a guard reads).
  bool is_domain_name(const std::string& id) const { return domain_names_.count(id) != 0; }
  const load::Mission& mission() const { return mission_; }

 private:
  const load::Mission& mission_;
  std::unordered_map<std::string, const bt::NodeModel*> models_;
  std::unordered_map<std::string, bt::Family> families_;  // built-ins first, then models
  std::unordered_set<std::string> domain_names_;
};

// One node of a tree: its document (for SubTree targets), tree, and the ancestors from the
// tree's root (root first, the node itself excluded).
struct Site {
  const bt::Document* document = nullptr;
  const bt::TreeDef* tree = nullptr;
  const bt::Node* node = nullptr;
  const std::vector<const bt::Node*>* path = nullptr;

  SourceLocation location() const;                                   // the element
  SourceLocation attribute_location(const std::string& name) const;  // `name="…"`
  SourceLocation location_of(const bt::Node& other) const;           // another element, same file
};

// The controls BehaviorTree.CPP 4.10 ticks as a Sequence (stop at the first child that does
// not succeed) and as a Fallback (stop at the first that does not fail).
inline bool is_sequence(std::string_view kind) {
  const bt::NodeKind k = bt::node_kind(kind);
  return k == bt::NodeKind::sequence || k == bt::NodeKind::sequence_with_memory ||
         k == bt::NodeKind::reactive_sequence || k == bt::NodeKind::async_sequence;
}
inline bool is_fallback(std::string_view kind) {
  const bt::NodeKind k = bt::node_kind(kind);
  return k == bt::NodeKind::fallback || k == bt::NodeKind::reactive_fallback ||
         k == bt::NodeKind::async_fallback;
}

// How BehaviorTree.CPP 4.10 makes a node's result from its children's. The one reading of its
// tick rules that the flow graph (what runs before what) and the outcome questions (what a node
// can return) share, so that a rule is fixed in one place.
enum class Combine : std::uint8_t {
  leaf,           // no children: a robot action or condition, or a built-in leaf
  sequence,       // stops at the first child that fails; succeeds when every child did
  fallback,       // stops at the first child that succeeds; fails when every child did
  if_then_else,   // IfThenElse, WhileDoElse: the first child picks the branch
  parallel,       // every child in the same tick; its thresholds decide
  pass,           // a decorator that returns what its child returns
  invert,         // Inverter
  force_success,  // ForceSuccess: a child that completes makes it succeed
  force_failure,  // ForceFailure: a child that completes makes it fail
  any_child,      // another control (Switch, TryCatch, the robot's own): one of its children
};

struct ControlRule {
  Combine combine = Combine::leaf;
  // Precondition, SkipUnlessUpdated, Loop*, BlackboardCheck*: may end without ticking the child.
  // (RunOnce skips it only once it has run it to the end; Timeout and Delay tick it first.)
  bool may_end_without_child = false;
  // Delay, Timeout, WaitValueUpdate: may return RUNNING whatever the child does.
  bool may_run_alone = false;
};

// `family` is the kind's registered family (a built-in's or nodes.xml's).
ControlRule control_rule(std::string_view kind, bt::Family family, std::size_t children);

// "<Sequence name=\"collect\">", "<Drill>", "<Action ID=\"Drill\">": how a message names a node.
std::string describe(const bt::Node& node);

// The path through the tree to the finding's place as SARIF relatedLocations: the
// <BehaviorTree>, then every ancestor, then (`through_node`: the finding is at one of its
// children) the site's node itself.
void add_path(Finding& finding, const Site& site, bool through_node = false);

}  // namespace uabt::verify::tree
