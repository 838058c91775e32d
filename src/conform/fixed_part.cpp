// The parts of the compiled document that compilation must not touch, and the document-wide
// rules (no adaptable left, every SubTree resolves, BT.CPP's load rules).
#include <algorithm>
#include <functional>

#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "conform/compare.hpp"
#include "conform/tree_rules.hpp"

namespace uabt::conform {

namespace {

// Pre-order visit of every node of every compiled tree, with its path.
void for_each_node(const bt::Document& doc,
                   const std::function<void(const bt::Node&, const std::string&)>& visit) {
  for (const auto& tree : doc.trees) {
    if (tree.root.tag.empty()) continue;
    std::vector<std::pair<const bt::Node*, std::string>> pending{{&tree.root, root_path(tree)}};
    while (!pending.empty()) {
      auto [node, path] = std::move(pending.back());
      pending.pop_back();
      visit(*node, path);
      for (std::size_t i = node->children.size(); i-- > 0;)
        pending.emplace_back(&node->children[i], child_path(path, node->children[i], i));
    }
  }
}

}  // namespace

void check_adaptables_left(Context& ctx) {
  for_each_node(ctx.compiled(), [&](const bt::Node& node, const std::string& path) {
    if (node.tag != "Adaptable") return;
    const std::string* id = node.attribute("ID");
    Finding& f = ctx.report(
        "compiled-adaptable-left",
        "<Adaptable" + (id ? " ID=\"" + *id + "\"" : std::string()) +
            "> is still in the compiled tree: BehaviorTree.CPP cannot execute it; compilation "
            "replaces it with a SubTree that calls its selection tree",
        node, path);
    if (id) f.adaptable = *id;
  });
}

void check_dangling_subtrees(Context& ctx) {
  const bt::Document& doc = ctx.compiled();
  for_each_node(doc, [&](const bt::Node& node, const std::string& path) {
    if (!bt::is_subtree(node.tag)) return;
    const std::string* id = node.attribute("ID");
    if (id == nullptr || id->empty()) {
      ctx.report("compiled-dangling-subtree", "<" + node.tag + "> has no ID: it calls no tree",
                 node, path);
      return;
    }
    if (doc.find_tree(*id) != nullptr) return;
    ctx.report("compiled-dangling-subtree",
               "<" + node.tag + " ID=\"" + *id + "\"> names no tree of the compiled document", node,
               path);
  });
}

void check_fixed_part(Context& ctx) {
  const load::Mission& m = ctx.mission();
  const bt::Document& doc = ctx.compiled();
  const bt::TreeDef* source_main = m.tree.main();
  const bt::TreeDef* compiled_main = doc.main();
  if (source_main != nullptr &&
      (compiled_main == nullptr || compiled_main->id != source_main->id)) {
    ctx.report_at_tree("compiled-fixed-part-changed",
                       "the compiled document's main tree is " +
                           (compiled_main ? "'" + compiled_main->id + "'"
                                          : std::string("not determined (no main_tree_to_execute "
                                                        "naming a tree, and several trees)")) +
                           "; mission.xml executes '" + source_main->id + "'",
                       compiled_main, compiled_main ? root_path(*compiled_main) : "");
  }
  const AdaptableRule rule{doc.format};
  for (const auto& source : m.tree.trees) {
    const bt::TreeDef* compiled = doc.find_tree(source.id);
    if (compiled == nullptr) {
      ctx.report_at_tree("compiled-fixed-part-changed",
                         "tree '" + source.id + "' of mission.xml is missing", nullptr, source.id);
      continue;
    }
    if (source.root.tag.empty() || compiled->root.tag.empty()) {
      if (source.root.tag != compiled->root.tag)
        ctx.report_at_tree(
            "compiled-fixed-part-changed",
            "tree '" + source.id + "' differs from mission.xml: one of them is empty", compiled,
            source.id);
      continue;
    }
    auto diff = first_difference(source.root, compiled->root, root_path(*compiled), &rule);
    if (!diff) continue;
    ctx.report(
        "compiled-fixed-part-changed",
        "tree '" + source.id + "' differs from mission.xml at " + diff->path + ": " + diff->what,
        *diff->node, diff->path);
  }
}

void check_compiled_structure(Context& ctx) {
  const load::Mission& m = ctx.mission();
  const bt::Document& doc = ctx.compiled();
  std::vector<const bt::TreeDef*> trees;
  for (const auto& t : doc.trees) trees.push_back(&t);
  bt::StructureOptions options;
  options.allow_adaptable = false;
  if (m.nodes) {
    options.known_nodes_given = true;
    for (const auto& model : *m.nodes) options.known_nodes.push_back(model.id);
    options.node_models = *m.nodes;
  }
  for (const auto& model : doc.node_models) options.node_models.push_back(model);
  std::vector<Finding> found = bt::check_structure(trees, options);
  // The adaptable and dangling-SubTree rules have their own compiled-* findings at the same
  // node; keep one finding per problem.
  auto duplicates_own = [&](const Finding& f) {
    return std::any_of(ctx.findings().begin(), ctx.findings().end(), [&](const Finding& own) {
      if (own.check != "compiled-adaptable-left" && own.check != "compiled-dangling-subtree")
        return false;
      const bool same_place =
          own.location.line == f.location.line && own.location.column == f.location.column;
      const bool same_problem = own.check == "compiled-adaptable-left"
                                    ? f.message.find("left in a compiled tree") != std::string::npos
                                    : f.message.find("names no tree") != std::string::npos ||
                                          f.message.find("needs an ID") != std::string::npos;
      return same_place && same_problem;
    });
  };
  for (auto& f : found) {
    if (duplicates_own(f)) continue;
    ctx.findings().push_back(std::move(f));
  }
}

}  // namespace uabt::conform
