// The Fig. 4 shape of a selection tree: Fallback[Sequence[guard?, SubTree alternative] …].
#include "conform/selector_shape.hpp"

#include <functional>

#include "bt/node_kinds.hpp"
#include "conform/compare.hpp"

namespace uabt::conform {

namespace {

const char* const kCheck = "compiled-selector-shape";

// Every call of `adaptable` in the trees of mission.xml shares its parent's blackboard.
bool calls_share_blackboard(const Context& ctx, const std::string& adaptable) {
  bool shared = true;
  std::function<void(const bt::Node&)> visit = [&](const bt::Node& n) {
    if (bt::is_subtree(n.kind())) {
      const std::string* id = n.attribute("ID");
      if (id && *id == adaptable && !shares_blackboard(n, ctx.compiled().format)) shared = false;
    }
    for (const auto& c : n.children) visit(c);
  };
  for (const auto& source : ctx.mission().tree.trees)
    if (const bt::TreeDef* t = ctx.compiled().find_tree(source.id)) visit(t->root);
  return shared;
}

void identify_call(Context& ctx, const std::string& adaptable, Branch& b) {
  const bt::Node& call = *b.call;
  const int format = ctx.compiled().format;
  for (const std::string& remap : remapping_attributes(call, format)) {
    ctx.report(kCheck,
               "the alternative call of branch " + std::to_string(b.index) + " of '" + adaptable +
                   "' has " + remap +
                   ": the call must pass the parent's blackboard unchanged (only " +
                   (format == 3 ? "__shared_blackboard" : "_autoremap") + "=\"true\", or nothing)",
               call, b.call_path)
        .adaptable = adaptable;
    b.well_formed = false;
  }
  const std::string* id = call.attribute("ID");
  if (id == nullptr) return;  // compiled-dangling-subtree
  const load::Mission& m = ctx.mission();
  b.alternatives = ctx.alternatives_called(adaptable, *id);
  if (ctx.compiled().find_tree(*id) == nullptr) return;  // a dangling SubTree
  if (!b.alternatives.empty()) return;
  std::string known;
  for (const auto& alt : m.alternatives) {
    if (alt.adaptable != adaptable) continue;
    known += (known.empty() ? "" : ", ") + alt.name +
             (alt.tree_id != alt.name ? " (tree " + alt.tree_id + ")" : "");
  }
  ctx.report(kCheck,
             "branch " + std::to_string(b.index) + " of '" + adaptable + "' ends with a call of '" +
                 *id + "', which is none of the alternatives of '" + adaptable + "'" +
                 (known.empty() ? "" : " (" + known + ")") +
                 "; the last child of a branch runs the alternative",
             call, b.call_path)
      .adaptable = adaptable;
}

Branch read_branch(Context& ctx, const std::string& adaptable, const bt::Node& node,
                   std::size_t index, const std::string& path) {
  Branch b;
  b.index = index;
  b.node = &node;
  b.path = path;
  if (const std::string* name = node.attribute("name")) b.name = *name;
  const std::string kind = node.kind();
  const bt::NodeKind k = bt::node_kind(kind);
  const std::string where = "branch " + std::to_string(index) + " of '" + adaptable + "'";
  std::string problem;
  if (k != bt::NodeKind::sequence && k != bt::NodeKind::reactive_sequence) {
    problem = where + " is a <" + kind + ">; each branch must be a Sequence or ReactiveSequence";
  } else if (auto extra = extra_attribute(node)) {
    problem = where + " has " + *extra + "; a branch carries at most a name";
  } else if (node.children.empty() || node.children.size() > 2) {
    problem = where + " has " + std::to_string(node.children.size()) +
              " children; a branch is [condition-checking subtree, alternative call], or just "
              "[alternative call] for the default";
  } else if (!bt::is_subtree(node.children.back().kind())) {
    problem = where + " ends with <" + node.children.back().kind() +
              ">; its last child must be the SubTree call of the alternative";
  }
  if (!problem.empty()) ctx.report(kCheck, problem, node, path).adaptable = adaptable;
  b.well_formed = problem.empty();
  // Even a misshapen branch usually still says which alternative it runs; knowing it keeps
  // one mistake from turning into a cascade of missing-alternative findings.
  if (!node.children.empty() && bt::is_subtree(node.children.back().kind())) {
    const std::size_t last = node.children.size() - 1;
    b.call = &node.children[last];
    b.call_path = child_path(path, *b.call, last);
    identify_call(ctx, adaptable, b);
  }
  if (b.well_formed && node.children.size() == 2) {
    b.guard = &node.children[0];
    b.guard_path = child_path(path, *b.guard, 0);
  }
  return b;
}

}  // namespace

std::optional<Selector> read_selector(Context& ctx, const std::string& adaptable) {
  const bt::TreeDef* tree = ctx.compiled().find_tree(adaptable);
  if (tree == nullptr) {
    // A SubTree that calls it is reported as dangling; otherwise say what is missing.
    bool called = false;
    std::function<void(const bt::Node&)> visit = [&](const bt::Node& n) {
      const std::string* id = n.attribute("ID");
      if (bt::is_subtree(n.kind()) && id && *id == adaptable) called = true;
      for (const auto& c : n.children) visit(c);
    };
    for (const auto& t : ctx.compiled().trees) visit(t.root);
    if (!called)
      ctx.report_at_tree(kCheck,
                         "the compiled document has no selection tree '" + adaptable +
                             "' for the adaptable node '" + adaptable + "'",
                         nullptr, adaptable)
          .adaptable = adaptable;
    return std::nullopt;
  }
  Selector s;
  s.tree = tree;
  s.root_path = root_path(*tree);
  s.blackboard_visible = calls_share_blackboard(ctx, adaptable);
  const bt::Node& root = tree->root;
  const std::string kind = root.kind();
  std::string problem;
  if (root.tag.empty()) {
    problem = "the selection tree '" + adaptable + "' is empty";
  } else if (bt::node_kind(kind) != bt::NodeKind::fallback &&
             bt::node_kind(kind) != bt::NodeKind::reactive_fallback) {
    problem = "the selection tree '" + adaptable + "' is a <" + kind +
              ">; it must be a Fallback or ReactiveFallback that tries the alternatives in "
              "priority order";
  } else if (auto extra = extra_attribute(root)) {
    problem =
        "the selection tree's " + kind + " has " + *extra + "; the selector carries at most a name";
  }
  if (!problem.empty()) {
    if (root.tag.empty())
      ctx.report_at_tree(kCheck, problem, tree, adaptable).adaptable = adaptable;
    else
      ctx.report(kCheck, problem, root, s.root_path).adaptable = adaptable;
    return std::nullopt;
  }
  for (std::size_t i = 0; i < root.children.size(); ++i)
    s.branches.push_back(read_branch(ctx, adaptable, root.children[i], i,
                                     child_path(s.root_path, root.children[i], i)));
  return s;
}

}  // namespace uabt::conform
