// The paper's compilation: adaptable BT + alternatives + requirements → one executable BT.
#include "compile/compile.hpp"

#include <functional>
#include <map>
#include <set>

#include "bt/node_kinds.hpp"
#include "bt/xml_io.hpp"
#include "compile/guard_rewrite.hpp"
#include "fretish/requirement.hpp"
#include "load/references.hpp"

namespace uabt::compile {

namespace {

using bt::child_path;

// Replaces every <Adaptable ID="A"/> with <SubTree ID="A" _autoremap="true"/> (v4) or its
// v3 spelling, keeping a `name` the engineer gave it.
void replace_adaptables(bt::Node& node, int bt_format) {
  std::vector<bt::Node*> stack{&node};
  while (!stack.empty()) {
    bt::Node* n = stack.back();
    stack.pop_back();
    if (n->tag == "Adaptable") {
      bt::Node sub;
      sub.tag = bt::kind_name(bt::NodeKind::subtree);
      sub.line = n->line;
      sub.column = n->column;
      if (const std::string* id = n->attribute("ID")) sub.set_attribute("ID", *id);
      if (const std::string* name = n->attribute("name")) sub.set_attribute("name", *name);
      if (bt_format == 3)
        sub.set_attribute("__shared_blackboard", "true");
      else
        sub.set_attribute("_autoremap", "true");
      *n = std::move(sub);
      continue;
    }
    for (auto& child : n->children) stack.push_back(&child);
  }
}

bt::Node subtree_call(const std::string& tree_id, int bt_format) {
  bt::Node n;
  n.tag = bt::kind_name(bt::NodeKind::subtree);
  n.set_attribute("ID", tree_id);
  if (bt_format == 3)
    n.set_attribute("__shared_blackboard", "true");
  else
    n.set_attribute("_autoremap", "true");
  return n;
}

void trace_guard(const bt::Node& node, const std::string& path, const std::string& tree_id,
                 const fretish::SelectionRequirement& req, std::vector<TraceEntry>& trace) {
  TraceEntry entry;
  entry.tree_id = tree_id;
  entry.node_path = path;
  entry.requirement = req.id;
  entry.source = req.guard_location;
  const bt::NodeKind kind = bt::node_kind(node.tag);
  if (kind == bt::NodeKind::script_condition) {
    entry.atom = *node.attribute("code");
  } else if (kind == bt::NodeKind::inverter) {
    entry.atom = "!";
  } else if (kind == bt::NodeKind::sequence) {
    entry.atom = "&";
  } else if (kind == bt::NodeKind::fallback) {
    entry.atom = "|";
  } else {
    entry.atom = node.tag;
  }
  trace.push_back(std::move(entry));
  for (std::size_t i = 0; i < node.children.size(); ++i)
    trace_guard(node.children[i], child_path(path, node.children[i], i), tree_id, req, trace);
}

}  // namespace

SelectionStyle selection_style_of(const load::Mission& m, const std::string& adaptable,
                                  const Options& options) {
  if (options.selection_forced) return options.selection;
  for (const auto& site : m.adaptables) {
    if (site.id != adaptable || site.selection.empty()) continue;
    if (site.selection == "reactive") return SelectionStyle::reactive;
    if (site.selection == "optimized") return SelectionStyle::optimized;
    return SelectionStyle::sequence;
  }
  return options.selection;
}

bool reactive_selection(const load::Mission& m, const std::string& adaptable,
                        const Options& options) {
  const SelectionStyle style = selection_style_of(m, adaptable, options);
  if (style != SelectionStyle::optimized) return style == SelectionStyle::reactive;
  for (const auto& site : m.adaptables)
    if (site.id == adaptable && site.selection == "reactive") return true;
  return false;
}

namespace {

// Fig. 4: Fallback[Sequence[guard_i, SubTree alt_i] …] in priority order, default last.
bt::TreeDef selection_tree(const load::Mission& m, const std::string& adaptable,
                           const Options& options, std::vector<TraceEntry>& trace,
                           std::vector<Finding>& findings, std::vector<SelectionStats>& stats) {
  const SelectionStyle style = selection_style_of(m, adaptable, options);
  const bool reactive = reactive_selection(m, adaptable, options);
  const std::size_t trace_start = trace.size();
  const std::size_t findings_start = findings.size();
  bt::TreeDef tree;
  tree.id = adaptable;
  tree.root.tag =
      bt::kind_name(reactive ? bt::NodeKind::reactive_fallback : bt::NodeKind::fallback);
  tree.root.set_attribute("name", adaptable);
  const std::string root_path = adaptable + "/" + tree.root.tag;
  trace.push_back({adaptable, root_path, "", "selector", {}});

  for (const fretish::SelectionRequirement* req : m.selections_for(adaptable)) {
    const load::Alternative* alt = m.find_alternative(adaptable, req->alternative);
    bt::Node branch;
    branch.tag = bt::kind_name(reactive ? bt::NodeKind::reactive_sequence : bt::NodeKind::sequence);
    branch.set_attribute("name", req->id);
    if (req->guard) {
      try {
        branch.children.push_back(guard_to_tree(
            *req->guard, m.domain, reactive ? SelectionStyle::reactive : SelectionStyle::sequence));
      } catch (const UnsupportedGuard& e) {
        Finding f = make_finding("compile-unsupported", "requirement " + req->id + ": " + e.what(),
                                 req->guard_location);
        f.adaptable = adaptable;
        f.requirements = {req->id};
        findings.push_back(std::move(f));
        continue;
      }
      if (options.bt_format == 3) {
        bool uses_script = false;
        std::vector<const bt::Node*> stack{&branch.children.back()};
        while (!stack.empty()) {
          const bt::Node* n = stack.back();
          stack.pop_back();
          uses_script |= bt::node_kind(n->tag) == bt::NodeKind::script_condition;
          for (const auto& c : n->children) stack.push_back(&c);
        }
        if (uses_script) {
          Finding f = make_finding(
              "compile-unsupported",
              "requirement " + req->id + ": guard '" + fretish::to_fretish(*req->guard) +
                  "' needs ScriptCondition, which BehaviorTree.CPP v3 does not have; compile "
                  "with --bt-format 4 or use condition nodes only",
              req->guard_location);
          f.adaptable = adaptable;
          f.requirements = {req->id};
          findings.push_back(std::move(f));
          continue;
        }
      }
    }
    branch.children.push_back(
        subtree_call(alt ? alt->tree_id : req->alternative, options.bt_format));
    const std::size_t index = tree.root.children.size();
    const std::string branch_path = child_path(root_path, branch, index);
    trace.push_back({adaptable, branch_path, req->id, "requirement", req->location});
    if (req->guard)
      trace_guard(branch.children.front(), child_path(branch_path, branch.children.front(), 0),
                  adaptable, *req, trace);
    const std::size_t alt_index = branch.children.size() - 1;
    trace.push_back({adaptable, child_path(branch_path, branch.children.back(), alt_index), req->id,
                     "selected_alt = " + req->alternative, req->alternative_location});
    tree.root.children.push_back(std::move(branch));
  }
  if (style == SelectionStyle::optimized && findings.size() == findings_start) {
    std::vector<TraceEntry> decision_trace;
    SelectionStats& node_stats = stats.emplace_back();
    if (auto root = optimized_selector(m, adaptable, options.bt_format, reactive, decision_trace,
                                       node_stats)) {
      tree.root = std::move(*root);
      trace.resize(trace_start);
      trace.insert(trace.end(), decision_trace.begin(), decision_trace.end());
    }
  }
  return tree;
}

void add_model(std::vector<bt::NodeModel>& models, std::set<std::string>& known,
               const bt::NodeModel& model) {
  if (known.insert(model.id).second) models.push_back(model);
}

}  // namespace

ReadBack read_back(const Result& compiled, const Options& options) {
  ReadBack out;
  bt::WriteOptions write_options;
  write_options.format = options.bt_format;
  out.xml = bt::write_document(compiled.document, write_options);
  out.tree = bt::parse_document(out.xml, "compiled.xml", out.findings);
  return out;
}

Result compile_mission(const load::Mission& m, const Options& options) {
  Result result;
  if (has_errors(m.findings)) {
    // The mission does not load cleanly (its findings say why): nothing sound to compile.
    return result;
  }
  const bt::TreeDef* main = m.tree.main();
  bt::Document& doc = result.document;
  doc.format = options.bt_format;
  doc.main_tree = main ? main->id : std::string();
  doc.file = m.tree.file;

  for (const auto& t : m.tree.trees) {
    bt::TreeDef copy = t;
    replace_adaptables(copy.root, options.bt_format);
    doc.trees.push_back(std::move(copy));
  }

  std::set<std::string> adaptables_done;
  std::set<std::string> trees_done;
  for (const auto& t : doc.trees) trees_done.insert(t.id);
  std::vector<bt::TreeDef> alternative_trees;
  for (const auto& site : m.adaptables) {
    if (!adaptables_done.insert(site.id).second) continue;
    doc.trees.push_back(
        selection_tree(m, site.id, options, result.trace, result.findings, result.selection_stats));
    trees_done.insert(site.id);
    for (const fretish::SelectionRequirement* req : m.selections_for(site.id)) {
      const load::Alternative* alt = m.find_alternative(site.id, req->alternative);
      if (alt == nullptr) continue;
      // The alternative's main tree first, then the subtrees it brings along.
      std::vector<const bt::TreeDef*> order{alt->document.find_tree(alt->tree_id)};
      for (const auto& t : alt->document.trees)
        if (t.id != alt->tree_id) order.push_back(&t);
      for (const bt::TreeDef* t : order)
        if (t != nullptr && trees_done.insert(t->id).second) alternative_trees.push_back(*t);
    }
  }
  for (auto& t : alternative_trees) doc.trees.push_back(std::move(t));

  // Node models: what the robot declares, then what the files declare, then the guards'
  // conditions (so that Groot2 shows them as conditions, not actions).
  std::set<std::string> known;
  if (m.nodes)
    for (const auto& model : *m.nodes) add_model(doc.node_models, known, model);
  for (const auto& model : m.tree.node_models) add_model(doc.node_models, known, model);
  for (const auto& alt : m.alternatives)
    for (const auto& model : alt.document.node_models) add_model(doc.node_models, known, model);
  for (const auto& s : m.selections) {
    if (!s.guard) continue;
    for (const fretish::Expr* atom : load::boolean_atoms(*s.guard)) {
      const fretish::Variable* v = m.domain.find(atom->text);
      if (v == nullptr || v->type != fretish::VarType::boolean) continue;
      add_model(doc.node_models, known, bt::NodeModel{"Condition", atom->text, {}, 0, 0, ""});
    }
  }
  // A leaf named after a boolean of the domain reads that boolean: a condition, whatever its
  // name looks like (`Ok_1` as much as `IsDug`).
  std::function<void(const bt::Node&)> leaves = [&](const bt::Node& n) {
    for (const auto& c : n.children) leaves(c);
    if (!n.children.empty() || n.tag != n.kind()) return;
    const fretish::Variable* v = m.domain.find(n.tag);
    if (v != nullptr && v->type == fretish::VarType::boolean)
      add_model(doc.node_models, known, bt::NodeModel{"Condition", n.tag, {}, 0, 0, ""});
  };
  for (const auto& t : doc.trees) leaves(t.root);
  result.ok = !has_errors(result.findings);
  return result;
}

}  // namespace uabt::compile
