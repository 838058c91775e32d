#include "verify/tree/flow_graph.hpp"

#include <cctype>
#include <set>
#include <tuple>

#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "verify/tree/walk.hpp"

namespace uabt::verify::tree {

using bt::blackboard_key;

namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

struct ScopeInfo {
  std::uint32_t parent = kNone;
  bool autoremap = false;
  std::map<std::string, std::string> remapped;  // SubTree port → the parent's key
};

// A built-in node's port: the Loop decorators write `value` (and pop `queue`, which must be
// there); every other built-in port is an input.
// A built-in node's port direction as BT.CPP declares it; input for a name it does not declare.
std::string builtin_direction(const std::string& kind, const std::string& port) {
  for (const bt::Port& p : bt::find_builtin(kind)->ports)
    if (p.name == port) return p.direction;
  return "input_port";
}

bool is_precondition(const std::string& a) {
  return a == "_skipIf" || a == "_failureIf" || a == "_successIf" || a == "_while";
}
bool is_postcondition(const std::string& a) {
  return a == "_onSuccess" || a == "_onFailure" || a == "_onHalted" || a == "_post";
}

struct Exits {
  std::vector<std::uint32_t> success, failure, skipped;  // vertices a parent continues from
};

class Builder {
 public:
  Builder(const load::Mission& mission, FlowGraph& g) : m_(mission), g_(g) {
    if (m_.nodes)
      for (const auto& model : *m_.nodes) models_.emplace(model.id, &model);
    for (const auto& alt : m_.alternatives) alternatives_[alt.adaptable].push_back(&alt);
  }

  void build() {
    const bt::TreeDef* main = m_.tree.main();
    if (main == nullptr) return;
    scopes_.push_back({});
    g_.scope_trees.push_back(main->id);
    documents_.push_back(&m_.tree);
    const std::uint32_t start = vertex(kNone, Step::enter);  // the first tick
    g_.nodes.push_back({nullptr, {m_.tree.file, main->line, main->column}, main->id, 0});
    g_.vertices[start].node = 0;
    stack_.push_back(main->id);
    tick(main->root, *main, 0, {start});
  }

 private:
  std::uint32_t vertex(std::uint32_t node, Step step, std::vector<std::uint32_t> preds = {}) {
    Vertex v;
    v.node = node;
    v.step = step;
    v.preds = std::move(preds);
    g_.vertices.push_back(std::move(v));
    return static_cast<std::uint32_t>(g_.vertices.size() - 1);
  }

  std::uint32_t entry(std::uint32_t scope, std::string key) {
    for (int guard = 0; guard < 4096; ++guard) {
      if (!key.empty() && key.front() == '@') {
        scope = 0;
        key.erase(0, 1);
        continue;
      }
      const ScopeInfo& s = scopes_[scope];
      if (s.parent == kNone || locals_.count({scope, key}) != 0) break;
      if (auto it = s.remapped.find(key); it != s.remapped.end()) {
        key = it->second;
        scope = s.parent;
        continue;
      }
      if (s.autoremap && key.front() != '_') {
        scope = s.parent;
        continue;
      }
      break;
    }
    auto [it, inserted] =
        entries_.emplace(std::make_pair(scope, key), static_cast<std::uint32_t>(entries_.size()));
    if (inserted) {
      g_.entry_keys.push_back(key);
      g_.entry_scopes.push_back(scope);
      g_.robot.push_back(scope == 0 && m_.domain.find(key) != nullptr);
    }
    return it->second;
  }

  // The names a script reads before it writes them, and the names it writes, in order.
  void script_effects(const bt::script::Script& s, std::uint32_t scope, const std::string& what,
                      Vertex& at, Vertex& after) {
    using bt::script::Op;
    std::set<std::string> written;
    const auto& nodes = s.nodes();
    // Evaluation order: an assignment evaluates its value, then stores; operands left to right.
    std::vector<std::pair<std::uint32_t, bool>> work;  // (node, stored) post-order walk
    for (auto st = s.statements().rbegin(); st != s.statements().rend(); ++st)
      work.push_back({*st, false});
    while (!work.empty()) {
      auto [index, done] = work.back();
      work.pop_back();
      const bt::script::Expr& e = nodes[index];
      const bool assigns = bt::script::is_assignment(e.op);
      if (done) {
        const std::string& key = nodes[e.a].name;
        written.insert(key);
        after.writes.push_back(entry(scope, key));
        if (e.op == Op::assign_create || e.op == Op::assign) {
          const bt::script::Expr& value = nodes[e.b];
          if (value.op == Op::literal) {
            TypedUse use;
            use.entry = entry(scope, key);
            use.from_script = true;
            use.type = value.literal.is_string() ? "string" : "number";
            use.literal = value.literal.is_string() ? value.literal.text : std::string();
            use.location = g_.nodes[at.node].location;
            use.what = what;
            g_.typed_uses.push_back(std::move(use));
          }
        }
        continue;
      }
      if (e.op == Op::name) {
        if (written.count(e.name) == 0) at.reads.push_back({entry(scope, e.name), what});
        continue;
      }
      if (assigns) {
        work.push_back({index, true});
        work.push_back({e.b, false});
        // `x = …`, `x += …` need x to exist; `x := …` creates it.
        if (e.op != Op::assign_create && written.count(nodes[e.a].name) == 0)
          at.reads.push_back({entry(scope, nodes[e.a].name), what});
        continue;
      }
      std::vector<std::uint32_t> operands;
      if (e.op == Op::compare) {
        for (std::uint32_t i = 0; i < e.list_size; ++i)
          operands.push_back(s.compare_operands()[e.list_begin + i]);
      } else if (e.op == Op::conditional) {
        operands = {e.a, e.b, e.c};
      } else if (e.op == Op::negate || e.op == Op::logical_not || e.op == Op::complement) {
        operands = {e.a};
      } else if (e.op != Op::literal) {
        operands = {e.a, e.b};
      }
      for (auto it = operands.rbegin(); it != operands.rend(); ++it) work.push_back({*it, false});
    }
  }

  std::shared_ptr<const bt::script::Script> parse(const std::string& code) {
    try {
      return std::make_shared<const bt::script::Script>(bt::script::Script::parse(code));
    } catch (const std::exception&) {
      return nullptr;  // bt-structure reports a script that does not parse
    }
  }

  void add_script(const std::string& attribute, const std::string& kind, const std::string& code,
                  std::uint32_t node, bool condition, std::uint32_t at, std::uint32_t after) {
    auto script = parse(code);
    if (!script) return;
    const std::string what =
        "the script `" + code + "` of " + (attribute == "code" ? kind : kind + " " + attribute);
    script_effects(*script, g_.nodes[node].scope, what, g_.vertices[at], g_.vertices[after]);
    const SourceLocation& where = g_.nodes[node].location;
    if (seen_scripts_.insert({where.file, where.line, where.column, attribute}).second)
      g_.scripts.push_back({attribute, kind, script, where, g_.nodes[node].scope, condition});
  }

  // Reads and writes of a leaf's ports, with their nodes.xml directions and types.
  void leaf_ports(const bt::Node& xml, const std::string& kind, std::uint32_t node,
                  std::uint32_t at) {
    const std::uint32_t scope = g_.nodes[node].scope;
    const SourceLocation& where = g_.nodes[node].location;
    const bool first_visit = seen_nodes_.insert({where.file, where.line, where.column}).second;
    if (bt::node_kind(kind) == bt::NodeKind::set_blackboard) {
      if (const std::string* value = xml.attribute("value"))
        if (auto key = blackboard_key("value", *value))
          g_.vertices[at].reads.push_back(
              {entry(scope, *key), "port 'value' (" + *value + ") of SetBlackboard"});
      if (const std::string* out = xml.attribute("output_key")) {
        auto key = blackboard_key("output_key", *out);
        g_.vertices[at].writes.push_back(entry(scope, key ? *key : *out));
      }
      return;
    }
    const auto model_it = models_.find(kind);
    const bt::NodeModel* model = model_it == models_.end() ? nullptr : model_it->second;
    for (const auto& [attribute, value] : xml.attributes) {
      if (!bt::is_port_attribute(attribute)) continue;
      const bt::Port* port = nullptr;
      if (model)
        for (const auto& p : model->ports)
          if (p.name == attribute) port = &p;
      const auto key = blackboard_key(attribute, value);
      if (!key) {
        if (port && first_visit && port->direction != "output_port" && !port->type.empty())
          g_.literal_ports.push_back({attribute, port->type, value, kind, where});
        continue;
      }
      // A built-in node's ports are inputs; a robot node's direction is in nodes.xml (without
      // it, BT.CPP refuses the node: ref-unknown-node says so, and the entry is not judged).
      const bool builtin = model == nullptr && bt::find_builtin(kind) != nullptr;
      if (!builtin && port == nullptr) continue;
      const std::string direction = !builtin ? port->direction : builtin_direction(kind, attribute);
      const std::uint32_t e = entry(scope, *key);
      if (direction != "output_port")
        g_.vertices[at].reads.push_back(
            {e, "input port '" + attribute + "' (" + value + ") of " + kind});
      if (direction != "input_port") g_.vertices[at].writes.push_back(e);
      if (port && !port->type.empty())
        g_.typed_uses.push_back(
            {e, port->type, false, {}, where, "port '" + attribute + "' of " + kind});
    }
  }

  // Ticks `xml` once, entered from `preds`; returns where its parent goes on.
  Exits tick(const bt::Node& xml, const bt::TreeDef& def, std::uint32_t scope,
             std::vector<std::uint32_t> preds) {
    const auto node = static_cast<std::uint32_t>(g_.nodes.size());
    const std::string kind = xml.kind();
    std::string label = xml.tag == "Adaptable" ? "Adaptable" : kind;
    if (const std::string* id = xml.attribute("ID"); xml.tag == "Adaptable" && id)
      label += " '" + *id + "'";
    if (const std::string* name = xml.attribute("name")) label += " '" + *name + "'";
    g_.nodes.push_back({&xml, {def.file, xml.line, xml.column}, label, scope});
    const std::uint32_t enter = vertex(node, Step::enter, std::move(preds));
    Exits out;
    ++depth_;
    if (depth_ > bt::kMaxDepth * 4) {  // bt-structure refuses such a tree
      --depth_;
      return out;
    }

    // Pre-conditions: each may end the tick before the node runs.
    std::vector<std::uint32_t> short_success, short_failure, short_skip;
    for (const auto& [attribute, value] : xml.attributes) {
      if (!is_precondition(attribute)) continue;
      add_script(attribute, label, value, node, true, enter, enter);
      if (attribute == "_failureIf") short_failure.push_back(enter);
      if (attribute == "_successIf") short_success.push_back(enter);
      if (attribute == "_skipIf" || attribute == "_while") short_skip.push_back(enter);
    }
    const bool guarded = !short_success.empty() || !short_failure.empty() || !short_skip.empty();
    const std::uint32_t run = guarded ? vertex(node, Step::run, {enter}) : enter;

    Exits body = tick_body(xml, kind, def, scope, node, run);
    for (auto v : short_success) body.success.push_back(v);
    for (auto v : short_failure) body.failure.push_back(v);
    for (auto v : short_skip) body.skipped.push_back(v);

    auto close = [&](Step step, const std::vector<std::uint32_t>& from) -> std::uint32_t {
      if (from.empty()) return kNone;
      return vertex(node, step, from);
    };
    const std::uint32_t success = close(Step::success, body.success);
    const std::uint32_t failure = close(Step::failure, body.failure);
    const std::uint32_t skipped = close(Step::skipped, body.skipped);
    for (const auto& [attribute, value] : xml.attributes) {
      if (!is_postcondition(attribute) || attribute == "_onHalted") continue;
      for (const std::uint32_t v : {success, failure}) {
        if (v == kNone) continue;
        const bool applies = attribute == "_post" || (attribute == "_onSuccess" && v == success) ||
                             (attribute == "_onFailure" && v == failure);
        if (applies) add_script(attribute, label, value, node, false, v, v);
      }
    }
    if (success != kNone) out.success.push_back(success);
    if (failure != kNone) out.failure.push_back(failure);
    if (skipped != kNone) out.skipped.push_back(skipped);
    --depth_;
    return out;
  }

  Exits tick_body(const bt::Node& xml, const std::string& kind, const bt::TreeDef& def,
                  std::uint32_t scope, std::uint32_t node, std::uint32_t enter) {
    Exits out;
    const auto& children = xml.children;
    if (xml.tag == "Adaptable") return adaptable(xml, node, enter);
    const bt::NodeKind k = bt::node_kind(kind);
    if (k == bt::NodeKind::subtree) return subtree(xml, def, scope, node, enter);
    const bt::BuiltinNode* builtin = bt::find_builtin(kind);
    const ControlRule rule =
        control_rule(kind, builtin ? builtin->family : bt::Family::unknown, children.size());

    if (rule.combine == Combine::leaf) {
      using K = bt::NodeKind;
      if (k == K::script || k == K::script_condition) {
        if (const std::string* code = xml.attribute("code"))
          add_script("code", kind, *code, node, k == K::script_condition, enter, enter);
      } else {
        leaf_ports(xml, kind, node, enter);
      }
      if (k != K::always_failure && k != K::script) out.success.push_back(enter);
      if (k != K::always_success && k != K::script) out.failure.push_back(enter);
      if (k == K::script) out.success.push_back(enter);
      return out;
    }
    leaf_ports(xml, kind, node, enter);  // a control's or decorator's own ports ({key} inputs)

    switch (rule.combine) {
      case Combine::sequence:
      case Combine::fallback: {
        // Each child runs when the ones before it returned the result that goes on (a skipped
        // child goes on as well); the first other result ends the node.
        const bool sequence = rule.combine == Combine::sequence;
        std::vector<std::uint32_t> from{enter};
        for (std::size_t i = 0; i < children.size(); ++i) {
          Exits c = tick(children[i], def, scope, from);
          auto& go_on = sequence ? c.success : c.failure;
          auto& stop = sequence ? c.failure : c.success;
          for (auto v : stop) (sequence ? out.failure : out.success).push_back(v);
          from = go_on;
          for (auto v : c.skipped) from.push_back(v);
        }
        for (auto v : from) (sequence ? out.success : out.failure).push_back(v);
        return out;
      }
      case Combine::if_then_else: {
        Exits c = tick(children[0], def, scope, {enter});
        Exits then = tick(children[1], def, scope, c.success);
        append(out, then);
        if (children.size() == 3) {
          append(out, tick(children[2], def, scope, c.failure));
        } else {
          for (auto v : c.failure) out.failure.push_back(v);
        }
        return out;
      }
      case Combine::parallel: {
        // Every child is ticked in order in the same tick, whatever the ones before returned.
        std::vector<std::uint32_t> from{enter};
        for (const auto& child : children) {
          Exits c = tick(child, def, scope, from);
          from = c.success;
          for (auto v : c.failure) from.push_back(v);
          for (auto v : c.skipped) from.push_back(v);
        }
        out.success = from;
        out.failure = from;
        return out;
      }
      case Combine::pass:
      case Combine::invert:
      case Combine::force_success:
      case Combine::force_failure: {
        Exits c = tick(children[0], def, scope, {enter});
        if (rule.combine == Combine::invert) {
          out.success = c.failure;
          out.failure = c.success;
        } else if (rule.combine == Combine::force_success) {
          out.success = c.success;
          for (auto v : c.failure) out.success.push_back(v);
        } else if (rule.combine == Combine::force_failure) {
          out.failure = c.success;
          for (auto v : c.failure) out.failure.push_back(v);
        } else {
          out.success = c.success;
          out.failure = c.failure;
        }
        out.skipped = c.skipped;
        if (rule.may_end_without_child) {
          out.success.push_back(enter);
          out.failure.push_back(enter);
          out.skipped.push_back(enter);
        }
        return out;
      }
      case Combine::leaf:
      case Combine::any_child: break;
    }
    // Any other control (Switch, TryCatch, ManualSelector, a robot's own): it may tick any one
    // child; the node ends with what that child returns.
    for (const auto& child : children) append(out, tick(child, def, scope, {enter}));
    return out;
  }

  static void append(Exits& out, const Exits& more) {
    for (auto v : more.success) out.success.push_back(v);
    for (auto v : more.failure) out.failure.push_back(v);
    for (auto v : more.skipped) out.skipped.push_back(v);
  }

  // An <Adaptable>: the compiled tree runs one of its alternatives as a SubTree with
  // _autoremap, so each alternative sees and writes the mission's entries.
  Exits adaptable(const bt::Node& xml, std::uint32_t node, std::uint32_t enter) {
    Exits out;
    const std::string* id = xml.attribute("ID");
    if (!id) return out;
    const auto it = alternatives_.find(*id);
    if (it == alternatives_.end()) return out;
    for (const load::Alternative* alt : it->second) {
      const bt::TreeDef* def = alt->document.find_tree(alt->tree_id);
      if (def == nullptr) def = alt->document.main();
      if (def == nullptr) continue;
      const auto scope = static_cast<std::uint32_t>(scopes_.size());
      ScopeInfo info;
      info.parent = g_.nodes[node].scope;
      info.autoremap = true;
      scopes_.push_back(std::move(info));
      g_.scope_trees.push_back(alt->adaptable + "/" + alt->name);
      documents_.push_back(&alt->document);
      stack_.push_back(def->id);
      append(out, tick(def->root, *def, scope, {enter}));
      stack_.pop_back();
      documents_.pop_back();
    }
    return out;
  }

  Exits subtree(const bt::Node& xml, const bt::TreeDef& def, std::uint32_t scope,
                std::uint32_t node, std::uint32_t enter) {
    Exits out;
    const std::string* target = xml.attribute("ID");
    if (!target) return out;
    const bt::Document& doc = *documents_.back();
    const bt::TreeDef* sub = doc.find_tree(*target);
    if (sub == nullptr) return out;
    for (const auto& open : stack_)
      if (open == *target) return out;  // recursion: bt-structure's
    if (stack_.size() > 64) return out;
    const auto sub_scope = static_cast<std::uint32_t>(scopes_.size());
    ScopeInfo info;
    info.parent = scope;
    const bool v3 = doc.format == 3;
    auto flag = [&](const char* name) {
      const std::string* text = xml.attribute(name);
      return text && (*text == "true" || *text == "True" || *text == "TRUE" || *text == "1");
    };
    const bool shared = v3 && flag("__shared_blackboard");
    info.autoremap = flag("_autoremap") || (v3 && flag("__autoremap"));
    scopes_.push_back(info);
    g_.scope_trees.push_back(*target);
    std::uint32_t run_scope = shared ? scope : sub_scope;
    if (!shared) {
      for (const auto& [attribute, value] : xml.attributes) {
        if (!bt::is_port_attribute(attribute) || attribute.front() == '_') continue;
        if (auto key = blackboard_key(attribute, value)) {
          // The remapping itself reads nothing: a read inside the SubTree reaches the parent.
          scopes_[sub_scope].remapped[attribute] = *key;
        } else {
          locals_.insert({sub_scope, attribute});
          g_.vertices[enter].writes.push_back(entry(sub_scope, attribute));  // literal value
        }
      }
    }
    (void)def;
    (void)node;
    stack_.push_back(*target);
    append(out, tick(sub->root, *sub, run_scope, {enter}));
    stack_.pop_back();
    return out;
  }

  const load::Mission& m_;
  FlowGraph& g_;
  std::map<std::string, const bt::NodeModel*> models_;
  std::map<std::string, std::vector<const load::Alternative*>> alternatives_;
  std::vector<ScopeInfo> scopes_;
  std::set<std::pair<std::uint32_t, std::string>> locals_;
  std::map<std::pair<std::uint32_t, std::string>, std::uint32_t> entries_;
  std::vector<const bt::Document*> documents_;
  std::vector<std::string> stack_;
  std::set<std::tuple<std::string, int, int, std::string>> seen_scripts_;
  std::set<std::tuple<std::string, int, int>> seen_nodes_;
  int depth_ = 0;
};

}  // namespace

std::string FlowGraph::entry_name(std::uint32_t e) const {
  const std::uint32_t scope = entry_scopes[e];
  if (scope == 0) return "'" + entry_keys[e] + "'";
  return "'" + entry_keys[e] + "' of " + scope_trees[scope];
}

FlowGraph build_flow_graph(const load::Mission& mission) {
  FlowGraph g;
  Builder(mission, g).build();
  return g;
}

}  // namespace uabt::verify::tree
