#include "prove/model.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <iterator>
#include <map>
#include <optional>

#include "bt/node_kinds.hpp"
#include "bt/script/ast.hpp"
#include "fretish/expr.hpp"
#include "monitor/monitor.hpp"
#include "monitor/property_set.hpp"
#include "prove/cells.hpp"
#include "prove/environment.hpp"
#include "prove/property_formula.hpp"
#include "prove/prove.hpp"
#include "runtime/observed_nodes.hpp"

namespace uabt::prove {

using runtime::ScriptValue;

namespace {

// The leaves of the tree as the engine binds them, learnt by building it once.
struct ProbeWorld : runtime::World {
  struct Output {
    std::string entry, port, type;  // type: the port's C++ type in nodes.xml
    bool root = true;               // the entry lives on the root blackboard
    std::string where;              // "file:line:col: Kind"
  };
  struct Seen {
    std::string kind, family, key;
    std::vector<Output> outputs;
  };
  std::vector<Seen> leaves;
  std::vector<bt::NodeModel> models;
  std::uint32_t bind_leaf(const runtime::LeafBinding& b) override {
    Seen s{b.kind, b.declared_family, leaf_state_key(b.kind, b.ports), {}};
    const bt::NodeModel* model = nullptr;
    for (const auto& m : models)
      if (m.id == b.kind) model = &m;
    if (s.family.empty() && model) s.family = model->family;
    for (const auto& p : b.ports) {
      if (!p.writes_entry()) continue;
      Output out{b.blackboard.key(p.slot), p.name, "",
                 b.blackboard.owner(p.slot) == runtime::Blackboard::kRootScope,
                 place_text(b.info.location) + ": " + b.kind};
      if (model)
        for (const auto& port : model->ports)
          if (port.name == p.name) out.type = port.type;
      s.outputs.push_back(std::move(out));
    }
    leaves.push_back(std::move(s));
    return 0;
  }
  runtime::NodeStatus tick_leaf(const runtime::LeafContext&) override {
    return runtime::NodeStatus::failure;
  }
  void halt_leaf(const runtime::LeafContext&) override {}
};

// A variable with more values than this is cut into cells or left to the symbolic engine.
constexpr long long kMaxValues = 4096;

std::vector<ScriptValue> values_of(const fretish::Variable& v, std::string& why) {
  std::vector<ScriptValue> out;
  switch (v.type) {
    case fretish::VarType::boolean:
      return {ScriptValue::of_bool(false), ScriptValue::of_bool(true)};
    case fretish::VarType::enumeration:
      for (const auto& e : v.enum_values) out.push_back(ScriptValue::of_string(e));
      return out;
    case fretish::VarType::integer: {
      if (v.lower.empty() || v.upper.empty()) {
        why = "integer '" + v.name + "' has no bounds";
        return out;
      }
      const auto lo = verify::detail::Fraction::parse(v.lower);
      const auto hi = verify::detail::Fraction::parse(v.upper);
      if (!lo || !hi || lo->denominator() != 1 || hi->denominator() != 1 ||
          *hi - *lo > verify::detail::Fraction(kMaxValues)) {
        why = "integer '" + v.name + "' ranges over more than " + std::to_string(kMaxValues) +
              " values";
        return out;
      }
      const auto first = static_cast<long long>(lo->numerator());
      const auto last = static_cast<long long>(hi->numerator());
      for (long long i = first; i <= last; ++i) out.push_back(ScriptValue::of_int(i));
      return out;
    }
    case fretish::VarType::real:
      why = "real '" + v.name + "' has no finite set of values";
      return out;
  }
  return out;
}

// The constant a top-level conjunct `name = c` of the initial condition gives a variable.
std::optional<ScriptValue> fixed_number(const fretish::Expr& e, const fretish::Variable& v) {
  using K = fretish::ExprKind;
  if (e.kind == K::logical_and) {
    for (const auto& a : e.args)
      if (auto x = fixed_number(*a, v)) return x;
    return std::nullopt;
  }
  if (e.kind != K::eq || e.args.size() != 2) return std::nullopt;
  const fretish::Expr* id = e.args[0].get();
  const fretish::Expr* number = e.args[1].get();
  if (id->kind != K::identifier) std::swap(id, number);
  if (id->kind != K::identifier || id->text != v.name || number->kind != K::number)
    return std::nullopt;
  const auto f = verify::detail::Fraction::parse(number->text);
  if (!f) return std::nullopt;
  if (v.type == fretish::VarType::integer) {
    if (f->denominator() != 1) return std::nullopt;
    return ScriptValue::of_int(static_cast<std::int64_t>(f->numerator()));
  }
  return ScriptValue::of_real(f->to_double());
}

}  // namespace

bool has_guarantees(const load::Mission& mission) {
  for (const auto& r : mission.properties)
    if (!fretish::is_assumption(r)) return true;
  return false;
}

Model::Model(const load::Mission& m, const bt::Document& compiled, const WorldModel& w)
    : mission(m), doc(compiled), world(w) {
  std::vector<bt::NodeModel> models = doc.node_models;
  if (mission.nodes) models.insert(models.end(), mission.nodes->begin(), mission.nodes->end());

  // 1. The state: domain variables, then conditions the domain does not declare (booleans).
  ProbeWorld probe;
  probe.models = models;
  try {
    runtime::Engine::build(doc, probe);
  } catch (const std::exception& e) {
    throw ProveError(std::string("the compiled tree does not load: ") + e.what());
  }
  std::map<std::string, std::string, std::less<>> unenumerable;  // variable: why
  for (const auto& v : mission.domain.variables) {
    StateVar s;
    s.name = v.name;
    std::string why;
    s.values = values_of(v, why);
    if (!why.empty()) unenumerable[v.name] = why;
    if (s.values.empty()) s.values.push_back(ScriptValue{});  // cut into cells or refused below
    vars.push_back(std::move(s));
    state_names.insert(v.name);
  }
  for (const auto& leaf : probe.leaves) {
    const bool condition =
        world.find(leaf.key, leaf.kind) == nullptr &&
        (leaf.family == "Condition" || (leaf.family.empty() && (state_names.contains(leaf.key) ||
                                                                state_names.contains(leaf.kind))));
    if (!condition || state_names.contains(leaf.key) || state_names.contains(leaf.kind)) continue;
    StateVar s;
    s.name = leaf.key;
    s.values = {ScriptValue::of_bool(false), ScriptValue::of_bool(true)};
    vars.push_back(std::move(s));
    state_names.insert(leaf.key);
  }

  // The entries output ports write: a domain variable, or an entry of the tree's own with the
  // port's type, empty until its first write.
  std::map<std::string, std::vector<const ProbeWorld::Output*>, std::less<>> written_by;
  for (const auto& leaf : probe.leaves)
    for (const auto& out : leaf.outputs) {
      if (!out.root)
        throw ProveError(out.where + ": output port '" + out.port + "' writes {" + out.entry +
                         "}, an entry of a SubTree's own blackboard: prove models the root "
                         "blackboard's entries (remap the port, or use _autoremap)");
      written_by[out.entry].push_back(&out);
    }
  for (const auto& [entry, writers] : written_by) {
    // An init-capture: clang before 16 cannot capture a structured binding.
    auto it = std::find_if(vars.begin(), vars.end(),
                           [&name = entry](const StateVar& v) { return v.name == name; });
    if (it == vars.end()) {
      fretish::Variable decl;
      decl.name = entry;
      const std::string& type = writers.front()->type;
      if (type == "bool") {
        decl.type = fretish::VarType::boolean;
      } else if (type == "double" || type == "float") {
        decl.type = fretish::VarType::real;
      } else if (type.find("int") != std::string::npos || type.find("long") != std::string::npos ||
                 type.find("short") != std::string::npos || type == "unsigned" ||
                 type.find("size_t") != std::string::npos) {
        decl.type = fretish::VarType::integer;
      } else {
        decl.type = fretish::VarType::enumeration;  // strings: the values world.json gives
        for (const auto& [name, c] : world.actions)
          for (const auto& [port, value] : c.outputs)
            for (const auto* w : writers)
              if (port == w->port && value.is_string() &&
                  std::find(decl.enum_values.begin(), decl.enum_values.end(), value.text) ==
                      decl.enum_values.end())
                decl.enum_values.push_back(value.text);
        if (decl.enum_values.empty())
          unenumerable[entry] = "the values of {" + entry + "} (output port '" +
                                writers.front()->port + "' of type '" + type +
                                "'): declare the entry in domain.fret, or give the value in "
                                "world.json's outputs";
      }
      port_entries[entry] = decl;
      StateVar s;
      s.name = entry;
      std::string why;
      s.values = values_of(decl, why);
      if (!why.empty() && !unenumerable.contains(entry)) unenumerable[entry] = why;
      // Until it is cut into cells (or when nothing reads its value), one value of its type.
      if (s.values.empty())
        s.values.push_back(decl.type == fretish::VarType::integer ? ScriptValue::of_int(0)
                           : decl.type == fretish::VarType::real  ? ScriptValue::of_real(0)
                                                                  : ScriptValue::of_string(""));
      s.unset_first = true;
      vars.push_back(std::move(s));
      it = vars.end() - 1;
    }
    it->port_written = true;
    it->env = false;
  }

  // 2. What the actions write is the mission's.
  for (const auto& [name, c] : world.actions)
    for (const std::string* code : {&c.on_success, &c.on_failure})
      for (const std::string& written : assigned_names(*code)) {
        auto it = std::find_if(vars.begin(), vars.end(),
                               [&](const StateVar& v) { return v.name == written; });
        if (it == vars.end())
          throw ProveError(place_text(c.location) + ": error: action '" + name + "' writes '" +
                           written + "', which is neither declared in the domain nor a condition");
        it->env = false;
        it->script_written = true;
      }
  // So is what the tree's scripts assign: the runtime keeps it from one tick to the next, the
  // environment does not choose it again.
  std::function<void(const bt::Node&)> assigned_by_tree = [&](const bt::Node& n) {
    for (const auto& [attr, value] : n.attributes)
      if (attr == "code" || (!attr.empty() && attr[0] == '_'))
        for (const std::string& written : assigned_names(value))
          for (StateVar& v : vars)
            if (v.name == written) {
              v.env = false;
              v.script_written = true;
            }
    for (const auto& c : n.children) assigned_by_tree(c);
  };
  for (const auto& t : doc.trees) assigned_by_tree(t.root);

  // 3. The engine on the choice world, and what properties observe.
  choice = std::make_unique<ChoiceWorld>(world, models, state_names, &mission.domain);
  try {
    engine = std::make_unique<runtime::Engine>(runtime::Engine::build(doc, *choice));
  } catch (const std::exception& e) {
    throw ProveError(std::string("the compiled tree cannot be explored: ") + e.what());
  }
  observables =
      std::make_unique<runtime::TickObservation>(*engine, mission, state_names, variables, symbols);
  engine->add_observer(observables.get());
  for (StateVar& v : vars) {
    v.slot = engine->blackboard().resolve(runtime::Blackboard::kRootScope, v.name);
    v.frame = variables.id(v.name);
  }
  const monitor::Resolver resolve = [this](const std::string& name) {
    return observables->resolve(name);
  };

  // 4. Properties, assumptions, the initial condition; what they read is relevant.
  std::set<std::string, std::less<>> read;
  auto reads = [&](const fretish::ExprPtr& e) {
    if (e)
      for (const auto& id : fretish::identifiers_of(*e)) read.insert(id);
  };
  for (const fretish::Requirement& property : mission.properties) {
    Property p = make_property(property, resolve);
    if (p.layout) {
      p.offset = monitor_words;
      monitor_words += p.layout->words();
      for (const auto& part : p.exprs) reads(part);
    }
    properties.push_back(std::move(p));
  }
  auto state_expression = [&](const fretish::ExprPtr& e, const std::string& what) {
    std::string error;
    auto compiled_e = monitor::CompiledExpression::compile(*e, resolve, error);
    if (!compiled_e) throw ProveError(what + ": " + error);
    reads(e);
    return std::make_shared<monitor::CompiledExpression>(std::move(*compiled_e));
  };
  for (const auto& a : mission.domain.assumptions)
    if (a.expr) assumptions.push_back(state_expression(a.expr, "assumption " + a.name));
  if (world.initial) initial = state_expression(world.initial, world.file + ": initial");

  // Names the tree itself reads: conditions and scripts.
  tree_scripts.clear();
  port_reads.clear();
  for (const auto& leaf : choice->leaves()) {
    if (leaf.condition) read.insert(leaf.label);
    for (const auto* p : {&leaf.on_success, &leaf.on_failure})
      if (*p)
        for (const auto& n : (*p)->names()) read.insert(n);
  }
  disjunctions.clear();
  bool in_selection_tree = false;
  std::function<void(const bt::Node&)> scan = [&](const bt::Node& n) {
    const std::size_t first_script = tree_scripts.size();
    for (const auto& [attr, value] : n.attributes) {
      if (attr == "code" || (!attr.empty() && attr[0] == '_')) {
        try {
          auto program = runtime::script::Program::parse(value);
          for (const auto& name : program.names()) read.insert(name);
          tree_scripts.push_back({std::move(program), "the " + attr + " of " + n.tag + " at " +
                                                          place_text(doc.file, n.line, n.column)});
        } catch (const std::exception&) {
        }
      }
      const auto open = value.find('{');
      // A robot leaf's port only needs its entry to be there (ChoiceWorld reads no value).
      const bool robot_leaf =
          n.children.empty() && bt::find_builtin(n.kind()) == nullptr && n.tag != "Adaptable";
      if (open != std::string::npos && value.back() == '}' && !robot_leaf) {
        read.insert(value.substr(open + 1, value.size() - open - 2));
        port_reads.push_back(value.substr(open + 1, value.size() - open - 2));
      }
    }
    for (const auto& c : n.children) scan(c);
    if (in_selection_tree && tree_scripts.size() - first_script == n.children.size() &&
        fallback_of_conditions(n))
      disjunctions.push_back({first_script, tree_scripts.size()});
  };
  for (const auto& t : doc.trees) {
    in_selection_tree = runtime::generated_selection_tree(mission, t.id);
    scan(t.root);
  }

  for (StateVar& v : vars) v.relevant = read.contains(v.name);
  choose_values(unenumerable);
  mark_read_once();
  for (StateVar& v : vars) {
    if (v.port_written) choice->output_values[v.slot] = v.values;
    if (!v.unset_first) engine->blackboard().value(v.slot) = v.values.front();
  }
  environment = std::make_unique<Environment>(*this);
  fresh = runtime::EngineState::save(*engine);
}

Model::~Model() = default;

Property make_property(const fretish::Requirement& property, const monitor::Resolver& resolve) {
  const fretish::Requirement* r = &property;
  Property p;
  p.requirement = r;
  p.assumption = fretish::is_assumption(property);
  const monitor::Classified c = monitor::classify(*r);
  fretish::ExprPtr mode;
  if (r->scope)
    mode = r->scope->condition ? r->scope->condition : fretish::make_identifier(r->scope->mode);
  const fretish::ExprPtr parts[] = {mode, r->folded_condition(), r->response,
                                    r->timing.stop_condition, r->judged};
  if (!c.shape) p.unsupported = c.reason;
  p.exprs.assign(std::begin(parts), std::end(parts));
  // Each part compiles as the monitor compiles it (its errors are the monitor's).
  for (std::size_t k = 0; k < std::size(parts) && p.unsupported.empty(); ++k) {
    if (!parts[k]) continue;
    std::string error;
    if (!monitor::CompiledExpression::compile(
            *parts[k], resolve, error, k == 0 ? monitor::Field::mode : monitor::Field::other))
      p.unsupported = error;
  }
  if (p.unsupported.empty()) {
    PropertyFormula pf = build_property_formula(
        *c.shape, {parts[0], parts[1], parts[2], parts[3], parts[4]}, resolve);
    p.unsupported = pf.unsupported;
    if (p.unsupported.empty() && pf.atoms.size() > Property::kMaxAtoms)
      p.unsupported = "its parts read " + std::to_string(pf.atoms.size()) +
                      " separate conditions of a tick; prove's monitors read at most " +
                      std::to_string(Property::kMaxAtoms);
    for (const auto& atom : pf.atoms) {
      if (!p.unsupported.empty()) break;
      std::string error;
      auto compiled = monitor::CompiledExpression::compile(*atom, resolve, error);
      if (!compiled) {
        p.unsupported = error;
        break;
      }
      p.atoms.push_back(std::make_shared<monitor::CompiledExpression>(std::move(*compiled)));
    }
    if (p.unsupported.empty()) {
      p.shape = *c.shape;
      p.atom_exprs = std::move(pf.atoms);
      p.mode_node = pf.mode;
      p.condition_node = pf.condition;
      p.layout = std::make_unique<monitor::PastTimeLayout>(pf.formula, pf.root);
    } else {
      p.atoms.clear();
    }
  }
  return p;
}

void Property::read_atoms(const std::vector<monitor::Val>& frame, bool* bits, std::uint64_t tick,
                          monitor::Reader* reader) const {
  for (std::size_t k = 0; k < atoms.size(); ++k) {
    std::string error;
    bits[k] = atoms[k]->evaluate_bool(frame, error, reader);
    if (!error.empty())
      throw ProveError(requirement->id + ": at tick " + std::to_string(tick) + ": " + error);
  }
}

void Model::choose_values(const std::map<std::string, std::string, std::less<>>& unenumerable) {
  // Numeric environment variables are cut into cells by every atom that reads them.
  std::set<std::string, std::less<>> numeric;
  // So are the entries output ports write (and nothing computes): the action may write any
  // value, and one per cell is all the readers tell apart. Of an enumerated one, the values no
  // atom names are one cell.
  Cuts::EnumValues enums;
  for (const StateVar& v : vars) {
    const fretish::Variable* d = declaration(v.name);
    if (!v.relevant || !(v.env || (v.port_written && !v.script_written)) || !d) continue;
    if (d->type == fretish::VarType::integer || d->type == fretish::VarType::real)
      numeric.insert(v.name);
    else if (d->type == fretish::VarType::enumeration)
      enums[v.name].insert(d->enum_values.begin(), d->enum_values.end());
  }
  // The mission's own numeric variables: an atom that compares an environment variable with
  // them is cut in each state, with the values they have there.
  std::set<std::string, std::less<>> mission_numbers;
  for (const StateVar& v : vars) {
    const fretish::Variable* d = declaration(v.name);
    if (v.relevant && !numeric.contains(v.name) && !v.env && d &&
        (d->type == fretish::VarType::integer || d->type == fretish::VarType::real))
      mission_numbers.insert(v.name);
  }
  std::set<std::string, std::less<>> integers;
  for (const StateVar& v : vars)
    if (const fretish::Variable* d = declaration(v.name); d && d->type == fretish::VarType::integer)
      integers.insert(v.name);
  Cuts cuts(numeric, mission_numbers, integers, enums);
  if (!numeric.empty() || !enums.empty()) {
    for (const Property& p : properties)
      for (const auto& e : p.exprs)
        if (e) cuts.add(*e, place_text(p.requirement->location));
    for (const auto& a : mission.domain.assumptions)
      if (a.expr) cuts.add(*a.expr, place_text(a.location), true);
    if (world.initial) cuts.add(*world.initial, world.file + ": initial", true);
    std::vector<char> in_disjunction(tree_scripts.size(), 0);
    for (const auto& [first, last] : disjunctions) {
      std::vector<const runtime::script::Program*> programs;
      for (std::size_t i = first; i < last; ++i) {
        programs.push_back(&tree_scripts[i].first);
        in_disjunction[i] = 1;
      }
      cuts.add_any_of(programs, mission.domain, tree_scripts[first].second);
    }
    for (std::size_t i = 0; i < tree_scripts.size(); ++i)
      if (!in_disjunction[i])
        cuts.add(tree_scripts[i].first, mission.domain, tree_scripts[i].second);
    for (const auto& leaf : choice->leaves()) {
      if (leaf.condition) cuts.add_truth_read(leaf.label, "condition " + leaf.name);
      for (const auto* effect : {&leaf.on_success, &leaf.on_failure})
        if (*effect)
          cuts.add(**effect, mission.domain, world.file + ": the effect of " + leaf.label);
    }
    for (const std::string& key : port_reads)
      cuts.add_uncut(key, "a port of the tree reads {" + key + "}");
  }
  for (std::size_t index = 0; index < vars.size(); ++index) {
    StateVar& v = vars[index];
    if (!v.relevant) continue;
    const fretish::Variable* d = declaration(v.name);
    const auto why = unenumerable.find(v.name);
    if (enums.contains(v.name) && cuts.uncut(v.name).empty()) {
      v.values = enum_cell_values(*d, cuts.named(v.name));
      continue;
    }
    if (numeric.contains(v.name)) {
      const std::string uncut = cuts.uncut(v.name);
      const std::vector<MixedAtom>& mixed = cuts.mixed(v.name);
      // Cut in each state only where it would otherwise be left to the symbolic engine: a
      // variable with few values is enumerated, as it is without such an atom.
      if (uncut.empty() && (mixed.empty() || why != unenumerable.end())) {
        v.values = cell_values(*d, cuts.breaks(v.name));
        if (v.values.empty()) v.values.push_back(ScriptValue{});
        if (mixed.empty()) continue;
        StateCut& cut = state_cuts[index];
        cut.declaration = d;
        cut.breaks = cuts.breaks(v.name);
        for (const MixedAtom& a : mixed) {
          StateCut::Atom atom{{}, a.b, a.at_tick_start, a.where};
          for (const auto& [name, factor] : a.terms)
            for (std::size_t k = 0; k < vars.size(); ++k)
              if (vars[k].name == name) atom.terms.emplace_back(k, factor);
          cut.atoms.push_back(std::move(atom));
        }
        continue;
      }
      if (why == unenumerable.end()) continue;  // few enough values to take each one
      if (explicit_refusal.empty())
        explicit_refusal = std::string("the explicit-state engine cannot cut ") +
                           (d->type == fretish::VarType::real ? "real" : "integer") + " '" +
                           v.name + "' into cells: " + uncut;
      continue;
    }
    if (why == unenumerable.end()) continue;
    // A numeric variable the mission writes: only its initial value is chosen.
    if (world.initial && d)
      if (auto fixed = fixed_number(*world.initial, *d)) {
        v.values = {*fixed};
        continue;
      }
    if (explicit_refusal.empty())
      explicit_refusal = "the explicit-state engine cannot enumerate " + why->second +
                         " (the mission writes it: fix its initial value in world.json's "
                         "`initial`, or bound its range)";
  }
}

const fretish::Variable* Model::declaration(const std::string& name) const {
  if (const fretish::Variable* d = mission.domain.find(name)) return d;
  const auto it = port_entries.find(name);
  return it == port_entries.end() ? nullptr : &it->second;
}

void Model::mark_read_once() {
  // Repeat, RetryUntilSuccessful and SequenceWithMemory ask for wake-up re-ticks: the whole
  // tree may then run again within the tick.
  bool loops = false;
  std::function<void(const bt::Node&)> scan = [&](const bt::Node& n) {
    const bt::NodeKind kind = bt::node_kind(n.kind());
    loops = loops || kind == bt::NodeKind::repeat || kind == bt::NodeKind::retry_until_successful ||
            kind == bt::NodeKind::sequence_with_memory;
    for (const auto& c : n.children) scan(c);
  };
  for (const auto& t : doc.trees) scan(t.root);
  if (loops) return;
  std::set<std::string, std::less<>> env;
  for (const StateVar& v : vars)
    if (v.env && v.relevant) env.insert(v.name);
  std::map<std::string, int, std::less<>> sites;
  for (const auto& leaf : choice->leaves()) {
    if (leaf.condition) ++sites[leaf.label];
    for (const auto* effect : {&leaf.on_success, &leaf.on_failure})
      if (*effect)
        for (const auto& n : (*effect)->names()) sites[bt::script::entry_key(n)] += 2;
  }
  for (const auto& [program, what] : tree_scripts) {
    std::set<std::string> names;
    for (const auto& n : program.names())
      if (env.contains(bt::script::entry_key(n))) names.insert(bt::script::entry_key(n));
    for (const auto& n : names) sites[n] += names.size() > 1 ? 2 : 1;
  }
  for (const auto& key : port_reads) sites[bt::script::entry_key(key)] += 2;
  for (StateVar& v : vars) v.read_once = v.env && v.relevant && sites[v.name] == 1;
}

bool Model::fallback_of_conditions(const bt::Node& n) {
  const bt::NodeKind kind = bt::node_kind(n.kind());
  if (kind != bt::NodeKind::fallback && kind != bt::NodeKind::reactive_fallback) return false;
  for (const auto& [attr, value] : n.attributes)
    if (attr != "name") return false;
  for (const bt::Node& c : n.children) {
    if (bt::node_kind(c.kind()) != bt::NodeKind::script_condition || !c.children.empty())
      return false;
    for (const auto& [attr, value] : c.attributes)
      if (attr != "name" && attr != "code") return false;
  }
  return !n.children.empty();
}

void Model::fill_state(std::vector<monitor::Val>& frame) const {
  frame.resize(variables.size());
  for (const StateVar& v : vars)
    frame[v.frame] = runtime::TickObservation::value_of(engine->blackboard().value(v.slot),
                                                        const_cast<monitor::Symbols&>(symbols));
}

bool Model::holds(monitor::CompiledExpression& e, std::vector<monitor::Val>& frame) {
  fill_state(frame);
  std::string error;
  const bool v = e.evaluate_bool(frame, error);
  if (!error.empty()) throw ProveError(error);
  return v;
}

}  // namespace uabt::prove
