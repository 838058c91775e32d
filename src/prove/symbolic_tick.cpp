#include "prove/symbolic_tick.hpp"

#include <map>
#include <optional>

#include "bt/node_kinds.hpp"
#include "bt/script/load_check.hpp"
#include "monitor/templates.hpp"
#include "prove/prove.hpp"
#include "runtime/tick_observation.hpp"
#include "smt/assign.hpp"

namespace uabt::prove {

using runtime::NodeId;
using runtime::NodeStatus;
using runtime::ScriptValue;

namespace {

constexpr int kIdle = static_cast<int>(NodeStatus::idle);
constexpr int kRunning = static_cast<int>(NodeStatus::running);
constexpr int kSuccess = static_cast<int>(NodeStatus::success);
constexpr int kFailure = static_cast<int>(NodeStatus::failure);

using NK = bt::NodeKind;

// The built-ins this encoding models; the runtime has a few more.
bool modelled(NK kind) {
  static const std::set<NK> kinds = {NK::sequence,       NK::reactive_sequence,
                                     NK::fallback,       NK::reactive_fallback,
                                     NK::if_then_else,   NK::while_do_else,
                                     NK::inverter,       NK::force_success,
                                     NK::force_failure,  NK::keep_running_until_failure,
                                     NK::repeat,         NK::subtree,
                                     NK::always_success, NK::always_failure,
                                     NK::script,         NK::script_condition};
  return kinds.contains(kind);
}

bool has_counter(NK k) {
  return k == NK::sequence || k == NK::fallback || k == NK::if_then_else || k == NK::repeat;
}

struct NodeDef {
  NK kind = NK::always_success;
  bool condition = false;  // a robot leaf that is a condition (else an action)
  std::vector<NodeId> children;
  int leaf = -1;   // ChoiceWorld leaf
  int var = -1;    // condition: the variable it reads
  int cycles = 0;  // Repeat: num_cycles
  std::optional<runtime::script::Program> program;
  std::map<std::string, int> script_vars;  // script names -> variables (in its scope)
  std::vector<int> inputs;                 // robot leaf: the variables its input ports `{key}` read
  std::vector<int> outputs;                // action: the variables its output ports write, by port
  std::string where;
};

struct VarDef {
  SymType type = SymType::boolean;
  std::set<int> codes;                // symbol
  std::optional<std::string> lo, hi;  // integer, real
  bool tracked = false;               // read by something
  bool chosen = false;                // tracked and the environment's
};

}  // namespace

struct SymbolicTick::Impl {
  Model& m;
  z3::context& ctx;
  SymbolCodes codes;
  std::vector<NodeDef> nodes;
  std::vector<VarDef> vars;
  std::vector<SymType> types;
  std::vector<std::set<int>> domains;
  std::vector<z3::expr> first;  // per variable: its value in the fresh state
  std::map<runtime::SlotId, int> var_of_slot;
  std::vector<std::unique_ptr<MonitorTable>> tables;  // per property
  std::vector<std::map<NodeId, int>> alternatives;    // per adaptable: call -> alternative code
  std::vector<std::string> adaptable_names;
  std::vector<std::pair<std::optional<runtime::script::Program>,
                        std::optional<runtime::script::Program>>>
      effects;  // per leaf: on_success, on_failure (parsed without binding)
  NodeId root = 0;
  int wake_ups = 0;               // wake-up re-ticks unrolled per tick (0 without Repeat)
  bool may_stop = false;          // a node reads an entry that may not be written yet
  std::vector<int> multiplicity;  // per leaf: how often the unrolled tick may tick it

  // Per encode() call.
  struct Exec {
    SymState cur;
    std::vector<z3::expr> ret, selected;
    std::vector<z3::expr> leaf_ticks;  // per leaf, so far in this tick
    const TickInputs* in = nullptr;
    std::vector<z3::expr> constraints;
    bool naming = false;
    std::vector<z3::expr> locals;  // the constants name() introduced
    // Where the tick stops with an error: a node ticked under its guard reads an entry
    // nothing has written. The first of them in the tick's order has its exact guard, so their
    // disjunction is the tick's error whatever the terms say of the rest of that tick.
    std::vector<z3::expr> errors;
  };
  unsigned names = 0;  // constants name() made so far, for unique names

  // A fresh constant defined as `e`, so that the terms built on it refer to it instead of
  // repeating it: Z3's preprocessing flattens nested guards, and without names one tick of a
  // tree of n nodes grew to hundreds of kilobytes.
  z3::expr name(Exec& x, const z3::expr& e) {
    if (!x.naming) return e;
    // Each term named is small (its parts are names), so simplifying it is cheap, and it
    // folds what a concrete state decides (the first tick).
    const z3::expr v = e.simplify();
    if (v.is_numeral() || v.is_true() || v.is_false() || (v.is_app() && v.num_args() == 0))
      return v;
    const z3::expr c = ctx.constant(("tick!" + std::to_string(names++)).c_str(), v.get_sort());
    x.constraints.push_back(c == v);
    x.locals.push_back(c);
    return c;
  }

  Impl(Model& model, z3::context& c) : m(model), ctx(c) {}

  std::string where(NodeId id) const { return m.engine->info(id).place(); }

  void build() {
    const runtime::Engine& e = *m.engine;
    // Variables.
    for (std::size_t i = 0; i < m.vars.size(); ++i) {
      const StateVar& v = m.vars[i];
      VarDef d;
      if (const fretish::Variable* decl = m.declaration(v.name)) {
        switch (decl->type) {
          case fretish::VarType::boolean: d.type = SymType::boolean; break;
          case fretish::VarType::integer: d.type = SymType::integer; break;
          case fretish::VarType::real: d.type = SymType::real; break;
          case fretish::VarType::enumeration:
            d.type = SymType::symbol;
            for (const auto& value : decl->enum_values) d.codes.insert(codes.code(value));
            break;
        }
        if (!decl->lower.empty()) d.lo = decl->lower;
        if (!decl->upper.empty()) d.hi = decl->upper;
      }
      d.tracked = v.relevant;
      d.chosen = v.relevant && v.env;
      types.push_back(d.type);
      domains.push_back(d.codes);
      first.push_back(constant_of(ctx, v.values.front(), d.type, codes));
      var_of_slot[v.slot] = static_cast<int>(i);
      vars.push_back(std::move(d));
    }
    codes.code("none");
    for (const auto& a : m.mission.alternatives) codes.code(a.name);

    // Nodes.
    nodes.resize(e.node_count());
    std::map<NodeId, int> leaf_of;
    const auto& leaves = m.choice->leaves();
    for (std::size_t l = 0; l < leaves.size(); ++l) leaf_of[leaves[l].node] = static_cast<int>(l);
    root = e.root();
    std::vector<NodeId> stack{root};
    while (!stack.empty()) {
      const NodeId id = stack.back();
      stack.pop_back();
      NodeDef& d = nodes[id];
      const runtime::NodeInfo& info = e.info(id);
      d.where = where(id);
      const auto kids = e.children(id);
      d.children.assign(kids.begin(), kids.end());
      for (NodeId c : d.children) stack.push_back(c);
      if (info.element)
        for (const auto& [attr, value] : info.element->attributes)
          if (bt::script::is_condition_attribute(attr))
            throw SymbolicUnsupported(d.where + ": the symbolic engine does not model " + attr);
      d.kind = bt::node_kind(info.kind);
      if (modelled(d.kind)) {
        // a built-in: its kind is all the encoding needs
      } else if (d.kind != NK::robot) {
        throw SymbolicUnsupported(d.where + ": the symbolic engine does not model " + info.kind);
      } else if (const auto l = leaf_of.find(id); l != leaf_of.end()) {
        d.leaf = l->second;
        d.condition = leaves[static_cast<std::size_t>(d.leaf)].condition;
        const ChoiceWorld::Leaf& leaf = leaves[static_cast<std::size_t>(d.leaf)];
        for (const runtime::SlotId slot : leaf.inputs) {
          const auto v = var_of_slot.find(slot);
          if (v == var_of_slot.end())
            throw SymbolicUnsupported(d.where + ": an input port reads {" +
                                      m.engine->blackboard().key(slot) +
                                      "}, which no output port writes and the domain does not "
                                      "declare");
          d.inputs.push_back(v->second);
        }
        for (const auto& out : leaf.outputs) {
          const auto v = var_of_slot.find(out.slot);
          if (v == var_of_slot.end() || m.vars[static_cast<std::size_t>(v->second)].script_written)
            throw SymbolicUnsupported(d.where + ": output port '" + out.port +
                                      "' writes an entry a script or an effect also assigns");
          if (types[static_cast<std::size_t>(v->second)] == SymType::symbol &&
              domains[static_cast<std::size_t>(v->second)].empty() && out.fixed == nullptr)
            throw SymbolicUnsupported(d.where + ": output port '" + out.port +
                                      "' has no values the symbolic engine can choose from");
          d.outputs.push_back(v->second);
        }
      } else {
        throw SymbolicUnsupported(d.where + ": the symbolic engine does not model this node");
      }
      check_shape(d);
      if (d.kind == NK::repeat) {
        const std::string* text = info.element ? info.element->attribute("num_cycles") : nullptr;
        int cycles = -1;
        if (text && !text->empty() && text->find_first_not_of("0123456789") == std::string::npos &&
            text->size() < 6)
          cycles = std::stoi(*text);
        if (cycles < 0)
          throw SymbolicUnsupported(d.where +
                                    ": the symbolic engine models Repeat with a literal "
                                    "num_cycles of at least 0 only");
        d.cycles = cycles;
        // Each re-tick within a tick is asked for by a Repeat that counted a cycle.
        wake_ups = std::min(32, wake_ups + cycles);
      }
      if (d.kind == NK::robot && d.condition) {
        const auto v = var_of_slot.find(leaves[static_cast<std::size_t>(d.leaf)].key);
        if (v == var_of_slot.end() || !vars[static_cast<std::size_t>(v->second)].tracked)
          throw SymbolicUnsupported(d.where + ": a condition on an untracked entry");
        d.var = v->second;
      }
      if (d.kind == NK::script || d.kind == NK::script_condition) {
        const std::string* code = info.element ? info.element->attribute("code") : nullptr;
        if (code == nullptr) throw SymbolicUnsupported(d.where + ": a script without code");
        d.program = runtime::script::Program::parse(*code);
        if (d.kind == NK::script_condition && d.program->empty())
          throw SymbolicUnsupported(d.where + ": an empty ScriptCondition");
        for (const std::string& name : d.program->names()) {
          const auto slot = m.engine->blackboard().find(e.scope(id), name);
          const auto v = slot ? var_of_slot.find(*slot) : var_of_slot.end();
          d.script_vars[name] = v == var_of_slot.end() ? -1 : v->second;
        }
      }
    }
    for (const NodeDef& d : nodes) {
      for (const int v : d.inputs)
        may_stop = may_stop || m.vars[static_cast<std::size_t>(v)].unset_first;
      for (const auto& [name, v] : d.script_vars)
        may_stop = may_stop || (v >= 0 && m.vars[static_cast<std::size_t>(v)].unset_first);
    }
    // How often one tick may tick each leaf: once per root pass, twice under a Repeat.
    multiplicity.assign(leaves.size(), 0);
    std::vector<std::pair<NodeId, int>> todo{{root, wake_ups + 1}};
    while (!todo.empty()) {
      const auto [id, times] = todo.back();
      todo.pop_back();
      if (nodes[id].leaf >= 0) multiplicity[static_cast<std::size_t>(nodes[id].leaf)] += times;
      for (NodeId c : nodes[id].children)
        todo.emplace_back(c, nodes[id].kind == NK::repeat ? 2 * times : times);
    }
    for (const auto& leaf : leaves) {
      auto parse = [](const std::optional<runtime::script::Program>& p) {
        return p ? std::optional(runtime::script::Program::parse(p->code())) : std::nullopt;
      };
      effects.emplace_back(parse(leaf.on_success), parse(leaf.on_failure));
    }

    // Adaptables: which SubTree call selects which alternative.
    for (const auto& site : m.mission.adaptables) {
      adaptable_names.push_back(site.id);
      std::map<NodeId, int> calls;
      for (const auto& [call, alt] :
           runtime::observable_of(e, m.mission, {}, site.id + ".selected").alternatives)
        calls[call] = codes.code(alt);
      alternatives.push_back(std::move(calls));
    }

    // Monitors.
    for (const Property& p : m.properties) {
      if (!p.layout) {
        tables.emplace_back();
        continue;
      }
      std::function<bool(const std::vector<char>&)> triggered;
      if (!p.assumption && p.has_trigger())
        triggered = [&p](const std::vector<char>& values) { return p.triggered(values); };
      auto t = std::make_unique<MonitorTable>(*p.layout, 4096, triggered);
      if (t->failed())
        throw SymbolicUnsupported(p.requirement->id +
                                  (p.layout->inputs() > MonitorTable::kMaxInputs
                                       ? ": its monitor reads more than " +
                                             std::to_string(MonitorTable::kMaxInputs) +
                                             " separate conditions of a tick"
                                       : std::string(": its monitor has more than 4096 states")));
      tables.push_back(std::move(t));
    }
  }

  void check_shape(const NodeDef& d) const {
    const std::size_t n = d.children.size();
    switch (d.kind) {
      case NK::sequence:
      case NK::reactive_sequence:
      case NK::fallback:
      case NK::reactive_fallback:
        if (n == 0) throw SymbolicUnsupported(d.where + ": a control node without children");
        break;
      case NK::if_then_else:
      case NK::while_do_else:
        if (n != 2 && n != 3)
          throw SymbolicUnsupported(d.where + ": IfThenElse and WhileDoElse need 2 or 3 children");
        break;
      case NK::inverter:
      case NK::force_success:
      case NK::force_failure:
      case NK::keep_running_until_failure:
      case NK::repeat:
      case NK::subtree:
        if (n != 1) throw SymbolicUnsupported(d.where + ": a decorator needs one child");
        break;
      default:
        if (n != 0) throw SymbolicUnsupported(d.where + ": a leaf with children");
    }
  }

  z3::expr sort_const(const std::string& name, SymType t) const {
    switch (t) {
      case SymType::boolean: return ctx.bool_const(name.c_str());
      case SymType::real: return ctx.real_const(name.c_str());
      default: return ctx.int_const(name.c_str());
    }
  }

  // The range/enum a value of variable `i` the environment chooses lies in.
  z3::expr in_range(std::size_t i, const z3::expr& v) const {
    const VarDef& d = vars[i];
    z3::expr ok = ctx.bool_val(true);
    if (d.type == SymType::symbol) {
      z3::expr any = ctx.bool_val(false);
      for (int c : d.codes) smt::assign(any, any || v == c);
      return any;
    }
    if (d.type == SymType::integer) {
      if (d.lo) smt::assign(ok, ok && v >= ctx.int_val(d.lo->c_str()));
      if (d.hi) smt::assign(ok, ok && v <= ctx.int_val(d.hi->c_str()));
    } else if (d.type == SymType::real) {
      if (d.lo) smt::assign(ok, ok && v >= ctx.real_val(d.lo->c_str()));
      if (d.hi) smt::assign(ok, ok && v <= ctx.real_val(d.hi->c_str()));
    }
    return ok;
  }

  static void set(z3::expr& slot, const z3::expr& g, const z3::expr& v) {
    if (g.is_false()) return;
    slot = g.is_true() ? v : z3::ite(g, v, slot);
  }

  // --- The tick, node kind by node kind (src/runtime/controls, decorators, leaves).

  z3::expr exec(Exec& x, NodeId id, const z3::expr& guard) {
    const z3::expr g = name(x, guard);
    const z3::expr s = name(x, tick_kind(x, id, g));
    set(x.cur.status[id], g, s);  // Core::execute_tick (no SKIPPED in this subset)
    smt::assign(x.cur.status[id], name(x, x.cur.status[id]));
    set(x.ret[id], g, s);  // TickObservation::on_node_ticked
    for (std::size_t a = 0; a < alternatives.size(); ++a)
      if (const auto it = alternatives[a].find(id); it != alternatives[a].end())
        set(x.selected[a], g, ctx.int_val(it->second));
    return s;
  }

  void halt_child(Exec& x, NodeId parent, std::size_t i, const z3::expr& g) {
    const NodeId c = nodes[parent].children[i];
    halt_node(x, c, name(x, g && x.cur.status[c] == kRunning));
    set(x.cur.status[c], g, ctx.int_val(kIdle));
    smt::assign(x.cur.status[c], name(x, x.cur.status[c]));
  }
  void reset_children(Exec& x, NodeId parent, const z3::expr& g) {
    for (std::size_t i = 0; i < nodes[parent].children.size(); ++i) halt_child(x, parent, i, g);
  }
  void halt_node(Exec& x, NodeId id, const z3::expr& g) {
    const NodeDef& d = nodes[id];
    if (has_counter(d.kind)) set(x.cur.counter[id], g, ctx.int_val(0));
    if (d.kind == NK::robot && !d.condition)
      set(x.cur.elapsed[static_cast<std::size_t>(d.leaf)], g && x.cur.status[id] == kRunning,
          ctx.int_val(0));
    reset_children(x, id, g);
    set(x.cur.status[id], g, ctx.int_val(kIdle));
  }

  z3::expr tick_kind(Exec& x, NodeId id, const z3::expr& g) {
    const NodeDef& d = nodes[id];
    switch (d.kind) {
      case NK::sequence: return sequence(x, id, g, kSuccess, kFailure);
      case NK::fallback: return sequence(x, id, g, kFailure, kSuccess);
      case NK::reactive_sequence: return reactive(x, id, g, kSuccess, kFailure);
      case NK::reactive_fallback: return reactive(x, id, g, kFailure, kSuccess);
      case NK::if_then_else: return if_then_else(x, id, g);
      case NK::while_do_else: return while_do_else(x, id, g);
      case NK::repeat: return repeat(x, id, g);
      case NK::inverter:
      case NK::force_success:
      case NK::force_failure: {
        set(x.cur.status[id], g, ctx.int_val(kRunning));
        const z3::expr s = exec(x, d.children[0], g);
        const z3::expr completed = s == kSuccess || s == kFailure;
        halt_child(x, id, 0, g && completed);
        const z3::expr forced =
            d.kind == NK::inverter
                ? z3::ite(s == kSuccess, ctx.int_val(kFailure), ctx.int_val(kSuccess))
                : ctx.int_val(d.kind == NK::force_success ? kSuccess : kFailure);
        return z3::ite(completed, forced, s);
      }
      case NK::keep_running_until_failure: {
        // runtime/decorators/keep_running_until_failure.cpp: SUCCESS restarts the child next
        // tick (RUNNING); only FAILURE ends it.
        set(x.cur.status[id], g, ctx.int_val(kRunning));
        const z3::expr s = exec(x, d.children[0], g);
        halt_child(x, id, 0, g && (s == kSuccess || s == kFailure));
        return z3::ite(s == kFailure, ctx.int_val(kFailure), ctx.int_val(kRunning));
      }
      case NK::subtree: {
        set(x.cur.status[id], g && x.cur.status[id] == kIdle, ctx.int_val(kRunning));
        const z3::expr s = exec(x, d.children[0], g);
        halt_child(x, id, 0, g && (s == kSuccess || s == kFailure));
        return s;
      }
      case NK::always_success: return ctx.int_val(kSuccess);
      case NK::always_failure: return ctx.int_val(kFailure);
      case NK::script:
      case NK::script_condition: {
        ScriptScope scope{[&d](const std::string& n) {
                            const auto it = d.script_vars.find(n);
                            return it == d.script_vars.end() ? -1 : it->second;
                          },
                          &m.mission.domain, &types, &domains, &codes};
        // A read of an entry nothing has written yet stops the tick (BT.CPP throws).
        for (const auto& [name, var] : d.script_vars)
          if (var >= 0) require_written(x, static_cast<std::size_t>(var), g);
        const auto v = run_script(ctx, *d.program, scope, x.cur.values, g, d.where);
        if (d.kind == NK::script) return ctx.int_val(kSuccess);
        return z3::ite(script_truth(*v, d.where), ctx.int_val(kSuccess), ctx.int_val(kFailure));
      }
      case NK::robot: {
        if (!d.condition) return action(x, id, g);
        require_inputs(x, d, g);
        const z3::expr& v = x.cur.values[static_cast<std::size_t>(d.var)];
        z3::expr truth = ctx.bool_val(false);
        switch (types[static_cast<std::size_t>(d.var)]) {
          case SymType::boolean: truth = v; break;
          case SymType::integer: smt::assign(truth, v != 0); break;
          case SymType::real: smt::assign(truth, v != ctx.real_val(0)); break;
          case SymType::symbol: break;
        }
        return z3::ite(truth, ctx.int_val(kSuccess), ctx.int_val(kFailure));
      }
      default: break;
    }
    return ctx.int_val(kFailure);
  }

  // Sequence (`go` = SUCCESS moves on, `stop` = FAILURE ends it) and Fallback (mirrored).
  z3::expr sequence(Exec& x, NodeId id, const z3::expr& g, int go, int stop) {
    const std::size_t count = nodes[id].children.size();
    set(x.cur.status[id], g, ctx.int_val(kRunning));
    z3::expr looping = ctx.bool_val(true), stopped = ctx.bool_val(false);
    z3::expr result = ctx.int_val(go);
    for (std::size_t i = 0; i < count; ++i) {
      const z3::expr gi = g && looping && x.cur.counter[id] == static_cast<int>(i);
      const z3::expr s = exec(x, nodes[id].children[i], gi);
      const z3::expr run = gi && s == kRunning, ended = name(x, gi && s == stop),
                     next = gi && s == go;
      smt::assign(result, name(x, z3::ite(run, ctx.int_val(kRunning),
                                          z3::ite(ended, ctx.int_val(stop), result))));
      smt::assign(stopped, stopped || ended);
      set(x.cur.counter[id], ended, ctx.int_val(0));
      set(x.cur.counter[id], next, ctx.int_val(static_cast<int>(i + 1)));
      smt::assign(x.cur.counter[id], name(x, x.cur.counter[id]));
      smt::assign(looping, name(x, looping && !run && !ended));
    }
    const z3::expr all = g && looping;
    // A child that ended the sequence stops the loop: no child is ticked after the reset, so
    // one reset after the loop is the runtime's reset within it.
    reset_children(x, id, name(x, stopped || all));
    set(x.cur.counter[id], all, ctx.int_val(0));
    return z3::ite(all, ctx.int_val(go), result);
  }

  // ReactiveSequence / ReactiveFallback.
  z3::expr reactive(Exec& x, NodeId id, const z3::expr& g, int go, int stop) {
    const std::size_t count = nodes[id].children.size();
    set(x.cur.status[id], g, ctx.int_val(kRunning));
    z3::expr looping = ctx.bool_val(true), stopped = ctx.bool_val(false);
    z3::expr result = ctx.int_val(go);
    std::vector<z3::expr> runs;
    for (std::size_t i = 0; i < count; ++i) {
      const z3::expr gi = g && looping;
      const z3::expr s = exec(x, nodes[id].children[i], gi);
      const z3::expr run = name(x, gi && s == kRunning), ended = name(x, gi && s == stop);
      runs.push_back(run);
      smt::assign(stopped, stopped || ended);
      smt::assign(result, name(x, z3::ite(run, ctx.int_val(kRunning),
                                          z3::ite(ended, ctx.int_val(stop), result))));
      smt::assign(looping, name(x, looping && !run && !ended));
    }
    // The halts of the loop, after it: a running or ending child stops the loop, so no child
    // is ticked after them, and each child's subtree is its own.
    const z3::expr reset = name(x, stopped || (g && looping));
    z3::expr any_run = ctx.bool_val(false);
    for (const z3::expr& r : runs) smt::assign(any_run, any_run || r);
    for (std::size_t j = 0; j < count; ++j) halt_child(x, id, j, reset || (any_run && !runs[j]));
    return z3::ite(g && looping, ctx.int_val(go), result);
  }

  z3::expr if_then_else(Exec& x, NodeId id, const z3::expr& g) {
    const NodeDef& d = nodes[id];
    const bool has_else = d.children.size() == 3;
    set(x.cur.status[id], g, ctx.int_val(kRunning));
    const z3::expr gc = g && x.cur.counter[id] == 0;
    const z3::expr c = exec(x, d.children[0], gc);
    const z3::expr waiting = gc && c == kRunning;
    set(x.cur.counter[id], gc && c == kSuccess, ctx.int_val(1));
    const z3::expr refused = has_else ? ctx.bool_val(false) : gc && c == kFailure;
    if (has_else) set(x.cur.counter[id], gc && c == kFailure, ctx.int_val(2));
    const z3::expr go = g && !waiting && !refused;
    const z3::expr branch = x.cur.counter[id];
    const z3::expr then_s = exec(x, d.children[1], go && branch == 1);
    z3::expr s = then_s;
    if (has_else)
      smt::assign(s, z3::ite(branch == 1, then_s, exec(x, d.children[2], go && branch == 2)));
    const z3::expr finished = go && s != kRunning;
    reset_children(x, id, finished);
    set(x.cur.counter[id], finished, ctx.int_val(0));
    return z3::ite(waiting, ctx.int_val(kRunning), z3::ite(refused, ctx.int_val(kFailure), s));
  }

  // WhileDoElse (controls/while_do_else.cpp): the condition on every tick; the branch it picks
  // runs and the other one is halted.
  z3::expr while_do_else(Exec& x, NodeId id, const z3::expr& g) {
    const NodeDef& d = nodes[id];
    const bool has_else = d.children.size() == 3;
    set(x.cur.status[id], g, ctx.int_val(kRunning));
    const z3::expr c = exec(x, d.children[0], g);
    const z3::expr yes = name(x, g && c == kSuccess), no = name(x, g && c == kFailure);
    if (has_else) halt_child(x, id, 2, yes);
    const z3::expr then_s = exec(x, d.children[1], yes);
    z3::expr s = z3::ite(yes, then_s, ctx.int_val(kFailure));
    if (has_else) {
      halt_child(x, id, 1, no);
      smt::assign(s, z3::ite(yes, then_s, exec(x, d.children[2], no)));
    }
    smt::assign(s, name(x, s));
    reset_children(x, id, (yes || no) && s != kRunning);
    return z3::ite(yes || no, s, ctx.int_val(kRunning));
  }

  // Repeat (decorators/repeat.cpp): at most two rounds of its child per tick; a child that
  // was IDLE and succeeded at once yields with the wake-up signal.
  z3::expr repeat(Exec& x, NodeId id, const z3::expr& g) {
    const int n = nodes[id].cycles;
    const NodeId child = nodes[id].children[0];
    set(x.cur.status[id], g, ctx.int_val(kRunning));
    z3::expr& a = x.cur.counter[id];
    z3::expr result = ctx.int_val(kSuccess);
    z3::expr go = g && a < n;  // this round runs
    const z3::expr none = g && !(a < n);
    for (int round = 0; round < 2; ++round) {
      const z3::expr before = x.cur.status[child];
      const z3::expr s = exec(x, child, go);
      const z3::expr run = go && s == kRunning, failed = go && s == kFailure,
                     succeeded = go && s == kSuccess;
      set(a, failed, ctx.int_val(0));
      halt_child(x, id, 0, failed || succeeded);
      set(a, succeeded, a + 1);
      const z3::expr again = succeeded && a < n;
      const z3::expr yield = again && before == kIdle;
      set(x.cur.wake[0], yield, ctx.bool_val(true));
      const z3::expr finished = succeeded && !again;
      set(a, finished, ctx.int_val(0));
      smt::assign(result, z3::ite(run || yield, ctx.int_val(kRunning),
                                  z3::ite(failed, ctx.int_val(kFailure),
                                          z3::ite(finished, ctx.int_val(kSuccess), result))));
      smt::assign(go, again && !yield);
    }
    set(a, none, ctx.int_val(0));
    return result;
  }

  // The engine's check before a robot leaf ticks: its input ports' entries are there.
  void require_inputs(Exec& x, const NodeDef& d, const z3::expr& g) {
    for (const int var : d.inputs) require_written(x, static_cast<std::size_t>(var), g);
  }
  // A node ticked under `g` reads variable `var`: the tick stops with an error if nothing has
  // written it yet.
  void require_written(Exec& x, std::size_t var, const z3::expr& g) {
    if (m.vars[var].unset_first) x.errors.push_back(name(x, g && !x.cur.written[var]));
  }

  // ChoiceWorld::tick_leaf for an action.
  z3::expr action(Exec& x, NodeId id, const z3::expr& g) {
    require_inputs(x, nodes[id], g);
    const std::size_t l = static_cast<std::size_t>(nodes[id].leaf);
    const ChoiceWorld::Leaf& leaf = m.choice->leaves()[l];
    const ActionContract* c = leaf.contract;
    static const std::vector<NodeStatus> kFree = {NodeStatus::success, NodeStatus::failure};
    const std::vector<NodeStatus>& results = c ? c->results : kFree;
    // The outcome of this leaf's n-th tick within the tick, n counted as the runtime ticks it.
    const auto& options = x.in->outcomes[l];
    z3::expr d = options.back();
    for (std::size_t k = options.size() - 1; k-- > 0;)
      smt::assign(d, z3::ite(x.leaf_ticks[l] == static_cast<int>(k), options[k], d));
    set(x.leaf_ticks[l], g, x.leaf_ticks[l] + 1);
    const z3::expr now = x.cur.elapsed[l] + 1;
    const z3::expr may_run = c ? now < ctx.int_val(c->max_ticks) : ctx.bool_val(true);
    const z3::expr may_end = c ? now >= ctx.int_val(c->min_ticks) : ctx.bool_val(true);
    x.constraints.push_back(z3::implies(
        g, (d == -1 && may_run) || (d >= 0 && d < static_cast<int>(results.size()) && may_end)));
    z3::expr status = ctx.int_val(kRunning);
    set(x.cur.elapsed[l], g && d == -1, c ? now : ctx.int_val(1));
    // Its output ports when it ends, before its effect (ChoiceWorld::tick_leaf): the value
    // world.json gives, else any value of the entry (of this tick of the leaf).
    const z3::expr ends_any = g && d >= 0;
    for (std::size_t k = 0; k < leaf.outputs.size(); ++k) {
      const auto var = static_cast<std::size_t>(nodes[id].outputs[k]);
      z3::expr value = x.in->outputs[l][k].back();
      for (std::size_t n = x.in->outputs[l][k].size() - 1; n-- > 0;)
        smt::assign(value, z3::ite(x.leaf_ticks[l] == static_cast<int>(n) + 1,
                                   x.in->outputs[l][k][n], value));
      if (leaf.outputs[k].fixed != nullptr) {
        smt::assign(value, constant_of(ctx, *leaf.outputs[k].fixed, types[var], codes));
      } else {
        x.constraints.push_back(z3::implies(ends_any, in_range(var, value)));
      }
      if (vars[var].tracked) set(x.cur.values[var], ends_any, value);
      set(x.cur.written[var], ends_any, ctx.bool_val(true));
    }
    for (std::size_t k = 0; k < results.size(); ++k) {
      const z3::expr ends = g && d == static_cast<int>(k);
      smt::assign(status, z3::ite(d == static_cast<int>(k),
                                  ctx.int_val(static_cast<int>(results[k])), status));
      set(x.cur.elapsed[l], ends, ctx.int_val(0));
      const auto& effect = results[k] == NodeStatus::success ? effects[l].first : effects[l].second;
      if (!effect) continue;
      ScriptScope scope{[this](const std::string& n) {
                          const auto slot =
                              m.engine->blackboard().find(runtime::Blackboard::kRootScope, n);
                          const auto it = slot ? var_of_slot.find(*slot) : var_of_slot.end();
                          return it == var_of_slot.end() ? -1 : it->second;
                        },
                        &m.mission.domain, &types, &domains, &codes};
      run_script(ctx, *effect, scope, x.cur.values, ends,
                 m.world.file + ": action '" + leaf.label + "'");
    }
    return status;
  }

  // --- Observables (runtime/tick_observation.hpp) and the state expressions.

  SymValue var_value(std::size_t i, const std::vector<z3::expr>& values) const {
    SymValue v{types[i], values[i], {}};
    if (v.type == SymType::symbol) v.codes = domains[i];
    return v;
  }

  std::optional<SymValue> literal(const std::string& name) {
    bool is = name == "none" || m.mission.domain.enum_owning(name) != nullptr;
    for (const auto& a : m.mission.alternatives) is = is || a.name == name;
    if (!is) return std::nullopt;
    const int c = codes.code(name);
    return SymValue{SymType::symbol, ctx.int_val(c), {c}};
  }

  int var_named(const std::string& name) const {
    for (std::size_t i = 0; i < m.vars.size(); ++i)
      if (m.vars[i].name == name) return static_cast<int>(i);
    return -1;
  }

  // The rule runtime::TickObservation computes a tick's observables by (observable_of), as
  // terms over this tick's returns: a state variable is its value; `<node>.success|failure|
  // running` one of its nodes returned that status last; `<adaptable>.selected` the alternative
  // of its last alternative call ticked (x.selected), else `none`; the mode one of its calls
  // returned anything.
  SymValue observe(const std::string& name, const Exec& x) {
    using Kind = runtime::Observable::Kind;
    const runtime::Observable o = runtime::observable_of(*m.engine, m.mission, m.state_names, name);
    switch (o.kind) {
      case Kind::state:
        if (const int v = var_named(name); v >= 0)
          return var_value(static_cast<std::size_t>(v), x.cur.values);
        break;
      case Kind::status: {
        const int s = o.status == NodeStatus::success   ? kSuccess
                      : o.status == NodeStatus::failure ? kFailure
                                                        : kRunning;
        z3::expr any = ctx.bool_val(false);
        for (NodeId n : o.nodes) smt::assign(any, any || x.ret[n] == s);
        return {SymType::boolean, any, {}};
      }
      case Kind::selected:
        for (std::size_t a = 0; a < adaptable_names.size(); ++a)
          if (adaptable_names[a] + ".selected" == name) {
            SymValue v{SymType::symbol, x.selected[a], {codes.code("none")}};
            for (const auto& [call, code] : alternatives[a]) v.codes.insert(code);
            return v;
          }
        break;
      case Kind::mode: {
        z3::expr any = ctx.bool_val(false);
        for (NodeId call : o.nodes) smt::assign(any, any || x.ret[call] != kIdle);
        return {SymType::boolean, any, {}};
      }
      case Kind::literal:
        if (auto l = literal(name)) return *l;
        break;
      case Kind::unknown: break;
    }
    throw SymbolicUnsupported("the symbolic engine cannot read '" + name + "'");
  }

  z3::expr state_expression(const fretish::Expr& e, const std::vector<z3::expr>& values,
                            const std::string& what) {
    const std::function<SymValue(const std::string&)> resolve = [&](const std::string& name) {
      const int v = m.state_names.contains(name) ? var_named(name) : -1;
      if (v >= 0) return var_value(static_cast<std::size_t>(v), values);
      if (auto l = literal(name)) return *l;
      throw SymbolicUnsupported(what + ": the symbolic engine cannot read '" + name + "'");
    };
    return fretish_bool(ctx, e, resolve, what);
  }

  // What a property's monitor makes of its input bits from `state`, as a table lookup: its
  // value now, its next state, or whether it is triggered.
  enum class Lookup { now, next, triggered };
  static z3::expr lookup(const MonitorTable& t, const z3::expr& state,
                         const std::vector<z3::expr>& bits, Lookup what, z3::context& ctx) {
    auto leaf = [&](std::uint32_t s, unsigned in) {
      switch (what) {
        case Lookup::now: return ctx.bool_val(t.now(s, in));
        case Lookup::triggered: return ctx.bool_val(t.triggered(s, in));
        case Lookup::next: break;
      }
      return ctx.int_val(static_cast<int>(t.next(s, in)));
    };
    z3::expr out = what == Lookup::next ? ctx.int_val(0) : ctx.bool_val(false);
    for (std::uint32_t s = static_cast<std::uint32_t>(t.size()); s-- > 0;) {
      // A tree over the inputs, input 0 innermost.
      std::vector<z3::expr> level;
      for (unsigned in = 0; in < (1u << t.inputs()); ++in) level.push_back(leaf(s, in));
      for (std::size_t bit = 0; bit < t.inputs(); ++bit) {
        std::vector<z3::expr> up;
        for (std::size_t k = 0; k < level.size(); k += 2)
          up.push_back(z3::eq(level[k], level[k + 1]) ? level[k]
                                                      : z3::ite(bits[bit], level[k + 1], level[k]));
        level = std::move(up);
      }
      smt::assign(
          out, s + 1 == t.size() ? level[0] : z3::ite(state == static_cast<int>(s), level[0], out));
    }
    return out;
  }
};

SymbolicTick::SymbolicTick(Model& model, z3::context& ctx)
    : impl_(std::make_unique<Impl>(model, ctx)) {
  impl_->build();
}
SymbolicTick::~SymbolicTick() = default;

SymbolCodes& SymbolicTick::codes() {
  return impl_->codes;
}
z3::context& SymbolicTick::context() {
  return impl_->ctx;
}
bool SymbolicTick::tracked(std::size_t var) const {
  return impl_->vars[var].tracked;
}
SymType SymbolicTick::type(std::size_t var) const {
  return impl_->types[var];
}
const MonitorTable* SymbolicTick::table(std::size_t property) const {
  return impl_->tables[property].get();
}
bool SymbolicTick::may_stop() const {
  return impl_->may_stop;
}

SymState SymbolicTick::fresh() const {
  Impl& i = *impl_;
  SymState s;
  for (std::size_t n = 0; n < i.nodes.size(); ++n) {
    s.status.push_back(i.ctx.int_val(kIdle));
    s.counter.push_back(i.ctx.int_val(0));
  }
  for (std::size_t l = 0; l < i.m.choice->leaves().size(); ++l)
    s.elapsed.push_back(i.ctx.int_val(0));
  s.values = i.first;
  for (const StateVar& v : i.m.vars) s.written.push_back(i.ctx.bool_val(!v.unset_first));
  for (std::size_t p = 0; p < i.tables.size(); ++p) s.monitor.push_back(i.ctx.int_val(0));
  s.done.push_back(i.ctx.bool_val(false));
  s.started.push_back(i.ctx.bool_val(false));
  s.wake.push_back(i.ctx.bool_val(false));
  return s;
}

SymState SymbolicTick::state(const std::string& prefix) const {
  Impl& i = *impl_;
  SymState s;
  for (std::size_t n = 0; n < i.nodes.size(); ++n) {
    const std::string id = prefix + "n" + std::to_string(n);
    s.status.push_back(i.ctx.int_const((id + ".status").c_str()));
    s.counter.push_back(has_counter(i.nodes[n].kind) ? i.ctx.int_const((id + ".a").c_str())
                                                     : i.ctx.int_val(0));
  }
  const auto& leaves = i.m.choice->leaves();
  for (std::size_t l = 0; l < leaves.size(); ++l)
    s.elapsed.push_back(leaves[l].condition
                            ? i.ctx.int_val(0)
                            : i.ctx.int_const((prefix + "elapsed" + std::to_string(l)).c_str()));
  for (std::size_t v = 0; v < i.vars.size(); ++v)
    s.values.push_back(i.vars[v].tracked && !i.vars[v].chosen
                           ? i.sort_const(prefix + i.m.vars[v].name, i.types[v])
                           : i.first[v]);
  for (const StateVar& v : i.m.vars)
    s.written.push_back(v.unset_first ? i.ctx.bool_const((prefix + v.name + ".written").c_str())
                                      : i.ctx.bool_val(true));
  for (std::size_t p = 0; p < i.tables.size(); ++p)
    s.monitor.push_back(i.tables[p]
                            ? i.ctx.int_const((prefix + "monitor" + std::to_string(p)).c_str())
                            : i.ctx.int_val(0));
  s.done.push_back(i.ctx.bool_const((prefix + "done").c_str()));
  s.started.push_back(i.ctx.bool_const((prefix + "started").c_str()));
  s.wake.push_back(i.wake_ups ? i.ctx.bool_const((prefix + "wake").c_str())
                              : i.ctx.bool_val(false));
  return s;
}

TickInputs SymbolicTick::inputs(const std::string& prefix) const {
  Impl& i = *impl_;
  TickInputs in;
  for (std::size_t v = 0; v < i.vars.size(); ++v)
    in.values.push_back(i.sort_const(prefix + "env." + i.m.vars[v].name, i.types[v]));
  for (std::size_t l = 0; l < i.m.choice->leaves().size(); ++l) {
    in.outcomes.emplace_back();
    for (int k = 0; k < std::max(1, i.multiplicity[l]); ++k)
      in.outcomes.back().push_back(i.ctx.int_const(
          (prefix + "outcome" + std::to_string(l) + "." + std::to_string(k)).c_str()));
    in.outputs.emplace_back();
    const NodeId node = i.m.choice->leaves()[l].node;
    for (std::size_t p = 0; p < i.nodes[node].outputs.size(); ++p) {
      const auto var = static_cast<std::size_t>(i.nodes[node].outputs[p]);
      in.outputs.back().emplace_back();
      for (int k = 0; k < std::max(1, i.multiplicity[l]); ++k)
        in.outputs.back().back().push_back(i.sort_const(prefix + "output" + std::to_string(l) +
                                                            "." + std::to_string(p) + "." +
                                                            std::to_string(k),
                                                        i.types[var]));
    }
  }
  return in;
}

z3::expr SymbolicTick::domain(const SymState& s) const {
  Impl& i = *impl_;
  z3::expr ok = i.ctx.bool_val(true);
  for (std::size_t n = 0; n < i.nodes.size(); ++n) {
    smt::assign(ok, ok && s.status[n] >= kIdle && s.status[n] <= kFailure);
    const NodeDef& d = i.nodes[n];
    // Between ticks only the children of a RUNNING node are not IDLE: every kind here resets
    // its children when it completes, and the root goes back to IDLE when it does.
    for (NodeId c : d.children)
      smt::assign(ok, ok && (s.status[c] == kIdle || s.status[n] == kRunning));
    if (has_counter(d.kind)) {
      const int top = d.kind == NK::if_then_else ? static_cast<int>(d.children.size()) - 1
                      : d.kind == NK::repeat     ? d.cycles
                                                 : static_cast<int>(d.children.size());
      smt::assign(ok, ok && s.counter[n] >= 0 && s.counter[n] <= top);
    }
  }
  const auto& leaves = i.m.choice->leaves();
  for (std::size_t l = 0; l < leaves.size(); ++l) {
    if (leaves[l].condition) continue;
    const std::int64_t top = leaves[l].contract ? leaves[l].contract->max_ticks - 1 : 1;
    smt::assign(ok, ok && s.elapsed[l] >= 0 && s.elapsed[l] <= i.ctx.int_val(top));
  }
  for (std::size_t v = 0; v < i.vars.size(); ++v)
    if (i.vars[v].tracked && !i.vars[v].chosen && i.types[v] == SymType::symbol)
      smt::assign(ok, ok && i.in_range(v, s.values[v]));
  for (std::size_t p = 0; p < i.tables.size(); ++p)
    if (i.tables[p])
      smt::assign(ok,
                  ok && s.monitor[p] >= 0 && s.monitor[p] < static_cast<int>(i.tables[p]->size()));
  smt::assign(ok, ok && (s.status[i.root] == kIdle || s.status[i.root] == kRunning));
  // Before the first tick there is one state.
  smt::assign(ok, ok && (s.started[0] || same(s, fresh())));
  return ok;
}

std::vector<z3::expr> SymbolicTick::flatten(const SymState& s) {
  std::vector<z3::expr> out;
  for (const auto* part : {&s.status, &s.counter, &s.elapsed, &s.values, &s.monitor, &s.done,
                           &s.started, &s.wake, &s.written})
    out.insert(out.end(), part->begin(), part->end());
  return out;
}

z3::expr SymbolicTick::same(const SymState& a, const SymState& b) const {
  z3::expr eq = a.done[0] == b.done[0] && a.started[0] == b.started[0];
  auto all = [&](const std::vector<z3::expr>& x, const std::vector<z3::expr>& y) {
    for (std::size_t k = 0; k < x.size(); ++k)
      if (!z3::eq(x[k], y[k])) smt::assign(eq, eq && x[k] == y[k]);
  };
  all(a.status, b.status);
  all(a.counter, b.counter);
  all(a.elapsed, b.elapsed);
  all(a.values, b.values);
  all(a.monitor, b.monitor);
  all(a.wake, b.wake);
  all(a.written, b.written);
  return eq;
}

TickEncoding SymbolicTick::encode(const SymState& s, const TickInputs& in, bool first, bool named) {
  Impl& i = *impl_;
  Impl::Exec x{s, {}, {}, {}, &in, {}, named, {}, {}};
  for (std::size_t n = 0; n < i.nodes.size(); ++n) x.ret.push_back(i.ctx.int_val(kIdle));
  x.leaf_ticks.assign(i.m.choice->leaves().size(), i.ctx.int_val(0));
  for (std::size_t a = 0; a < i.adaptable_names.size(); ++a)
    x.selected.push_back(i.ctx.int_val(i.codes.code("none")));
  z3::expr valid = !s.done[0] && (first ? !s.started[0] : s.started[0]);
  // The environment's values before the tick (for the first tick, every relevant variable).
  for (std::size_t v = 0; v < i.vars.size(); ++v) {
    if (!i.vars[v].tracked || (!first && !i.vars[v].chosen)) continue;
    x.cur.values[v] = in.values[v];
    smt::assign(valid, valid && i.in_range(v, in.values[v]));
  }
  if (first && i.m.world.initial)
    smt::assign(valid, valid && i.state_expression(*i.m.world.initial, x.cur.values,
                                                   i.m.world.file + ": initial"));
  for (const auto& a : i.m.mission.domain.assumptions)
    if (a.expr)
      smt::assign(valid,
                  valid && i.state_expression(*a.expr, x.cur.values, "assumption " + a.name));

  z3::expr root = i.exec(x, i.root, i.ctx.bool_val(true));
  // Engine::wake_up_loop: the root again while it runs and a node asked for it.
  for (int r = 0; r < i.wake_ups; ++r) {
    const z3::expr again = root == kRunning && x.cur.wake[0];
    Impl::set(x.cur.wake[0], again, i.ctx.bool_val(false));
    smt::assign(root, z3::ite(again, i.exec(x, i.root, again), root));
  }
  z3::expr_vector errors(i.ctx);
  for (const z3::expr& e : x.errors) errors.push_back(e);
  const z3::expr error = i.name(x, z3::mk_or(errors));
  const z3::expr overflow =
      i.ctx.bool_val(i.wake_ups > 0) && root == kRunning && x.cur.wake[0] && !error;
  // One n-ary conjunction: with a chain of thousands of binary ones, deleting the context
  // took 0.4 s.
  z3::expr_vector constraints(i.ctx);
  for (const z3::expr& c : x.constraints) constraints.push_back(c);
  smt::assign(valid, valid && z3::mk_and(constraints));
  const z3::expr done = root == kSuccess || root == kFailure;
  Impl::set(x.cur.status[i.root], done, i.ctx.int_val(kIdle));  // BT.CPP's resetStatus()

  TickEncoding out{x.cur, root, x.ret, {}, valid, {}, overflow, x.leaf_ticks, x.locals, error, {}};
  for (std::size_t p = 0; p < i.m.properties.size(); ++p) {
    const Property& prop = i.m.properties[p];
    const MonitorTable* t = i.tables[p].get();
    if (!t) {
      out.fails.push_back(i.ctx.bool_val(false));
      out.triggered.push_back(i.ctx.bool_val(false));
      continue;
    }
    std::vector<z3::expr> bits;
    const std::function<SymValue(const std::string&)> resolve = [&](const std::string& name) {
      return i.observe(name, x);
    };
    for (const fretish::ExprPtr& atom : prop.atom_exprs)
      bits.push_back(fretish_bool(i.ctx, *atom, resolve, prop.requirement->id));
    for (const z3::expr& b : bits) out.inputs.push_back(b);
    const z3::expr now = Impl::lookup(*t, s.monitor[p], bits, Impl::Lookup::now, i.ctx);
    smt::assign(out.next.monitor[p],
                Impl::lookup(*t, s.monitor[p], bits, Impl::Lookup::next, i.ctx));
    out.triggered.push_back(
        prop.assumption || !prop.has_trigger()
            ? i.ctx.bool_val(false)
            : !error && Impl::lookup(*t, s.monitor[p], bits, Impl::Lookup::triggered, i.ctx));
    // A tick that stops with an error is not judged (explore.cpp: no monitor reads it).
    const z3::expr fails =
        !error && !now &&
        (monitor::verdict_is_final_once_violated(prop.shape) ? i.ctx.bool_val(true) : done);
    if (prop.assumption) {
      smt::assign(out.valid, out.valid && !fails);
      out.fails.push_back(i.ctx.bool_val(false));
    } else {
      out.fails.push_back(fails);
    }
  }
  // The environment's values are chosen afresh before the next tick (explore.cpp).
  for (std::size_t v = 0; v < i.vars.size(); ++v)
    if (i.vars[v].chosen) out.next.values[v] = i.first[v];
  out.next.done = {done || error};
  out.next.started = {i.ctx.bool_val(true)};
  return out;
}

runtime::ScriptValue SymbolicTick::value(const z3::model& model, const z3::expr& e,
                                         std::size_t var) const {
  const z3::expr v = model.eval(e, true);
  switch (impl_->types[var]) {
    case SymType::boolean: return ScriptValue::of_bool(v.is_true());
    case SymType::integer: {
      int64_t i = 0;
      if (!v.is_numeral_i64(i))
        throw ProveError("internal error: the value of '" + impl_->m.vars[var].name +
                         "' does not fit 64 bits");
      return ScriptValue::of_int(i);
    }
    case SymType::real: {
      int64_t num = 0, den = 1;
      if (!v.numerator().is_numeral_i64(num) || !v.denominator().is_numeral_i64(den))
        throw ProveError("internal error: the value of '" + impl_->m.vars[var].name +
                         "' has no 64-bit fraction");
      return ScriptValue::of_real(static_cast<double>(num) / static_cast<double>(den));
    }
    case SymType::symbol: return ScriptValue::of_string(impl_->codes.name(v.get_numeral_int()));
  }
  return {};
}

}  // namespace uabt::prove
