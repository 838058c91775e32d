#include "runtime/scenario_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "base/suggest.hpp"
#include "bt/node_kinds.hpp"
#include "bt/script/ast.hpp"

namespace uabt::runtime {

namespace {

std::string base_name(const std::string& key) {
  return key.substr(0, key.find('('));
}

}  // namespace

std::string did_you_mean_hint(const std::string& name, const std::set<std::string>& known) {
  const std::string hint = uabt::did_you_mean(name, {known.begin(), known.end()});
  return hint.empty() ? "" : " (" + hint + ")";
}

namespace {

void add_script(const std::string& code, std::set<std::string>& state) {
  try {
    for (const std::string& name : bt::script::Script::parse(code).names())
      state.insert(bt::script::entry_key(name));
  } catch (const bt::script::ScriptError&) {
    // The gate reports scripts that do not parse.
  }
}

void add_node(const bt::Node& node, ScenarioVocabulary& v) {
  const std::string kind = node.kind();
  const bool builtin =
      bt::find_builtin(kind) != nullptr || node.tag == "Adaptable" || !node.children.empty();
  if (!builtin) v.leaves.insert(kind);
  for (const auto& [attr, value] : node.attributes) {
    if (attr == "code" || attr.starts_with('_')) {
      if (attr == "code" || (attr != "_autoremap" && attr != "_description"))
        add_script(value, v.state);
    } else if (value.size() > 2 && value.front() == '{' && value.back() == '}') {
      v.state.insert(value == "{=}" ? attr : value.substr(1, value.size() - 2));
    }
  }
  for (const bt::Node& child : node.children) add_node(child, v);
}

void add_model(const bt::NodeModel& model, ScenarioVocabulary& v) {
  v.leaves.insert(model.id);
  auto& ports = v.ports[model.id];
  for (const bt::Port& port : model.ports)
    if (std::none_of(ports.begin(), ports.end(),
                     [&](const bt::Port& p) { return p.name == port.name; }))
      ports.push_back(port);
}

void add_document(const bt::Document& doc, ScenarioVocabulary& v) {
  for (const bt::TreeDef& tree : doc.trees) add_node(tree.root, v);
  for (const bt::NodeModel& model : doc.node_models) add_model(model, v);
}

// What a port's C++ type (nodes.xml's type=) holds, as a domain type (a string as an enum);
// nullopt for a type uabt does not judge.
std::optional<fretish::VarType> port_value_type(const std::string& type) {
  using fretish::VarType;
  if (type == "bool") return VarType::boolean;
  if (type == "double" || type == "float") return VarType::real;
  static const std::set<std::string> integers = {
      "int",     "unsigned",           "unsigned int", "long",     "unsigned long", "long long",
      "short",   "unsigned long long", "int8_t",       "int16_t",  "int32_t",       "int64_t",
      "uint8_t", "uint16_t",           "uint32_t",     "uint64_t", "size_t",        "std::size_t"};
  if (integers.contains(type)) return VarType::integer;
  if (type == "std::string" || type == "string" || type.starts_with("std::__cxx11::basic_string"))
    return VarType::enumeration;
  return std::nullopt;
}

// What a port's C++ type takes, "" for a type uabt does not judge.
std::string port_misfit(const ScriptValue& value, const std::string& type) {
  using K = ScriptValue::Kind;
  const auto held = port_value_type(type);
  if (!held) return "";
  switch (*held) {
    case fretish::VarType::boolean:
      return value.kind == K::boolean ? "" : "is not a boolean (true or false)";
    case fretish::VarType::real:
      return value.kind == K::integer || value.kind == K::real ? "" : "is not a number";
    case fretish::VarType::integer: return value.kind == K::integer ? "" : "is not an integer";
    case fretish::VarType::enumeration: return value.kind == K::string ? "" : "is not a string";
  }
  return "";
}

// The output (or inout) port `port` of node `kind` in `ports`, nullptr when it has none;
// `outputs` collects the names of its output ports.
const bt::Port* output_port(const std::map<std::string, std::vector<bt::Port>>& ports,
                            const std::string& kind, const std::string& port,
                            std::set<std::string>* outputs = nullptr) {
  const auto it = ports.find(kind);
  const bt::Port* found = nullptr;
  if (it != ports.end())
    for (const bt::Port& p : it->second)
      if (p.direction == "output_port" || p.direction == "inout_port") {
        if (outputs != nullptr) outputs->insert(p.name);
        if (p.name == port && found == nullptr) found = &p;
      }
  return found;
}

}  // namespace

std::string misfit(const ScriptValue& value, const fretish::Variable& var) {
  using fretish::VarType;
  switch (var.type) {
    case VarType::boolean:
      return value.kind == ScriptValue::Kind::boolean ? "" : "is not a boolean (true or false)";
    case VarType::enumeration: {
      const auto& values = var.enum_values;
      if (value.is_string() && std::find(values.begin(), values.end(), value.text) != values.end())
        return "";
      std::string list;
      for (const auto& e : values)
        list += (list.empty() ? "" : ", ") + std::string("\"") + e + "\"";
      return "is not one of " + list;
    }
    case VarType::integer:
    case VarType::real: {
      const bool integer = var.type == VarType::integer;
      if (!(integer ? value.kind == ScriptValue::Kind::integer
                    : value.kind == ScriptValue::Kind::integer ||
                          value.kind == ScriptValue::Kind::real))
        return integer ? "is not an integer" : "is not a number";
      const double d = value.as_double();
      const double lo = var.lower.empty() ? -INFINITY : std::strtod(var.lower.c_str(), nullptr);
      const double hi = var.upper.empty() ? INFINITY : std::strtod(var.upper.c_str(), nullptr);
      if (d < lo || d > hi)
        return "is out of its range [" + (var.lower.empty() ? "-inf" : var.lower) + ", " +
               (var.upper.empty() ? "inf" : var.upper) + "]";
      return "";
    }
  }
  return "";
}

std::string misfit_message(const std::string& name, const ScriptValue& value,
                           const fretish::Variable& var) {
  const std::string why = misfit(value, var);
  if (why.empty()) return "";
  return name + " = " + (value.is_string() ? "\"" + value.to_string() + "\"" : value.to_string()) +
         " " + why + " (declared " + fretish::var_type_name(var.type) + " at " +
         place_text(var.location) + ")";
}

bool ScenarioVocabulary::is_leaf(const std::string& key) const {
  return leaves.contains(base_name(key));
}

std::string ScenarioVocabulary::output_misfit(const std::string& action, const std::string& port,
                                              const ScriptValue& value, bool& at_value) const {
  at_value = false;
  const std::string kind = base_name(action);
  std::set<std::string> outputs;
  const bt::Port* found = output_port(ports, kind, port, &outputs);
  if (found == nullptr) {
    if (outputs.empty())
      return "'" + kind + "' has no output port in nodes.xml, so it writes no '" + port + "'";
    std::string list;
    for (const std::string& o : outputs) list += (list.empty() ? "" : ", ") + o;
    return "'" + port + "' is not an output port of '" + kind + "' (its output ports: " + list +
           ")" + did_you_mean_hint(port, outputs);
  }
  const std::string why = port_misfit(value, found->type);
  if (why.empty()) return "";
  at_value = true;
  return "the value of output port '" + port + "' of '" + kind + "', " +
         (value.is_string() ? "\"" + value.to_string() + "\"" : value.to_string()) + ", " + why +
         " (the port's type is " + found->type + ")";
}

std::optional<fretish::VarType> ScenarioVocabulary::state_type(const std::string& key) const {
  const auto it = variables.find(key);
  if (it == variables.end()) return std::nullopt;
  return it->second.type;
}

std::optional<fretish::VarType> ScenarioVocabulary::output_type(const std::string& action,
                                                                const std::string& port) const {
  const bt::Port* found = output_port(ports, base_name(action), port);
  if (found == nullptr) return std::nullopt;
  return port_value_type(found->type);
}

void type_number(ScriptValue& value, std::optional<fretish::VarType> declared) {
  using K = ScriptValue::Kind;
  if (value.kind != K::integer && value.kind != K::real) return;
  const bool integer =
      fretish::number_is_integer(declared, value.as_double(), value.kind == K::integer);
  if (integer && value.kind == K::real)
    value = ScriptValue::of_int(static_cast<std::int64_t>(value.real));
  else if (!integer && value.kind == K::integer)
    value = ScriptValue::of_real(static_cast<double>(value.integer));
}

void type_numbers(Scenario& scenario, const ScenarioVocabulary& vocabulary) {
  const auto state = [&](StateAssignment& assignment) {
    for (auto& [key, value] : assignment) type_number(value, vocabulary.state_type(key));
  };
  const auto outputs = [&](const std::string& action, StateAssignment& assignment) {
    for (auto& [port, value] : assignment) type_number(value, vocabulary.output_type(action, port));
  };
  state(scenario.initial);
  for (ScenarioEvent& e : scenario.events) state(e.set);
  for (auto& [name, spec] : scenario.actions) {
    state(spec.effects);
    outputs(name, spec.outputs);
    for (ActionRun& run : spec.runs) {
      state(run.effects);
      outputs(name, run.outputs);
    }
  }
}

void ScenarioVocabulary::add(const load::Mission& mission) {
  for (const fretish::Variable& var : mission.domain.variables) {
    state.insert(var.name);
    if (var.declared) variables.emplace(var.name, var);
  }
  add_document(mission.tree, *this);
  for (const load::Alternative& alt : mission.alternatives) add_document(alt.document, *this);
  if (mission.nodes)
    for (const bt::NodeModel& model : *mission.nodes) add_model(model, *this);
}

std::vector<std::string> check_scenario(const Scenario& scenario,
                                        const ScenarioVocabulary& vocabulary) {
  std::vector<std::string> errors;
  std::set<std::string> names = vocabulary.state;
  names.insert(vocabulary.leaves.begin(), vocabulary.leaves.end());

  auto check_state = [&](const StateAssignment& assignment, const std::string& where) {
    for (const auto& [key, value] : assignment) {
      const std::string pointer = where + "/" + key;
      const auto var = vocabulary.variables.find(key);
      if (var != vocabulary.variables.end()) {
        const std::string why = misfit_message(key, value, var->second);
        if (!why.empty()) errors.push_back(scenario.where(pointer, true) + ": error: " + why);
      } else if (!vocabulary.state.contains(key) && !vocabulary.is_leaf(key)) {
        errors.push_back(scenario.where(pointer) + ": error: '" + key +
                         "' is not a state variable, condition or blackboard key of the mission" +
                         did_you_mean_hint(key, names));
      }
    }
  };
  check_state(scenario.initial, "/initial");
  for (const ScenarioEvent& e : scenario.events)
    check_state(e.set, "/events/" + std::to_string(e.index) + "/set");
  // Not a structured binding: clang before 16 cannot capture one in the lambda below.
  for (const auto& action : scenario.actions) {
    const std::string& name = action.first;
    const ActionSpec& spec = action.second;
    if (!vocabulary.is_leaf(name))
      errors.push_back(scenario.where("/actions/" + name) + ": error: action '" + name +
                       "' is not a leaf of the mission" +
                       did_you_mean_hint(name, vocabulary.leaves));
    check_state(spec.effects, "/actions/" + name + "/effects");
    auto check_outputs = [&](const StateAssignment& outputs, const std::string& where) {
      if (!vocabulary.is_leaf(name)) return;
      for (const auto& [port, value] : outputs) {
        bool at_value = false;
        const std::string why = vocabulary.output_misfit(name, port, value, at_value);
        if (!why.empty())
          errors.push_back(scenario.where(where + "/" + port, at_value) + ": error: " + why);
      }
    };
    check_outputs(spec.outputs, "/actions/" + name + "/outputs");
    for (std::size_t i = 0; i < spec.runs.size(); ++i) {
      const std::string run = "/actions/" + name + "/runs/" + std::to_string(i);
      check_state(spec.runs[i].effects, run + "/effects");
      check_outputs(spec.runs[i].outputs, run + "/outputs");
    }
  }
  return errors;
}

}  // namespace uabt::runtime
