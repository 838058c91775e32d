#include "realize/realize.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "base/number_text.hpp"
#include "base/suggest.hpp"
#include "bt/node_kinds.hpp"
#include "bt/script/load_check.hpp"
#include "load/run_trees.hpp"
#include "monitor/templates.hpp"
#include "prove/cells.hpp"
#include "prove/model.hpp"
#include "prove/world_model.hpp"

namespace uabt::realize {

namespace {

using monitor::Val;

// What the requirements may read of the mission: the node labels of the trees a run has, its
// adaptable nodes and their alternatives, and the blackboard entries its trees write.
struct Vocabulary {
  std::set<std::string> labels;        // every node's name and ID
  std::set<std::string> robot_leaves;  // labels of the robot's leaves: the world ends them
  std::map<std::string, std::set<std::string>> leaf_kinds;  // a robot leaf's label → its IDs
  std::set<std::string> other_nodes;                        // labels of built-in nodes and SubTrees
  std::set<std::string> conditions;  // the robot's leaves nodes.xml (or the tag) calls Condition
  std::map<std::string, std::vector<std::string>> alternatives;  // adaptable → alternatives
  std::set<std::string> written;   // entries a script assigns or an output port writes
  std::set<std::string> literals;  // enum literals, alternatives, none
};

using Models = std::map<std::string, const bt::NodeModel*, std::less<>>;

void visit(const bt::Node& n, const Models& models, Vocabulary& v) {
  if (n.tag != "Adaptable") {
    const std::string kind = n.kind();
    std::vector<std::string> labels{kind};
    if (const std::string* name = n.attribute("name"); name != nullptr && !name->empty())
      labels.push_back(*name);
    const bool robot_leaf =
        n.children.empty() && !bt::is_subtree(n.tag) && bt::find_builtin(kind) == nullptr;
    const auto registered = models.find(kind);  // the robot's registration of the node
    const bt::NodeModel* model = registered == models.end() ? nullptr : registered->second;
    const bool condition = n.tag == "Condition" || (model && model->family == "Condition");
    for (const auto& l : labels) {
      v.labels.insert(l);
      (robot_leaf ? v.robot_leaves : v.other_nodes).insert(l);
      if (robot_leaf) v.leaf_kinds[l].insert(kind);
      if (robot_leaf && condition) v.conditions.insert(l);
    }
    for (const auto& s : bt::script::parse_node_scripts(n))
      if (s.script)
        if (const std::string* code = n.attribute(s.attribute.empty() ? "code" : s.attribute))
          for (const auto& key : prove::assigned_names(*code))
            v.written.insert(bt::script::entry_key(key));
    if (model != nullptr)
      for (const auto& port : model->ports)
        if (port.direction != "input_port")
          if (const std::string* value = n.attribute(port.name))
            if (auto key = bt::blackboard_key(port.name, *value)) v.written.insert(*key);
  }
  for (const auto& c : n.children) visit(c, models, v);
}

Vocabulary vocabulary_of(const load::Mission& m) {
  Vocabulary v;
  Models models;
  if (m.nodes)
    for (const auto& model : *m.nodes) models.emplace(model.id, &model);  // the first of an ID
  for (const load::RunTree& t : load::run_trees(m)) visit(t.tree->root, models, v);
  for (const auto& alt : m.alternatives) {
    v.alternatives[alt.adaptable].push_back(alt.name);
    v.literals.insert(alt.name);
  }
  for (const auto& site : m.adaptables) v.alternatives[site.id];  // one without alternatives
  for (const auto& var : m.domain.variables)
    for (const auto& literal : var.enum_values) v.literals.insert(literal);
  v.literals.insert("none");
  return v;
}

// A name the requirements read, as the game plays it.
struct GameSignal {
  Signal shown;
  fretish::Variable declaration;  // its type and values (a synthetic one for node statuses)
  std::vector<Val> values;        // one per cell, parallel to shown.values
  int slot = -1;                  // its frame slot
  std::string label;              // a node status's node label, else ""
  std::string status;             // "running", "success", "failure", "selected", "mode", ""
  // A status of the robot's own node, which no side chooses alone: the world says how the
  // node ends when it ends this tick (`<label>.result`: success or failure, an input, so that
  // the tree's later nodes react to it as a Fallback does), the tree runs the node or lets it
  // end (`<label>.state`: idle, running, ended).
  bool derived = false;
  bool choice_of_node = false;  // one of those two choices
};

std::string state_name(const std::string& label) {
  return label + ".state";
}
std::string result_name(const std::string& label) {
  return label + ".result";
}

fretish::Variable boolean_named(const std::string& name) {
  fretish::Variable v;
  v.name = name;
  v.type = fretish::VarType::boolean;
  return v;
}

// The role and type of `name`; nullopt when the requirements cannot read it (a literal, FTP, an
// unknown name: the monitor's compilation says which).
std::optional<GameSignal> signal_of(const std::string& name, const load::Mission& m,
                                    const Vocabulary& v) {
  GameSignal s;
  s.shown.name = name;
  if (const fretish::Variable* d = m.domain.find(name)) {
    s.declaration = *d;
    const bool written = v.written.count(name) != 0;
    s.shown.role = written ? Role::output : Role::input;
    s.shown.why = written ? "a tree writes it" : "a domain variable no tree writes";
    return s;
  }
  if (v.literals.count(name) != 0 || name == "FTP") return std::nullopt;
  if (v.robot_leaves.count(name) != 0) {  // a condition of the robot's, read as its result
    s.declaration = boolean_named(name);
    s.shown.role = Role::input;
    s.shown.why = "the world decides what the robot's condition finds";
    return s;
  }
  if (v.alternatives.count(name) != 0) {
    s.declaration = boolean_named(name);
    s.shown.role = Role::output;
    s.shown.why = "the tree decides when it ticks the adaptable node";
    s.label = name;
    s.status = "mode";
    return s;
  }
  const std::size_t dot = name.rfind('.');
  if (dot == std::string::npos) return std::nullopt;
  const std::string label = name.substr(0, dot), field = name.substr(dot + 1);
  if (field == "selected" && v.alternatives.count(label) != 0) {
    s.declaration.name = name;
    s.declaration.type = fretish::VarType::enumeration;
    s.declaration.enum_values = v.alternatives.at(label);
    s.declaration.enum_values.push_back("none");
    s.shown.role = Role::output;
    s.shown.why = "the tree selects the alternative";
    s.label = label;
    s.status = "selected";
    return s;
  }
  if ((field == "running" || field == "success" || field == "failure") && v.labels.count(label)) {
    s.declaration = boolean_named(name);
    s.derived = v.robot_leaves.count(label) != 0 && v.other_nodes.count(label) == 0;
    s.shown.role = Role::output;
    s.shown.why = s.derived ? "the tree decides whether it ticks the node, the world how it ends"
                            : "the tree decides what it runs";
    s.label = label;
    s.status = field;
    return s;
  }
  return std::nullopt;
}

Val value_of(const runtime::ScriptValue& v, monitor::Symbols& symbols) {
  switch (v.kind) {
    case runtime::ScriptValue::Kind::boolean: return Val::of_bool(v.boolean);
    case runtime::ScriptValue::Kind::integer: return Val::of_whole(v.integer);
    case runtime::ScriptValue::Kind::real: return Val::of_number(v.real);
    default: return Val::of_symbol(symbols.id(v.text));
  }
}

// The properties the game reads and the signals they read: every name resolves to one slot of
// `variables` or to a literal of `symbols`.
struct Table {
  const load::Mission& mission;
  const prove::WorldModel& world;
  Vocabulary vocabulary;
  monitor::Variables variables;
  monitor::Symbols symbols;
  std::map<std::string, GameSignal> signals;  // by name
  std::vector<prove::Property> properties;    // parallel to mission.properties
  // The domain's `assume`s: what every tick's state satisfies (mission.domain.assumptions).
  struct Constraint {
    const fretish::Assumption* assumption = nullptr;
    std::shared_ptr<monitor::CompiledExpression> expr;  // null: it cannot be read (`error`)
    std::string error;
  };
  std::vector<Constraint> constraints;
  // Per property, then per constraint (a game's items): the signals it reads.
  std::vector<std::set<std::string>> reads;
  std::set<std::string> unknown;  // names a requirement reads that the mission does not have

  Table(const load::Mission& m, const prove::WorldModel& w)
      : mission(m), world(w), vocabulary(vocabulary_of(m)) {
    const monitor::Resolver resolve = [this](const std::string& name) -> monitor::Resolved {
      if (auto it = signals.find(name); it != signals.end())
        return {monitor::Resolved::Kind::variable, it->second.slot};
      if (auto s = signal_of(name, mission, vocabulary)) {
        s->slot = variables.id(name);
        const int slot = s->slot;
        if (s->derived) add_choices(s->label);
        signals.emplace(name, std::move(*s));
        return {monitor::Resolved::Kind::variable, slot};
      }
      if (vocabulary.literals.count(name) != 0)
        return {monitor::Resolved::Kind::literal, symbols.id(name)};
      if (name != "FTP") unknown.insert(name);
      return {};
    };
    for (const fretish::Requirement& r : mission.properties) {
      properties.push_back(prove::make_property(r, resolve));
      std::set<std::string> read;
      for (const auto& part : properties.back().exprs)
        if (part)
          for (const auto& id : fretish::identifiers_of(*part)) add_read(id, read);
      reads.push_back(std::move(read));
    }
    for (const fretish::Assumption& a : mission.domain.assumptions) {
      if (!a.expr) continue;
      Constraint c;
      c.assumption = &a;
      if (auto compiled = monitor::CompiledExpression::compile(*a.expr, resolve, c.error))
        c.expr = std::make_shared<monitor::CompiledExpression>(std::move(*compiled));
      std::set<std::string> read;
      for (const auto& id : fretish::identifiers_of(*a.expr)) add_read(id, read);
      constraints.push_back(std::move(c));
      reads.push_back(std::move(read));
    }
  }

  // Why a requirement cannot be read: the first name it reads that the mission does not have.
  std::string unreadable(std::size_t item, const std::string& fallback) {
    const fretish::Requirement* r = properties[item].requirement;
    for (const auto& part : properties[item].exprs)
      if (part)
        for (const auto& id : fretish::identifiers_of(*part)) {
          if (unknown.count(id) == 0) continue;
          std::string why = r->id + ": '" + id +
                            "' is no domain variable, condition, node status "
                            "(<node>.running/.success/.failure), adaptable node or "
                            "<adaptable>.selected of the mission";
          const std::string hint = did_you_mean(id, known_names());
          return hint.empty() ? why : why + " (" + hint + ")";
        }
    return r->id + ": " + fallback;
  }

  // Every name a requirement may read.
  std::vector<std::string> known_names() const {
    std::vector<std::string> out;
    for (const auto& d : mission.domain.variables) out.push_back(d.name);
    for (const auto& label : vocabulary.labels)
      for (const char* status : {".running", ".success", ".failure"}) out.push_back(label + status);
    for (const auto& label : vocabulary.robot_leaves) out.push_back(label);
    for (const auto& [adaptable, alternatives] : vocabulary.alternatives) {
      out.push_back(adaptable);
      out.push_back(adaptable + ".selected");
    }
    return out;
  }

  // `name` read: itself, and for a derived status the choices it is made of.
  void add_read(const std::string& name, std::set<std::string>& read) const {
    const auto it = signals.find(name);
    if (it == signals.end()) return;
    read.insert(name);
    if (it->second.derived) {
      read.insert(state_name(it->second.label));
      // How the node ends matters only to its success and failure.
      if (it->second.status != "running") read.insert(result_name(it->second.label));
    }
  }

  // The tree's and the world's choices for the robot's node `label`, once.
  void add_choices(const std::string& label) {
    if (signals.count(state_name(label)) != 0) return;
    const auto add = [&](const std::string& name, Role role, const std::string& why,
                         std::vector<std::string> values) {
      GameSignal choice;
      choice.shown = {name, role, {}, why, ""};
      choice.declaration.name = name;
      choice.declaration.type = fretish::VarType::enumeration;
      choice.declaration.enum_values = std::move(values);
      choice.label = label;
      choice.choice_of_node = true;
      choice.slot = variables.id(name);
      signals.emplace(name, std::move(choice));
    };
    const bool condition = vocabulary.conditions.count(label) != 0;
    add(state_name(label), Role::output, "the tree decides whether it runs the node or lets it end",
        condition ? std::vector<std::string>{"idle", "ended"}
                  : std::vector<std::string>{"idle", "running", "ended"});
    add(result_name(label), Role::input,
        "the world decides how the node ends when the tree lets it end this tick", endings(label));
    if (const auto& kinds = vocabulary.leaf_kinds.at(label); kinds.size() == 1)
      signals.at(result_name(label)).shown.action = *kinds.begin();
  }

  // How world.json lets the robot's node `label` end: the results its contracts list, over
  // every node of that label (an entry for one set of port values counts as a way the node may
  // end); success and failure when one of them has no entry.
  std::vector<std::string> endings(const std::string& label) const {
    std::set<runtime::NodeStatus> results;
    for (const std::string& kind : vocabulary.leaf_kinds.at(label)) {
      bool listed = false;
      for (const auto& [key, contract] : world.actions)
        if (key == kind ||
            (key.starts_with(kind) && key.size() > kind.size() && key[kind.size()] == '(')) {
          listed = true;
          results.insert(contract.results.begin(), contract.results.end());
        }
      if (!listed) return {"success", "failure"};
    }
    std::vector<std::string> out;
    if (results.count(runtime::NodeStatus::success)) out.push_back("success");
    if (results.count(runtime::NodeStatus::failure)) out.push_back("failure");
    if (out.empty()) return {"success", "failure"};
    return out;
  }

  // A game's items: the properties [0, properties.size()), then the constraints.
  std::size_t items() const { return reads.size(); }
  bool is_constraint(std::size_t item) const { return item >= properties.size(); }
  const Constraint& constraint(std::size_t item) const {
    return constraints[item - properties.size()];
  }
  bool is_guarantee(std::size_t item) const {
    return !is_constraint(item) && !properties[item].assumption;
  }
  std::string id(std::size_t item) const {
    return is_constraint(item) ? constraint(item).assumption->name
                               : properties[item].requirement->id;
  }
};

// The cells of every signal `properties` read: values each atom tells apart, one per cell.
// "" when every signal has its cells, else why one cannot be cut.
std::string cut_cells(Table& t, const std::vector<std::size_t>& properties,
                      std::vector<GameSignal*>& out) {
  std::set<std::string> names;
  for (std::size_t p : properties) names.insert(t.reads[p].begin(), t.reads[p].end());
  std::set<std::string, std::less<>> numeric, integers;
  prove::Cuts::EnumValues enums;
  for (const auto& n : names) {
    const fretish::Variable& d = t.signals.at(n).declaration;
    if (d.type == fretish::VarType::integer || d.type == fretish::VarType::real) numeric.insert(n);
    if (d.type == fretish::VarType::integer) integers.insert(n);
    if (d.type == fretish::VarType::enumeration)
      enums[n].insert(d.enum_values.begin(), d.enum_values.end());
  }
  prove::Cuts cuts(numeric, {}, integers, enums);
  for (std::size_t p : properties) {
    if (t.is_constraint(p)) {
      cuts.add(*t.constraint(p).assumption->expr, t.id(p), true);
      continue;
    }
    for (const auto& atom : t.properties[p].atom_exprs) cuts.add(*atom, t.id(p));
  }
  out.clear();
  for (const auto& n : names) {
    GameSignal& s = t.signals.at(n);
    if (s.derived) {
      out.push_back(&s);
      continue;
    }
    std::vector<runtime::ScriptValue> values;
    switch (s.declaration.type) {
      case fretish::VarType::boolean:
        values = {runtime::ScriptValue::of_bool(false), runtime::ScriptValue::of_bool(true)};
        break;
      case fretish::VarType::enumeration:
        if (s.choice_of_node) {  // no atom names its values: each is its own
          for (const auto& e : s.declaration.enum_values)
            values.push_back(runtime::ScriptValue::of_string(e));
        } else {
          values = prove::enum_cell_values(s.declaration, cuts.named(n));
        }
        break;
      default:
        if (const std::string why = cuts.uncut(n); !why.empty()) return why;
        if (!cuts.mixed(n).empty())
          return "'" + n + "' is compared with another variable: its cells are not fixed";
        values = prove::cell_values(s.declaration, cuts.breaks(n));
        break;
    }
    s.values.clear();
    s.shown.values.clear();
    for (const auto& v : values) {
      s.values.push_back(value_of(v, t.symbols));
      s.shown.values.push_back(runtime::to_value(v));
    }
    if (s.values.empty()) return "'" + n + "' has no value in its declared range";
    out.push_back(&s);
  }
  return "";
}

// An answer of the tree: the states it leads to, however the world ends the nodes it lets end.
using Answer = std::vector<std::int32_t>;

// The safety game of some properties (guarantees and assumptions) over the signals they read.
class Game {
 public:
  Game(Table& t, std::vector<std::size_t> properties, const Options& options)
      : t_(t), properties_(std::move(properties)), options_(options) {}

  // Builds and solves it; false with `reason` when it is not decided.
  bool solve(std::string& reason) {
    for (std::size_t p : properties_) {
      if (t_.is_constraint(p)) {
        if (!t_.constraint(p).expr) {
          reason = t_.id(p) + ": " + t_.constraint(p).error;
          return false;
        }
        continue;
      }
      const prove::Property& prop = t_.properties[p];
      if (!prop.layout) {
        reason = t_.unreadable(p, prop.unsupported);
        return false;
      }
      if (!monitor::verdict_is_final_once_violated(prop.shape)) {
        reason = prop.requirement->id +
                 ": its timing in its scope is not a safety requirement (a violation may "
                 "still be repaired later), and realizability is decided for safety ones only";
        return false;
      }
    }
    std::vector<GameSignal*> all;
    if (std::string why = cut_cells(t_, properties_, all); !why.empty()) {
      reason = why;
      return false;
    }
    for (GameSignal* s : all)
      (s->derived ? derived_ : s->shown.role == Role::input ? inputs_ : outputs_).push_back(s);
    // An assumption the tree's own outputs could break would let it "win" by breaking it.
    for (std::size_t p : properties_) {
      if (t_.is_guarantee(p)) continue;
      for (const auto& name : t_.reads[p])
        if (t_.signals.at(name).shown.role == Role::output) {
          reason = t_.id(p) + " reads '" + name +
                   "', which the tree decides: realizability is decided for assumptions over "
                   "the environment's inputs only";
          return false;
        }
    }
    const double moves = count(inputs_) * count(outputs_);
    if (moves > static_cast<double>(options_.max_moves)) {
      reason = "its inputs and outputs have " + number_text(moves) +
               " combinations a tick, more than the " + std::to_string(options_.max_moves) +
               " explored";
      return false;
    }
    find_ties();
    input_valuations_ = valuations(inputs_);
    output_valuations_ = valuations(outputs_);
    frame_.assign(t_.variables.size(), Val{});
    std::vector<std::uint64_t> initial;
    for (std::size_t p : properties_) {
      if (t_.is_constraint(p)) continue;
      const auto init = t_.properties[p].layout->initial();
      initial.insert(initial.end(), init.begin(), init.end());
    }
    index_of(initial);
    for (std::size_t s = 0; s < states_.size(); ++s) {
      if (states_.size() > options_.max_states || transitions_ > options_.max_transitions) {
        reason = "more than " + std::to_string(options_.max_states) + " monitor states or " +
                 std::to_string(options_.max_transitions) + " moves";
        return false;
      }
      expand(s);
    }
    // The greatest fixpoint: a state is lost when some input leaves the tree no answer that
    // keeps every guarantee and leads, however the world ends the nodes, to states not lost.
    alive_.assign(states_.size(), 1);
    const auto holds = [&](const Answer& answer) {
      return std::all_of(answer.begin(), answer.end(),
                         [&](std::int32_t n) { return alive_[static_cast<std::size_t>(n)] != 0; });
    };
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t s = 0; s < states_.size(); ++s) {
        if (!alive_[s]) continue;
        for (const auto& answers : moves_[s]) {
          const bool answered = std::any_of(answers.begin(), answers.end(), holds);
          if (!answered) {
            alive_[s] = 0;
            changed = true;
            break;
          }
        }
      }
    }
    return true;
  }

  bool realizable() const { return alive_[0] != 0; }
  std::uint64_t states() const { return states_.size(); }

  // A fixed input sequence after which no answer of the tree keeps every guarantee, shortest
  // first; empty when none within `depth` ticks.
  std::vector<Choice> defeating_inputs(std::uint64_t depth) const {
    std::vector<Belief> beliefs{{{0}, 0, 0, 0}};
    std::set<std::vector<std::int32_t>> seen{{0}};
    constexpr std::size_t kMaxBeliefs = 20'000;
    for (std::size_t b = 0; b < beliefs.size() && beliefs.size() < kMaxBeliefs; ++b) {
      if (beliefs[b].tick >= depth) continue;
      for (std::size_t i = 0; i < input_valuations_.size(); ++i) {
        std::set<std::int32_t> next;
        bool escapes = false;
        for (std::int32_t s : beliefs[b].states)
          for (const Answer& answer : moves_[static_cast<std::size_t>(s)][i]) {
            escapes = escapes || answer.empty();
            next.insert(answer.begin(), answer.end());
          }
        if (escapes) continue;
        if (next.empty()) return trace(beliefs, b, i);
        std::vector<std::int32_t> key(next.begin(), next.end());
        if (!seen.insert(key).second) continue;
        beliefs.push_back({std::move(key), b, i, beliefs[b].tick + 1});
      }
    }
    return {};
  }

 private:
  static double count(const std::vector<GameSignal*>& signals) {
    double n = 1;
    for (const GameSignal* s : signals) n *= static_cast<double>(s->values.size());
    return n;
  }

  // Every combination of the signals' values, as indices; the first signal counts fastest.
  static std::vector<std::vector<std::uint32_t>> valuations(const std::vector<GameSignal*>& of) {
    std::vector<std::vector<std::uint32_t>> out;
    std::vector<std::uint32_t> digits(of.size(), 0);
    while (true) {
      out.push_back(digits);
      std::size_t k = 0;
      while (k < of.size() && ++digits[k] == of[k]->values.size()) digits[k++] = 0;
      if (k == of.size()) return out;
    }
  }

  // Each derived status from the tree's and the world's choices for its node.
  void derive() {
    for (const GameSignal* s : derived_) {
      const auto choice = [&](const std::string& name) -> const std::string& {
        const Val& v = frame_[static_cast<std::size_t>(t_.signals.at(name).slot)];
        return t_.symbols.name(v.symbol);
      };
      const std::string& state = choice(state_name(s->label));
      const bool holds = s->status == "running"
                             ? state == "running"
                             : state == "ended" && choice(result_name(s->label)) == s->status;
      frame_[static_cast<std::size_t>(s->slot)] = Val::of_bool(holds);
    }
  }

  void put(const std::vector<GameSignal*>& signals, const std::vector<std::uint32_t>& digits) {
    for (std::size_t k = 0; k < signals.size(); ++k)
      frame_[static_cast<std::size_t>(signals[k]->slot)] = signals[k]->values[digits[k]];
  }

  bool is_true(const GameSignal* s) const {
    const Val& v = frame_[static_cast<std::size_t>(s->slot)];
    return v.kind == Val::Kind::boolean && v.truth();
  }

  // A node has one status a tick, and a node selects only in a tick it is ticked.
  bool consistent() const {
    for (const auto& statuses : one_status_)
      if (std::count_if(statuses.begin(), statuses.end(),
                        [&](const GameSignal* s) { return is_true(s); }) > 1)
        return false;
    for (const auto& [selected, mode] : selects_) {
      const Val& v = frame_[static_cast<std::size_t>(selected->slot)];
      const bool none = v.kind == Val::Kind::symbol && t_.symbols.name(v.symbol) == "none";
      if (!none && !is_true(mode)) return false;
    }
    return true;
  }

  // The ties consistent() and inputs_agree() check, among this game's signals.
  void find_ties() {
    std::map<std::string, std::vector<const GameSignal*>> statuses;
    std::map<std::string, const GameSignal*> mode, selected, input;
    for (const auto* list : {&inputs_, &outputs_})
      for (const GameSignal* s : *list) {
        if (s->status == "mode")
          mode[s->label] = s;
        else if (s->status == "selected")
          selected[s->label] = s;
        else if (!s->status.empty())
          statuses[s->label].push_back(s);
        if (list == &inputs_) input[s->shown.name] = s;
      }
    for (auto& [label, list] : statuses)
      if (list.size() > 1) one_status_.push_back(std::move(list));
    for (const auto& [label, s] : selected)
      if (mode.count(label) != 0) selects_.emplace_back(s, mode.at(label));
    for (const GameSignal* s : inputs_)
      if (s->choice_of_node && input.count(s->label) != 0)
        agrees_.emplace_back(s, input.at(s->label));
  }

  std::int32_t index_of(const std::vector<std::uint64_t>& state) {
    const auto [it, added] = index_.emplace(state, static_cast<std::int32_t>(states_.size()));
    if (added) states_.push_back(state);
    return it->second;
  }

  // This tick's verdict on the frame, stepping the monitors from `state` into `next`.
  enum class Tick { assumption_broken, guarantee_broken, kept };
  Tick step(const std::vector<std::uint64_t>& state, std::vector<std::uint64_t>& next) {
    next = state;
    bool assumptions_hold = true, guarantees_hold = true;
    std::size_t offset = 0;
    for (std::size_t p : properties_) {
      if (t_.is_constraint(p)) {
        std::string error;
        if (!t_.constraint(p).expr->evaluate_bool(frame_, error)) assumptions_hold = false;
        if (!error.empty()) throw std::runtime_error(t_.id(p) + ": " + error);
        continue;
      }
      const prove::Property& prop = t_.properties[p];
      const std::size_t words = prop.layout->words();
      words_.assign(next.begin() + static_cast<long>(offset),
                    next.begin() + static_cast<long>(offset + words));
      prop.read_atoms(frame_, bits_, 0);
      const bool now = prop.layout->step(bits_, words_, scratch_);
      std::copy(words_.begin(), words_.end(), next.begin() + static_cast<long>(offset));
      offset += words;
      if (!now) (prop.assumption ? assumptions_hold : guarantees_hold) = false;
    }
    return !assumptions_hold ? Tick::assumption_broken
           : guarantees_hold ? Tick::kept
                             : Tick::guarantee_broken;
  }

  void expand(std::size_t s) {
    std::vector<std::vector<Answer>> per_input;
    std::vector<std::uint64_t> next;
    for (const auto& input : input_valuations_) {
      std::vector<Answer> answers;
      put(inputs_, input);
      if (!inputs_agree()) {  // no world gives it: as good as an assumption it breaks
        per_input.push_back({Answer{}});
        continue;
      }
      for (const auto& output : output_valuations_) {
        put(outputs_, output);
        derive();
        if (!consistent()) continue;
        const Tick verdict = step(states_[s], next);
        if (verdict == Tick::assumption_broken) answers.push_back({});
        if (verdict == Tick::kept) answers.push_back({index_of(next)});
      }
      std::sort(answers.begin(), answers.end());
      answers.erase(std::unique(answers.begin(), answers.end()), answers.end());
      transitions_ += answers.size();
      per_input.push_back(std::move(answers));
    }
    if (moves_.size() <= s) moves_.resize(s + 1);
    moves_[s] = std::move(per_input);
  }

  // What the world gives agrees with itself: a condition the requirements read by its name
  // (its value) ends as that value says.
  bool inputs_agree() const {
    for (const auto& [result, value] : agrees_) {
      const Val& v = frame_[static_cast<std::size_t>(value->slot)];
      const Val& r = frame_[static_cast<std::size_t>(result->slot)];
      if (v.kind == Val::Kind::boolean && (t_.symbols.name(r.symbol) == "success") != v.truth())
        return false;
    }
    return true;
  }

  // The states the tree may be in after some inputs, whatever it answered.
  struct Belief {
    std::vector<std::int32_t> states;
    std::size_t parent = 0;  // the belief before the last input
    std::size_t input = 0;   // that input's valuation
    std::uint64_t tick = 0;
  };

  // The inputs that led to `beliefs[b]`, then `input`, tick by tick.
  std::vector<Choice> trace(const std::vector<Belief>& beliefs, std::size_t b,
                            std::size_t input) const {
    std::vector<std::size_t> inputs{input};
    for (; b != 0; b = beliefs[b].parent) inputs.push_back(beliefs[b].input);
    std::reverse(inputs.begin(), inputs.end());
    std::vector<Choice> out;
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      Choice c;
      c.tick = k + 1;
      const auto& digits = input_valuations_[inputs[k]];
      for (std::size_t i = 0; i < inputs_.size(); ++i)
        c.inputs.emplace_back(inputs_[i]->shown.name, inputs_[i]->shown.values[digits[i]]);
      out.push_back(std::move(c));
    }
    return out;
  }

  Table& t_;
  std::vector<std::size_t> properties_;
  const Options& options_;
  std::vector<GameSignal*> inputs_, outputs_, derived_;
  std::vector<std::vector<std::uint32_t>> input_valuations_, output_valuations_;
  std::uint64_t transitions_ = 0;
  std::vector<std::vector<const GameSignal*>> one_status_;                // a node's statuses
  std::vector<std::pair<const GameSignal*, const GameSignal*>> selects_;  // .selected, mode
  std::vector<std::pair<const GameSignal*, const GameSignal*>> agrees_;   // result, value
  std::vector<Val> frame_;
  std::vector<std::uint64_t> words_;
  std::vector<char> scratch_;
  bool bits_[prove::Property::kMaxAtoms] = {};
  struct Hash {
    std::size_t operator()(const std::vector<std::uint64_t>& v) const {
      std::size_t h = v.size();
      for (std::uint64_t w : v) h = h * 0x9e3779b97f4a7c15ull ^ w;
      return h;
    }
  };
  std::unordered_map<std::vector<std::uint64_t>, std::int32_t, Hash> index_;
  std::vector<std::vector<std::uint64_t>> states_;
  // Per state, per input valuation, per answer of the tree that keeps the guarantees however
  // the world ends its nodes: the states it may lead to (none: every way breaks an assumption,
  // so the tree is held to nothing).
  std::vector<std::vector<std::vector<Answer>>> moves_;
  std::vector<char> alive_;
};

// Decides one set of properties; nullopt with `reason` when it is not decided.
std::optional<bool> decide(Table& t, const std::vector<std::size_t>& properties,
                           const Options& options, std::string& reason,
                           std::uint64_t* states = nullptr, std::vector<Choice>* defeat = nullptr) {
  Game game(t, properties, options);
  try {
    if (!game.solve(reason)) return std::nullopt;
  } catch (const std::exception& e) {
    reason = e.what();
    return std::nullopt;
  }
  if (states != nullptr) *states = game.states();
  if (defeat != nullptr && !game.realizable())
    *defeat = game.defeating_inputs(options.max_defeat_depth);
  return game.realizable();
}

// Components: guarantees that share an output, and the assumptions (and the domain's
// `assume`s) that read a signal of one, directly or through another assumption. Guarantees
// that share only inputs are apart: each input is the environment's to choose anyway.
std::vector<std::vector<std::size_t>> components_of(const Table& t) {
  const std::size_t n = t.items();
  std::vector<std::size_t> parent(n);
  for (std::size_t i = 0; i < n; ++i) parent[i] = i;
  const auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto join = [&](std::size_t a, std::size_t b) { parent[find(a)] = find(b); };
  // The statuses of one node are tied (one status a tick; it selects only when ticked): a
  // node's signals share one key.
  const auto key = [&](const std::string& name) {
    const GameSignal& s = t.signals.at(name);
    return s.label.empty() ? name : "node " + s.label;
  };
  std::map<std::string, std::size_t> output_owner, assumed;  // a key: an item that reads it
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& name : t.reads[i]) {
      if (!t.is_guarantee(i)) {
        const auto [it, added] = assumed.emplace(key(name), i);
        if (!added) join(i, it->second);
      } else if (t.signals.at(name).shown.role == Role::output) {
        const auto [it, added] = output_owner.emplace(key(name), i);
        if (!added) join(i, it->second);
      }
    }
  for (std::size_t i = 0; i < n; ++i)
    if (t.is_guarantee(i))
      for (const auto& name : t.reads[i])
        if (auto it = assumed.find(key(name)); it != assumed.end()) join(i, it->second);
  std::map<std::size_t, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < n; ++i) groups[find(i)].push_back(i);
  std::vector<std::vector<std::size_t>> out;
  for (auto& [root, members] : groups)
    // An assumption no guarantee depends on constrains nothing that is asked.
    if (std::any_of(members.begin(), members.end(),
                    [&](std::size_t i) { return t.is_guarantee(i); }))
      out.push_back(std::move(members));
  std::sort(out.begin(), out.end());
  return out;
}

// Every minimal set of `guarantees` that no tree meets with `assumptions`, by size (or one,
// found by deletion, when there are too many guarantees to try every set).
void find_conflicts(Table& t, const std::vector<std::size_t>& guarantees,
                    const std::vector<std::size_t>& assumptions, const Options& options,
                    Component& c) {
  const auto unrealizable = [&](const std::vector<std::size_t>& subset) -> std::optional<bool> {
    std::vector<std::size_t> properties = subset;
    properties.insert(properties.end(), assumptions.begin(), assumptions.end());
    std::string reason;
    const std::optional<bool> r = decide(t, properties, options, reason);
    if (!r) return std::nullopt;
    return !*r;
  };
  const auto ids = [&](const std::vector<std::size_t>& subset) {
    std::vector<std::string> out;
    for (std::size_t p : subset) out.push_back(t.id(p));
    return out;
  };
  const std::size_t n = guarantees.size();
  constexpr std::size_t kMostSubsetBits = 20;  // 2^20 sets at the most
  if (n > std::min(options.max_conflict_search, kMostSubsetBits)) {
    std::vector<std::size_t> core = guarantees;
    for (std::size_t k = 0; k < core.size();) {
      std::vector<std::size_t> without = core;
      without.erase(without.begin() + static_cast<long>(k));
      if (unrealizable(without).value_or(false))
        core = std::move(without);
      else
        ++k;
    }
    c.conflicts.push_back(ids(core));
    c.conflicts_complete = false;
    return;
  }
  std::vector<std::uint32_t> found;  // as bit masks over `guarantees`
  for (std::size_t size = 1; size <= n; ++size)
    for (std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      if (static_cast<std::size_t>(__builtin_popcount(mask)) != size) continue;
      if (std::any_of(found.begin(), found.end(), [&](std::uint32_t f) { return (mask & f) == f; }))
        continue;
      std::vector<std::size_t> subset;
      for (std::size_t k = 0; k < n; ++k)
        if (mask & (1u << k)) subset.push_back(guarantees[k]);
      const std::optional<bool> r = unrealizable(subset);
      if (!r) c.conflicts_complete = false;
      if (r.value_or(false)) {
        found.push_back(mask);
        c.conflicts.push_back(ids(subset));
      }
    }
}

}  // namespace

Result check_realizability(const load::Mission& mission, const prove::WorldModel& world,
                           const Options& options) {
  Table t(mission, world);
  Result result;
  std::set<std::string> read;  // the signals some requirement or assumption reads
  for (const auto& r : t.reads) read.insert(r.begin(), r.end());
  for (const auto& [name, s] : t.signals)
    if (read.count(name) != 0) result.signals.push_back(s.shown);
  std::stable_sort(result.signals.begin(), result.signals.end(),
                   [](const Signal& a, const Signal& b) { return a.role < b.role; });
  bool any_false = false, any_unknown = false;
  std::map<std::string, std::vector<Value>> shown_values;
  for (const auto& members : components_of(t)) {
    Component c;
    std::vector<std::size_t> guarantees, assumptions;
    for (std::size_t p : members) (t.is_guarantee(p) ? guarantees : assumptions).push_back(p);
    for (std::size_t p : guarantees) c.requirements.push_back(t.id(p));
    for (std::size_t p : assumptions) c.requirements.push_back(t.id(p));
    c.realizable = decide(t, members, options, c.reason, &c.states, &c.defeating_inputs);
    // The values shown are the cells this component's own game cut.
    for (std::size_t p : members)
      for (const auto& name : t.reads[p]) shown_values[name] = t.signals.at(name).shown.values;
    if (c.realizable == false) find_conflicts(t, guarantees, assumptions, options, c);
    any_false = any_false || c.realizable == false;
    any_unknown = any_unknown || !c.realizable;
    result.components.push_back(std::move(c));
  }
  for (Signal& s : result.signals) s.values = shown_values[s.name];
  if (result.components.empty())
    result.notes.push_back("the mission states no guarantee: any tree meets it");
  else if (!world.actions.empty())
    result.notes.push_back(
        "how world.json lets an action end (its results) bounds the world's choices; how long "
        "it runs does not: the tree may let it end in any tick");
  result.realizable = any_false     ? std::optional<bool>(false)
                      : any_unknown ? std::nullopt
                                    : std::optional<bool>(true);
  return result;
}

}  // namespace uabt::realize
