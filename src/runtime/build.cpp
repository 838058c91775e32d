// Instantiation of a runtime tree from bt::TreeDefs: BT.CPP's load-time rules, ports
// resolved to blackboard slots, scripts compiled, robot leaves bound to the World.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

#include "bt/node_kinds.hpp"
#include "bt/script/load_check.hpp"
#include "bt/structure.hpp"
#include "runtime/core.hpp"
#include "runtime/smart_selection.hpp"

namespace uabt::runtime {

using bt::blackboard_key;

namespace detail {

namespace {

// The built-in kinds the runtime ticks (engine.cpp's execute_tick).
bool runs(Kind kind) {
  static constexpr Kind kRuns[] = {
      // controls
      Kind::sequence, Kind::sequence_with_memory, Kind::reactive_sequence, Kind::fallback,
      Kind::reactive_fallback, Kind::parallel, Kind::parallel_all, Kind::if_then_else,
      Kind::while_do_else,
      // decorators
      Kind::inverter, Kind::force_success, Kind::force_failure, Kind::repeat,
      Kind::retry_until_successful, Kind::keep_running_until_failure, Kind::run_once,
      // leaves
      Kind::subtree, Kind::always_success, Kind::always_failure, Kind::script,
      Kind::script_condition};
  return std::find(std::begin(kRuns), std::end(kRuns), kind) != std::end(kRuns);
}

// BT.CPP 4.x's pre- and post-condition attributes, where their scripts go.
struct ConditionAttribute {
  std::string_view name;
  bool pre;
  int index;
};
constexpr ConditionAttribute kConditionAttributes[] = {
    {"_failureIf", true, ConditionScripts::failure_if},
    {"_successIf", true, ConditionScripts::success_if},
    {"_skipIf", true, ConditionScripts::skip_if},
    {"_while", true, ConditionScripts::while_true},
    {"_onHalted", false, ConditionScripts::on_halted},
    {"_onFailure", false, ConditionScripts::on_failure},
    {"_onSuccess", false, ConditionScripts::on_success},
    {"_post", false, ConditionScripts::always},
};

const ConditionAttribute* condition_attribute(std::string_view name) {
  for (const auto& a : kConditionAttributes)
    if (a.name == name) return &a;
  return nullptr;
}

// BT.CPP treats only attributes that start with a letter as ports; `_description`, `_uid`
// and the pre/post-condition attributes are not ports of the node.
bool is_port_name(const std::string& attr) {
  return !attr.empty() && std::isalpha(static_cast<unsigned char>(attr.front()));
}

// BT.CPP 4's IsAllowedPortName: a SubTree attribute is a port when it starts with a letter,
// has none of the characters that break XML or paths, and is not reserved (ID, name,
// _autoremap, the pre/post-condition attributes, which all start with '_' anyway).
bool is_subtree_port(const std::string& attr) {
  if (!is_port_name(attr) || attr == "ID" || attr == "name") return false;
  for (const char c : attr) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) continue;
    if (u < 32 || u == 127 ||
        std::string_view(" \t\n\r<>&\"'/\\:*?|.").find(c) != std::string_view::npos)
      return false;
  }
  return true;
}

// A SubTree's literal port value as BT.CPP 4.10 stores it (recursivelyCreateSubtree): an
// integer when the whole text is one (no '.', 'e' or 'E'), else a double when the whole text
// is one, else the string.
ScriptValue subtree_literal(const std::string& text) {
  if (text.empty()) return ScriptValue::of_string(text);
  const char* first = text.data();
  const char* last = first + text.size();
  if (text.find_first_of(".eE") == std::string::npos) {
    std::int64_t i = 0;
    const auto [end, ec] = std::from_chars(first, last, i);
    if (ec == std::errc() && end == last) return ScriptValue::of_int(i);
  }
  double d = 0.0;
  const auto [end, ec] = std::from_chars(first, last, d);
  if (ec == std::errc() && end == last) return ScriptValue::of_real(d);
  return ScriptValue::of_string(text);
}

std::optional<bool> parse_bool(const std::string& text) {
  if (text == "true" || text == "True" || text == "TRUE" || text == "1") return true;
  if (text == "false" || text == "False" || text == "FALSE" || text == "0") return false;
  return std::nullopt;
}

}  // namespace

NodeId Builder::instantiate_tree(const std::shared_ptr<const bt::TreeDef>& def,
                                 std::uint32_t instance, NodeId parent) {
  call_stack.push_back(def->id);
  const NodeId root = instantiate_node(def->root, *def, instance, parent, 0, 1);
  call_stack.pop_back();
  return root;
}

NodeId Builder::instantiate_node(const bt::Node& xml, const bt::TreeDef& def,
                                 std::uint32_t instance, NodeId parent, std::uint32_t child_index,
                                 int depth) {
  const std::string& file = def.file.empty() ? core.file : def.file;
  const std::string where = place_text(file, xml.line, xml.column) + ": ";
  auto refuse = [&](const std::string& message) -> LoadError { return LoadError(where + message); };

  if (depth > bt::kMaxDepth)
    throw refuse("tree '" + def.id + "' is nested deeper than " + std::to_string(bt::kMaxDepth) +
                 " levels");
  const std::string kind_name = xml.kind();
  if (xml.tag == "Adaptable")
    throw refuse("<Adaptable ID=\"" + (xml.attribute("ID") ? *xml.attribute("ID") : "") +
                 "\"/> cannot run: compile the mission first (uabt compile)");
  // BT.CPP parses a node's scripts when it builds it; the static checks apply the same rules.
  std::vector<bt::script::NodeScript> scripts = bt::script::parse_node_scripts(xml);
  for (const bt::script::NodeScript& s : scripts) {
    if (s.refusal.empty()) continue;
    const auto [line, column] =
        s.attribute.empty() ? std::pair{xml.line, xml.column} : xml.attribute_position(s.attribute);
    throw LoadError(place_text(file, line, column) + ": " + s.refusal);
  }
  const bt::BuiltinNode* builtin = bt::find_builtin(kind_name);
  if (builtin != nullptr && !runs(builtin->kind))
    throw refuse("BehaviorTree.CPP's " + kind_name + " is not supported by the uabt runtime");
  if (builtin == nullptr && !xml.children.empty())
    throw refuse("'" + kind_name + "' has children but is not a control or decorator node " +
                 "of BehaviorTree.CPP");
  const bt::Family family = builtin ? builtin->family : bt::Family::action;
  const Kind kind = builtin ? builtin->kind : Kind::robot;

  const std::size_t n_children = xml.children.size();
  if (family == bt::Family::control && n_children == 0)
    throw refuse(kind_name + " needs at least one child");
  if (family == bt::Family::decorator && n_children != 1)
    throw refuse(kind_name + " needs exactly one child, it has " + std::to_string(n_children));
  if (family != bt::Family::control && family != bt::Family::decorator && n_children != 0)
    throw refuse(kind_name + " cannot have children");

  const auto id = static_cast<NodeId>(core.nodes.size());
  RtNode node;
  node.kind = kind;
  core.nodes.push_back(node);
  NodeInfo info;
  info.tag = xml.tag;
  info.kind = kind_name;
  if (const std::string* name = xml.attribute("name")) info.name = *name;
  info.tree_id = def.id;
  info.parent = parent;
  info.child_index = child_index;
  info.instance = instance;
  info.location = SourceLocation{file, xml.line, xml.column};
  info.element = &xml;
  core.info.push_back(std::move(info));

  const ScopeId scope = core.instances[instance].scope;
  Blackboard& bb = core.bb;
  auto new_params = [&]() -> NodeParams& {
    core.nodes[id].params = static_cast<std::uint32_t>(core.params.size());
    return core.params.emplace_back();
  };
  // An integer/boolean input: literal converted now (BT.CPP fails at load), `{key}` at tick.
  auto input = [&](const char* port, std::optional<std::int64_t> fallback, bool boolean) -> Input {
    Input in;
    const std::string* text = xml.attribute(port);
    if (text == nullptr) {
      in.present = fallback.has_value();
      in.value = fallback.value_or(0);
      return in;
    }
    in.present = true;
    if (auto key = blackboard_key(port, *text)) {
      in.slot = bb.resolve(scope, *key);
      return in;
    }
    if (boolean) {
      const auto b = parse_bool(*text);
      if (!b) throw refuse(kind_name + ": port " + port + "=\"" + *text + "\" is not a boolean");
      in.value = *b ? 1 : 0;
      return in;
    }
    const char* last = text->data() + text->size();
    const auto [end, ec] = std::from_chars(text->data(), last, in.value);
    if (text->empty() || ec != std::errc() || end != last || in.value < INT32_MIN ||
        in.value > INT32_MAX)
      throw refuse(kind_name + ": port " + port + "=\"" + *text + "\" is not an integer");
    return in;
  };

  // The script of `attribute`, parsed above, compiled and bound to this scope.
  auto compile = [&](std::string_view attribute) -> std::uint32_t {
    auto parsed = std::find_if(scripts.begin(), scripts.end(),
                               [&](const auto& s) { return s.attribute == attribute; });
    script::Program program = script::Program::of(std::move(*parsed->script));
    program.bind(bb, scope);
    core.programs.push_back(std::move(program));
    return static_cast<std::uint32_t>(core.programs.size() - 1);
  };

  // Attributes: reserved ones, then the ports the node declares.
  for (const auto& [attr, value] : xml.attributes) {
    if (attr == "name") continue;
    if (const ConditionAttribute* c = condition_attribute(attr)) {
      if (core.nodes[id].conditions == RtNode::kNoConditions) {
        core.nodes[id].conditions = static_cast<std::uint32_t>(core.conditions.size());
        core.conditions.emplace_back();
      }
      ConditionScripts& scripts = core.conditions[core.nodes[id].conditions];
      const auto program = static_cast<std::int32_t>(compile(attr));
      (c->pre ? scripts.pre : scripts.post)[c->index] = program;
      continue;
    }
    if (attr == "ID" && (bt::is_explicit_family_tag(xml.tag) || family == bt::Family::subtree))
      continue;
    if (family == bt::Family::subtree || kind == Kind::robot) continue;  // ports, see below
    if (!is_port_name(attr)) continue;
    bool known = false;
    for (const bt::Port& port : builtin->ports) known = known || port.name == attr;
    for (const std::string& port : builtin->v3_ports) known = known || port == attr;
    if (!known) throw refuse(kind_name + " has no port named '" + attr + "'");
  }

  switch (kind) {
    case Kind::parallel: {
      NodeParams& p = new_params();
      p.in0 =
          input(xml.attribute("success_count") ? "success_count" : "success_threshold", -1, false);
      p.in1 =
          input(xml.attribute("failure_count") ? "failure_count" : "failure_threshold", 1, false);
      break;
    }
    case Kind::parallel_all: new_params().in0 = input("max_failures", 1, false); break;
    case Kind::repeat: new_params().in0 = input("num_cycles", std::nullopt, false); break;
    case Kind::retry_until_successful:
      new_params().in0 = input("num_attempts", std::nullopt, false);
      break;
    case Kind::run_once: new_params().in0 = input("then_skip", 1, true); break;
    case Kind::script:
    case Kind::script_condition: {
      const std::uint32_t program = compile("code");  // present: parse_node_scripts above
      new_params().program = program;
      break;
    }
    case Kind::robot: {
      NodeParams& p = new_params();
      p.ports_begin = static_cast<std::uint32_t>(core.leaf_ports.size());
      for (const auto& [attr, value] : xml.attributes) {
        if (attr == "name" || (attr == "ID" && bt::is_explicit_family_tag(xml.tag))) continue;
        if (!is_port_name(attr)) continue;
        LeafPort port;
        port.name = attr;
        if (auto key = blackboard_key(attr, value)) {
          port.slot = bb.resolve(scope, *key);
          port.key = *key;
          if (const auto model = core.port_directions.find(core.info[id].kind);
              model != core.port_directions.end())
            if (const auto d = model->second.find(attr); d != model->second.end())
              port.direction = d->second;
        } else {
          port.literal = value;
        }
        core.leaf_ports.push_back(std::move(port));
      }
      p.ports_count = static_cast<std::uint32_t>(core.leaf_ports.size()) - p.ports_begin;
      if (bind_world) core.bind_world_leaf(id);
      break;
    }
    case Kind::subtree: {
      const std::string* target = xml.attribute("ID");
      if (target == nullptr) throw refuse("SubTree needs an ID attribute");
      const auto def_it = core.defs.find(*target);
      if (def_it == core.defs.end())
        throw refuse("SubTree ID '" + *target + "' names no <BehaviorTree>");
      for (std::size_t i = 0; i < call_stack.size(); ++i) {
        if (call_stack[i] != *target) continue;
        std::string cycle;
        for (std::size_t j = i; j < call_stack.size(); ++j) cycle += call_stack[j] + " -> ";
        throw refuse("recursive SubTree: " + cycle + *target);
      }
      if (static_cast<int>(call_stack.size()) >= core.options.max_subtree_nesting)
        throw refuse("SubTrees nested deeper than " +
                     std::to_string(core.options.max_subtree_nesting) + " levels");

      auto flag = [&](const char* attr) {
        const std::string* text = xml.attribute(attr);
        if (text == nullptr) return false;
        const auto b = parse_bool(*text);
        if (!b) throw refuse(std::string(attr) + "=\"" + *text + "\" is not a boolean");
        return *b;
      };
      // v3 spellings: `__shared_blackboard` (the caller's blackboard itself) and
      // `__autoremap`. A v4 file is read as BT.CPP 4 reads it: they are not port names
      // (they do not start with a letter), so it ignores them.
      const bool v3 = core.format == 3;
      const bool shared = v3 && flag("__shared_blackboard");
      const bool autoremap = flag("_autoremap") || (v3 && flag("__autoremap"));
      const ScopeId sub_scope = shared ? scope : bb.add_scope(scope, autoremap);
      if (!shared) {
        for (const auto& [attr, value] : xml.attributes) {
          if (v3 ? (attr == "ID" || attr == "name" || attr == "_autoremap" ||
                    attr == "__autoremap" || attr == "__shared_blackboard")
                 : !is_subtree_port(attr))
            continue;
          if (auto key = blackboard_key(attr, value)) {
            bb.add_remap(sub_scope, attr, *key);
          } else {
            bb.set_local(sub_scope, attr, subtree_literal(value));
          }
        }
      }
      const auto sub_instance = static_cast<std::uint32_t>(core.instances.size());
      Instance inst;
      inst.tree_id = *target;
      inst.call = id;
      inst.scope = sub_scope;
      core.instances.push_back(std::move(inst));
      new_params().instance = sub_instance;

      const auto slot = static_cast<std::uint32_t>(core.children.size());
      core.children.push_back(kNoNode);
      core.child_done.push_back(0);
      core.nodes[id].first_child = slot;
      core.nodes[id].child_count = 1;
      const NodeId sub_root = instantiate_tree(def_it->second, sub_instance, id);
      core.children[slot] = sub_root;
      core.instances[sub_instance].root = sub_root;
      return id;
    }
    default: break;
  }

  if (n_children > 0) {
    const auto first = static_cast<std::uint32_t>(core.children.size());
    core.children.resize(first + n_children, kNoNode);
    core.child_done.resize(first + n_children, 0);
    core.nodes[id].first_child = first;
    core.nodes[id].child_count = static_cast<std::uint32_t>(n_children);
    for (std::uint32_t i = 0; i < n_children; ++i)
      core.children[first + i] = instantiate_node(xml.children[i], def, instance, id, i, depth + 1);
  }
  return id;
}

CoreMark mark(const Core& core) {
  return CoreMark{core.nodes.size(),      core.children.size(), core.params.size(),
                  core.leaf_ports.size(), core.programs.size(), core.conditions.size(),
                  core.instances.size(),  core.bb.mark()};
}

void rollback(Core& core, const CoreMark& m) {
  core.nodes.resize(m.nodes);
  core.info.resize(m.nodes);
  core.children.resize(m.children);
  core.child_done.resize(m.children);
  core.params.resize(m.params);
  core.leaf_ports.resize(m.leaf_ports);
  core.programs.resize(m.programs);
  core.conditions.resize(m.conditions);
  core.instances.resize(m.instances);
  core.bb.rollback(m.bb);
}

}  // namespace detail

void detail::Core::bind_world_leaf(NodeId id) {
  const NodeInfo& i = info[id];
  const std::string family = i.tag == "Action" || i.tag == "Condition" ? i.tag : std::string();
  detail::NodeParams& p = params[nodes[id].params];
  const std::span<const LeafPort> ports(leaf_ports.data() + p.ports_begin, p.ports_count);
  p.world_handle = world->bind_leaf(LeafBinding{id, i.kind, family, ports, i, bb});
}

Engine Engine::build(const bt::Document& doc, World& world, EngineOptions options) {
  return build(doc, std::string(), world, std::move(options));
}

Engine Engine::build(const bt::Document& doc, const std::string& main_tree, World& world,
                     EngineOptions options) {
  auto core = std::make_unique<detail::Core>();
  core->world = &world;
  core->options = options;
  if (options.smart_selection) core->smart = std::make_shared<detail::SmartSelection>();
  core->file = doc.file;
  core->format = doc.format;
  for (const bt::NodeModel& model : doc.node_models) {
    auto& ports = core->port_directions[model.id];
    for (const bt::Port& port : model.ports)
      ports[port.name] = port.direction == "output_port"  ? PortDirection::output
                         : port.direction == "inout_port" ? PortDirection::inout
                                                          : PortDirection::input;
  }
  for (const bt::TreeDef& tree : doc.trees) {
    auto [it, inserted] = core->defs.emplace(tree.id, std::make_shared<bt::TreeDef>(tree));
    if (!inserted)
      throw LoadError(place_text(doc.file, tree.line, tree.column) + ": tree '" + tree.id +
                      "' is defined twice");
  }
  const bt::TreeDef* main = main_tree.empty() ? doc.main() : doc.find_tree(main_tree);
  if (main == nullptr)
    throw LoadError(
        doc.file + ":" + std::to_string(doc.root_line) + ":1: " +
        (main_tree.empty() && doc.main_tree.empty()
             ? std::string("several trees and no main_tree_to_execute: which one runs?")
             : "no tree '" + (main_tree.empty() ? doc.main_tree : main_tree) + "' to run"));
  detail::Instance inst;
  inst.tree_id = main->id;
  core->instances.push_back(std::move(inst));
  detail::Builder builder(*core);
  core->root = builder.instantiate_tree(core->defs.at(main->id), 0, kNoNode);
  core->instances[0].root = core->root;
  return Engine(std::move(core));
}

}  // namespace uabt::runtime
