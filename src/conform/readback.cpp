// Condition-checking subtrees back into formulas: the inverse of Algorithm 1 (guard_tree.cpp),
// but accepting any tree whose one-tick result is a pure function of the state.
#include "conform/readback.hpp"

#include <set>

#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "conform/script_parse.hpp"

namespace uabt::conform {

using fretish::ExprKind;
using fretish::ExprPtr;

namespace {

const char* const kGuardVocabulary =
    "a condition-checking subtree consists of condition nodes, ScriptCondition, "
    "AlwaysSuccess/AlwaysFailure, Sequence/Fallback (or their reactive forms), Inverter, "
    "ForceSuccess/ForceFailure and SubTree calls";

class Reader {
 public:
  explicit Reader(const Context& ctx) : ctx_(ctx) {}

  GuardReading read(const bt::Node& node, const std::string& path, bool visible, int depth) {
    if (depth > bt::kMaxDepth) return elsewhere(node, path, "nesting too deep");
    if (node.tag == "Adaptable") return elsewhere(node, path, "an <Adaptable> is left here");
    const std::string kind = node.kind();
    using K = bt::NodeKind;
    const K k = bt::node_kind(kind);
    const bool is_call = k == K::subtree;
    if (auto problem = attribute_problem(node, kind, is_call)) return fail(node, path, *problem);

    if (k == K::sequence || k == K::reactive_sequence || k == K::fallback ||
        k == K::reactive_fallback) {
      if (node.children.empty()) return elsewhere(node, path, kind + " has no children");
      const bool conjunction = k == K::sequence || k == K::reactive_sequence;
      std::vector<ExprPtr> parts;
      for (std::size_t i = 0; i < node.children.size(); ++i) {
        GuardReading r =
            read(node.children[i], child_path(path, node.children[i], i), visible, depth + 1);
        if (r.problem) return r;
        parts.push_back(std::move(r.formula));
      }
      if (parts.size() == 1) return ok(parts.front());
      return ok(fretish::make_expr(conjunction ? ExprKind::logical_and : ExprKind::logical_or,
                                   std::move(parts)));
    }
    if (k == K::inverter || k == K::force_success || k == K::force_failure) {
      if (node.children.size() != 1)
        return elsewhere(node, path, kind + " must have exactly one child");
      GuardReading r =
          read(node.children[0], child_path(path, node.children[0], 0), visible, depth + 1);
      if (r.problem) return r;
      if (k == K::inverter) return ok(fretish::make_expr(ExprKind::logical_not, {r.formula}));
      // The child is still evaluated (it is a pure condition), but its result is overridden.
      return ok(fretish::make_bool(k == K::force_success));
    }
    if (k == K::always_success || k == K::always_failure) {
      if (!node.children.empty()) return elsewhere(node, path, kind + " must have no children");
      return ok(fretish::make_bool(k == K::always_success));
    }
    if (k == K::script_condition) return script(node, path, visible);
    if (is_call) return call(node, path, visible, depth);
    if (const bt::BuiltinNode* builtin = bt::find_builtin(kind)) {
      return fail(node, path,
                  "<" + kind + "> is a built-in " + bt::family_name(builtin->family) +
                      " node, not a condition: " + kGuardVocabulary);
    }
    return leaf(node, path, kind);
  }

 private:
  static GuardReading ok(ExprPtr e) { return GuardReading{std::move(e), std::nullopt}; }
  static GuardReading fail(const bt::Node& node, const std::string& path, std::string message) {
    return GuardReading{nullptr, GuardProblem{&node, path, std::move(message), false}};
  }
  static GuardReading elsewhere(const bt::Node& node, const std::string& path,
                                std::string message) {
    return GuardReading{nullptr, GuardProblem{&node, path, std::move(message), true}};
  }

  // Pre- and post-conditions (_skipIf, _failureIf, _onSuccess, …) change what a node returns or
  // write the blackboard; ports make a condition a different atom than the requirement's.
  std::optional<std::string> attribute_problem(const bt::Node& node, const std::string& kind,
                                               bool is_call) const {
    for (const auto& [key, value] : node.attributes) {
      if (key == "name") continue;
      if (key == "ID" && (is_call || bt::is_explicit_family_tag(node.tag))) continue;
      if (is_call && is_remap_attribute(key, ctx_.compiled().format)) continue;
      if (bt::node_kind(kind) == bt::NodeKind::script_condition && key == "code") continue;
      if (!key.empty() && key[0] == '_')
        return "<" + kind + "> has " + key + "=\"" + value +
               "\": a pre/post-condition changes what the node returns, so the subtree no "
               "longer decides the requirement's condition alone";
      if (is_call)
        return "the call <" + kind + "> remaps port " + key + "=\"" + value +
               "\": a condition-checking subtree must read the same state as the requirement";
      return "<" + kind + "> has the port " + key + "=\"" + value +
             "\": a requirement's atom is a plain condition without parameters";
    }
    return std::nullopt;
  }

  GuardReading script(const bt::Node& node, const std::string& path, bool visible) const {
    if (!node.children.empty()) return elsewhere(node, path, "ScriptCondition has children");
    const std::string* code = node.attribute("code");
    if (code == nullptr) return fail(node, path, "<ScriptCondition> has no code attribute");
    ScriptReading r = parse_script_condition(*code, ctx_.mission().domain);
    if (!r.expr)
      return fail(
          node, path,
          "ScriptCondition code \"" + *code + "\" is not a condition uabt can read: " + r.error);
    if (!visible && !r.local_reads.empty())
      return fail(node, path,
                  "ScriptCondition code \"" + *code + "\" reads the blackboard entry '" +
                      r.local_reads.front() +
                      "', but a SubTree call on the way here does not share its parent's "
                      "blackboard (add _autoremap=\"true\", or write @" +
                      r.local_reads.front() + ")");
    return ok(r.expr);
  }

  GuardReading call(const bt::Node& node, const std::string& path, bool visible, int depth) {
    if (!node.children.empty()) return elsewhere(node, path, "SubTree has children");
    const std::string* id = node.attribute("ID");
    const bt::TreeDef* target = id ? ctx_.compiled().find_tree(*id) : nullptr;
    if (target == nullptr) return elsewhere(node, path, "SubTree names no tree");
    if (target->root.tag.empty()) return elsewhere(node, path, "SubTree calls an empty tree");
    if (!calling_.insert(target->id).second) return elsewhere(node, path, "SubTree cycle");
    GuardReading r = read(target->root, root_path(*target),
                          visible && shares_blackboard(node, ctx_.compiled().format), depth + 1);
    calling_.erase(target->id);
    return r;
  }

  GuardReading leaf(const bt::Node& node, const std::string& path, const std::string& kind) const {
    std::string family =
        bt::is_explicit_family_tag(node.tag) ? node.tag : ctx_.declared_family(kind);
    const bt::Family f = bt::family_named(family);
    if (f == bt::Family::action)
      return fail(node, path, "<" + kind + "> is an action, not a condition: " + kGuardVocabulary);
    if (f == bt::Family::control || f == bt::Family::decorator || f == bt::Family::subtree)
      return fail(node, path,
                  "<" + kind + "> is a " + family + " node, not a condition: " + kGuardVocabulary);
    if (!node.children.empty())
      return elsewhere(node, path, "a leaf with children");  // bt-structure: leaves have none
    return ok(fretish::make_identifier(kind));
  }

  const Context& ctx_;
  std::set<std::string> calling_;  // SubTree calls being followed (a cycle never ends)
};

}  // namespace

GuardReading read_guard(const Context& ctx, const bt::Node& node, const std::string& path,
                        bool blackboard_visible) {
  return Reader(ctx).read(node, path, blackboard_visible, 1);
}

}  // namespace uabt::conform
