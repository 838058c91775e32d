// BehaviorTree.CPP's load rules, checked before a tree reaches the robot.
#include "bt/structure.hpp"

#include <algorithm>
#include <map>

#include "bt/node_kinds.hpp"
#include "bt/script/load_check.hpp"

namespace uabt::bt {

namespace {

std::string children_phrase(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " child" : " children");
}

std::string invalid_id_message(const std::string& what, const std::string& id) {
  return "invalid " + what + " '" + id +
         "': IDs must not be empty or contain space, tab, newline or any of < > & \" ' / \\ : * "
         "? | .";
}

// "A → B → A"; a cycle through more than 12 trees is shortened in the middle.
std::string describe_cycle(const std::vector<std::string>& ids) {
  constexpr std::size_t kShown = 12;
  std::string out;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids.size() > kShown && i == kShown - 2) {
      out += "… (" + std::to_string(ids.size() - kShown + 1) + " more) → ";
      i = ids.size() - 1;
    }
    out += ids[i] + " → ";
  }
  return out + ids.front();
}

struct SubTreeEdge {
  std::size_t target;  // index into the tree list
  const Node* node;
};

class StructureChecker {
 public:
  StructureChecker(const std::vector<const TreeDef*>& trees, const StructureOptions& options)
      : trees_(trees), options_(options), edges_(trees.size()) {
    for (std::size_t i = 0; i < trees_.size(); ++i) index_.emplace(trees_[i]->id, i);
    for (const NodeModel& model : options_.node_models) families_.emplace(model.id, model.family);
  }

  std::vector<Finding> run() {
    check_tree_ids();
    for (std::size_t i = 0; i < trees_.size(); ++i) check_nodes(i);
    check_cycles();
    sort_findings(findings_);
    return std::move(findings_);
  }

 private:
  void report(const TreeDef& tree, int line, int column, std::string message) {
    findings_.push_back(
        make_finding("bt-structure", std::move(message), SourceLocation{tree.file, line, column}));
  }
  void report(const TreeDef& tree, const Node& node, std::string message) {
    report(tree, node.line, node.column, std::move(message));
  }

  bool is_registered_name(const std::string& id) const {
    if (find_builtin(id) != nullptr) return true;
    if (!options_.known_nodes_given) return false;
    return std::find(options_.known_nodes.begin(), options_.known_nodes.end(), id) !=
           options_.known_nodes.end();
  }

  void check_tree_ids() {
    std::map<std::string, const TreeDef*> first;
    for (const TreeDef* tree : trees_) {
      if (tree->id.empty()) {
        report(*tree, tree->line, tree->column, "<BehaviorTree> needs an ID");
        continue;
      }
      if (!is_valid_id(tree->id)) {
        report(*tree, tree->line, tree->column, invalid_id_message("tree ID", tree->id));
      }
      if (is_registered_name(tree->id)) {
        report(*tree, tree->line, tree->column,
               "a tree ID must not equal a registered node name '" + tree->id + "'");
      }
      const auto [it, inserted] = first.emplace(tree->id, tree);
      if (!inserted) {
        report(*tree, tree->line, tree->column,
               "tree ID '" + tree->id + "' is defined more than once (first at " +
                   it->second->file + ":" + std::to_string(it->second->line) + ")");
      }
    }
  }

  // Pre-order walk with an explicit stack: a tree built in memory may be arbitrarily deep.
  void check_nodes(std::size_t tree_index) {
    const TreeDef& tree = *trees_[tree_index];
    if (tree.root.tag.empty()) return;  // <BehaviorTree> without a child: the reader said so
    std::vector<std::pair<const Node*, int>> pending = {{&tree.root, 1}};
    while (!pending.empty()) {
      const auto [node, depth] = pending.back();
      pending.pop_back();
      if (depth > kMaxDepth) {
        report(tree, *node,
               "nesting deeper than " + std::to_string(kMaxDepth) +
                   " below <BehaviorTree>: its file would nest elements deeper than " +
                   std::to_string(kMaxXmlDepth) +
                   ", which tinyxml2 (BehaviorTree.CPP's XML parser) refuses; split the tree "
                   "into SubTrees");
        continue;
      }
      check_node(tree_index, *node);
      for (auto it = node->children.rbegin(); it != node->children.rend(); ++it) {
        pending.emplace_back(&*it, depth + 1);
      }
    }
  }

  void check_node(std::size_t tree_index, const Node& node) {
    const TreeDef& tree = *trees_[tree_index];
    // BT.CPP parses every script when it builds the node (the engine does the same).
    for (auto& [attribute, message] : script::node_script_refusals(node)) {
      const auto [line, column] = attribute.empty() ? std::pair{node.line, node.column}
                                                    : node.attribute_position(attribute);
      report(tree, line, column, std::move(message));
    }
    const std::size_t n = node.children.size();
    if (node.tag == "Adaptable") return check_adaptable(tree, node);
    if (is_explicit_family_tag(node.tag) && node.attribute("ID") == nullptr) {
      return report(tree, node, "<" + node.tag + "> needs an ID");
    }
    const std::string kind = node.kind();
    if (!is_valid_id(kind)) return report(tree, node, invalid_id_message("ID", kind));
    if (is_subtree(kind)) return check_subtree(tree_index, node);
    if (const BuiltinNode* builtin = find_builtin(kind)) {
      return check_count(tree, node, kind, builtin->family, builtin->min_children,
                         builtin->max_children);
    }
    std::string family = is_explicit_family_tag(node.tag) ? node.tag : "";
    if (family.empty()) {
      if (const auto it = families_.find(kind); it != families_.end()) family = it->second;
    }
    if (family == "Control") return check_count(tree, node, kind, Family::control, 1, -1);
    if (family == "Decorator") return check_count(tree, node, kind, Family::decorator, 1, 1);
    if (n > 0) {
      const std::string what = family == "Action"      ? "an action"
                               : family == "Condition" ? "a condition"
                                                       : "a leaf (an action or condition)";
      report(tree, node,
             kind + " is " + what + " and must have no children, has " + std::to_string(n));
    }
  }

  void check_count(const TreeDef& tree, const Node& node, const std::string& kind, Family family,
                   int min, int max) {
    const int n = static_cast<int>(node.children.size());
    const std::string has = ", has " + std::to_string(n);
    if (family == Family::action || family == Family::condition) {
      if (n > 0) {
        report(tree, node,
               kind + " is " + (family == Family::action ? "an action" : "a condition") +
                   " and must have no children" + has);
      }
    } else if (min == max && n != min) {
      report(tree, node, kind + " must have exactly " + children_phrase(min) + has);
    } else if (n < min || (max >= 0 && n > max)) {
      const std::string range = max < 0 ? "at least " + children_phrase(min)
                                        : std::to_string(min) + " to " + children_phrase(max);
      report(tree, node, kind + " must have " + range + has);
    }
  }

  void check_adaptable(const TreeDef& tree, const Node& node) {
    if (!options_.allow_adaptable) {
      const std::string* id = node.attribute("ID");
      report(tree, node,
             "<Adaptable" + (id ? " ID=\"" + *id + "\"" : std::string()) +
                 "> left in a compiled tree: compilation replaces every adaptable node");
      return;
    }
    if (!node.children.empty()) {
      report(tree, node,
             "<Adaptable> must have no children, has " + std::to_string(node.children.size()));
    }
    const std::string* id = node.attribute("ID");
    if (id == nullptr || id->empty()) {
      std::string hint;  // `id="navigation"`: XML attribute names are case-sensitive
      for (const auto& [name, value] : node.attributes)
        if (name != "ID" && name.size() == 2 && (name[0] | 0x20) == 'i' && (name[1] | 0x20) == 'd')
          hint = ": attribute names are case-sensitive, write ID=\"" + value + "\" instead of " +
                 name + "=\"" + value + "\"";
      report(tree, node, "<Adaptable> needs an ID" + hint);
    } else if (!is_valid_id(*id)) {
      report(tree, node, invalid_id_message("adaptable ID", *id));
    }
  }

  void check_subtree(std::size_t tree_index, const Node& node) {
    const TreeDef& tree = *trees_[tree_index];
    const std::string kind = node.kind();
    if (!node.children.empty()) {
      report(tree, node,
             kind + " must have no children, has " + std::to_string(node.children.size()));
    }
    const std::string* id = node.attribute("ID");
    if (id == nullptr || id->empty()) return report(tree, node, "<" + kind + "> needs an ID");
    const auto target = index_.find(*id);
    if (target == index_.end()) return report(tree, node, kind + " '" + *id + "' names no tree");
    edges_[tree_index].push_back(SubTreeEdge{target->second, &node});
  }

  // Iterative depth-first search; each back edge closes one cycle, reported at its SubTree.
  void check_cycles() {
    enum class Mark { unvisited, on_path, finished };
    std::vector<Mark> marks(trees_.size(), Mark::unvisited);
    for (std::size_t start = 0; start < trees_.size(); ++start) {
      if (marks[start] != Mark::unvisited || index_.at(trees_[start]->id) != start) continue;
      std::vector<std::pair<std::size_t, std::size_t>> path = {{start, 0}};  // tree, next edge
      marks[start] = Mark::on_path;
      while (!path.empty()) {
        auto& [tree, next] = path.back();
        if (next == edges_[tree].size()) {
          marks[tree] = Mark::finished;
          path.pop_back();
          continue;
        }
        const SubTreeEdge edge = edges_[tree][next++];
        if (marks[edge.target] == Mark::unvisited) {
          marks[edge.target] = Mark::on_path;
          path.emplace_back(edge.target, 0);
        } else if (marks[edge.target] == Mark::on_path) {
          std::vector<std::string> cycle;
          for (const auto& step : path) {
            if (!cycle.empty() || step.first == edge.target)
              cycle.push_back(trees_[step.first]->id);
          }
          report(*trees_[tree], *edge.node, "SubTree cycle: " + describe_cycle(cycle));
        }
      }
    }
  }

  const std::vector<const TreeDef*>& trees_;
  const StructureOptions& options_;
  std::map<std::string, std::size_t> index_;  // tree ID → first tree with it
  std::map<std::string, std::string> families_;
  std::vector<std::vector<SubTreeEdge>> edges_;
  std::vector<Finding> findings_;
};

}  // namespace

std::vector<Finding> check_structure(const std::vector<const TreeDef*>& trees,
                                     const StructureOptions& options) {
  return StructureChecker(trees, options).run();
}

}  // namespace uabt::bt
