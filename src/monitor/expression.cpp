#include "monitor/expression.hpp"

#include <cstdlib>

namespace uabt::monitor {

int NameTable::id(const std::string& name) {
  const auto [it, inserted] = ids_.emplace(name, static_cast<int>(names_.size()));
  if (inserted) names_.push_back(name);
  return it->second;
}

std::optional<int> NameTable::find(const std::string& name) const {
  const auto it = ids_.find(name);
  if (it == ids_.end()) return std::nullopt;
  return it->second;
}

namespace {

using fretish::ExprKind;

struct Function {
  const char* name;
  int arity;
};

// FRET's built-in functions (its LTL.g4 / SMV translation), by the name FRETISH writes.
std::optional<int> function_arity(const std::string& name) {
  static const Function functions[] = {
      {"absReal", 1},   {"absInt", 1},   {"minReal", 2}, {"minInt", 2}, {"maxReal", 2},
      {"maxInt", 2},    {"ite", 3},      {"preBool", 2}, {"preInt", 2}, {"preReal", 2},
      {"persisted", 2}, {"occurred", 2}, {"prevOcc", 2}};
  for (const Function& f : functions)
    if (name == f.name) return f.arity;
  return std::nullopt;
}

const char* kind_name(Val::Kind k) {
  switch (k) {
    case Val::Kind::missing: return "no value";
    case Val::Kind::boolean: return "a boolean";
    case Val::Kind::number: return "a number";
    case Val::Kind::symbol: return "a name";
  }
  return "no value";
}

}  // namespace

bool is_monitored_function(const std::string& name) {
  return function_arity(name).has_value();
}

bool is_temporal_function(const std::string& name) {
  return name == "persisted" || name == "occurred" || name == "prevOcc";
}

std::string unmonitored_temporal(const std::string& name, std::size_t args) {
  if (name == "nextOcc")
    return "FRET's 'nextOcc' looks ahead to the next occurrence: FRET expands it only into "
           "future-time LTL, ($Right$ | (X (((!p & !$Right$) U p) => ((!p & !$Right$) U (p & "
           "q))))), and its past-time formula, the one a monitor evaluates, keeps it unexpanded";
  if (name == "persists" || name == "occurs")
    return "FRET's '" + name + "' looks ahead (G[<=n] / F[<=n]): FRET expands it only into " +
           "future-time LTL, and its past-time formula, the one a monitor evaluates, has none";
  if ((name == "persisted" || name == "occurred") && args == 3)
    return "FRET's '" + name + "(m, n, p)' needs p at each of the last n ticks (" +
           (name == "persisted" ? "H[m,n]" : "S[m,n]") + "); only " + name + "(n, p) is monitored";
  return {};
}

std::optional<CompiledExpression> CompiledExpression::compile(const fretish::Expr& e,
                                                              const Resolver& resolve,
                                                              std::string& error, Field field) {
  CompiledExpression c;
  c.field_ = field;
  c.root_ = c.build(e, resolve, error);
  if (c.root_ < 0) return std::nullopt;
  return c;
}

int CompiledExpression::build(const fretish::Expr& e, const Resolver& resolve, std::string& error) {
  N n;
  switch (e.kind) {
    case ExprKind::bool_literal: n.constant = Val::of_bool(e.bool_value); break;
    case ExprKind::number: n.constant = fretish::number_literal(e.text); break;
    case ExprKind::identifier: {
      const Resolved r = resolve(e.text);
      if (r.kind == Resolved::Kind::unknown && e.text == "FTP") {
        n.kind = K::first_tick;  // FRET's first time point: (Z FALSE)
        break;
      }
      if (r.kind == Resolved::Kind::unknown) {
        error = "the trace has no variable '" + e.text + "'";
        return -1;
      }
      if (r.kind == Resolved::Kind::literal) {
        n.constant = Val::of_symbol(r.id);
      } else {
        n.kind = K::variable;
        n.slot = r.id;
        n.name = e.text;
        bool known = false;
        for (int v : variables_) known = known || v == r.id;
        if (!known) variables_.push_back(r.id);
      }
      break;
    }
    case ExprKind::call: {
      const auto arity = function_arity(e.text);
      if (!arity) {
        error = unmonitored_temporal(e.text, e.args.size());
        if (error.empty()) error = "'" + e.text + "' is not one of FRET's functions";
        return -1;
      }
      if (static_cast<int>(e.args.size()) != *arity) {
        error = unmonitored_temporal(e.text, e.args.size());
        if (error.empty())
          error = "function '" + e.text + "' takes " + std::to_string(*arity) + " arguments";
        return -1;
      }
      const std::string& f = e.text;
      if (f == "persisted" || f == "occurred") {
        // FRET expands them only when n is an integer (xform.js, nIsNumber).
        if (!fretish::is_natural_numeral(*e.args[0]) || e.args[0]->text.size() > 12) {
          error = "the first argument of '" + f + "' is '" + fretish::to_fretish(*e.args[0]) +
                  "': FRET expands " + f + "(n, p) only for a whole number of ticks n";
          return -1;
        }
        n.kind = f == "persisted" ? K::persisted : K::occurred;
        n.bound = std::strtoull(e.args[0]->text.c_str(), nullptr, 10);
        const int p = build(*e.args[1], resolve, error);
        if (p < 0) return -1;
        n.args.push_back(p);
      } else if (f == "prevOcc") {
        n.kind = K::prev_occ;
        for (const auto& a : e.args) {
          const int x = build(*a, resolve, error);
          if (x < 0) return -1;
          n.args.push_back(x);
        }
      } else if (f.starts_with("pre")) {
        n.kind = K::previous;
      } else {
        n.kind = K::apply;
        n.op = fretish::operator_of(e);
      }
      break;
    }
    default:
      n.kind = K::apply;
      n.op = fretish::operator_of(e);
      break;
  }
  const bool temporal = n.kind == K::persisted || n.kind == K::occurred || n.kind == K::prev_occ;
  if (!temporal) {
    for (const auto& arg : e.args) {
      const int a = build(*arg, resolve, error);
      if (a < 0) return -1;
      n.args.push_back(a);
    }
  }
  if (n.kind == K::previous) {
    n.state = static_cast<int>(previous_.size());
    previous_.push_back({});
  }
  if (temporal) {
    n.state = static_cast<int>(temporal_.size());
    Temporal t;
    t.age_a = t.age_left = n.bound + 1;  // never seen: beyond the bound
    temporal_.push_back(t);
  }
  nodes_.push_back(std::move(n));
  const int id = static_cast<int>(nodes_.size()) - 1;
  if (nodes_[static_cast<std::size_t>(id)].kind == K::previous) previous_nodes_.push_back(id);
  if (temporal) temporal_nodes_.push_back(id);
  return id;
}

// This tick's value of every temporal function, inner ones first, each from its arguments at
// this tick and its state, which then moves on: FRET's expansions (xform.js,
// pastTemporalConditions; pastTemporalConditionsNoBounds in the mode, where $Left$ is absent).
bool CompiledExpression::update_temporal(const std::vector<Val>& frame, std::string& error) {
  const bool in_mode = field_ == Field::mode;
  const bool left = !in_mode && (left_ ? *left_ : first_tick_);
  const auto boolean = [&](int node) -> std::optional<bool> {
    const Val v = eval(node, frame);
    if (!v.known()) {
      error = message(v);
      return std::nullopt;
    }
    if (v.kind != Val::Kind::boolean) {
      error = std::string("a boolean is needed, got ") + kind_name(v.kind);
      return std::nullopt;
    }
    return v.truth();
  };
  const auto older = [](std::uint64_t age, std::uint64_t bound) {
    return age > bound ? bound + 1 : age + 1;
  };
  for (int id : temporal_nodes_) {
    const N& n = nodes_[static_cast<std::size_t>(id)];
    Temporal& t = temporal_[static_cast<std::size_t>(n.state)];
    const auto p = boolean(n.args[0]);
    if (!p) return false;
    t.age_left = left ? 0 : older(t.age_left, n.bound);
    switch (n.kind) {
      case K::persisted:
        // H[<=n] p: no !p at distance 0..n; H[<n] !$Left$: no $Left$ at distance 0..n-1.
        t.age_a = *p ? older(t.age_a, n.bound) : 0;
        t.value = t.age_a > n.bound && t.age_left >= n.bound;
        break;
      case K::occurred:
        // (!$Left$) S p and O[<=n] p.
        t.age_a = *p ? 0 : older(t.age_a, n.bound);
        t.since_a = *p || (!left && t.since_a);
        t.value = t.since_a && t.age_a <= n.bound;
        break;
      default: {
        const auto q = boolean(n.args[1]);
        if (!q) return false;
        // Y reads the previous tick's S values; at the first tick Y is false.
        if (in_mode) {
          t.value = !first_tick_ && t.since_b;  // Y((!p) S (p & q))
        } else {
          t.value = left || (!first_tick_ && (!t.since_a || t.since_b));
        }
        const bool quiet = !left && !*p;
        t.since_a = *p || (quiet && t.since_a);
        t.since_b = (*p && *q) || (quiet && t.since_b);
        break;
      }
    }
  }
  return true;
}

std::string CompiledExpression::message(const Val& v) const {
  if (v.fault == Val::Fault::unset || v.kind == Val::Kind::missing)
    return unset_.empty() ? "no value" : "'" + unset_ + "' has no value";
  return fretish::fault_text(v.fault);
}

Val CompiledExpression::evaluate(const std::vector<Val>& frame, std::string& error,
                                 Reader* reader) {
  unset_.clear();
  struct Reading {
    Reader*& in;
    ~Reading() { in = nullptr; }
  } reading{reader_ = reader};
  if (!temporal_nodes_.empty() && !update_temporal(frame, error)) return {};
  const Val v = eval(root_, frame);
  if (!v.known()) error = message(v);
  // pre*: read this tick's argument values first, then store them all, so nested ones and
  // short-circuited branches see the same previous values.
  std::vector<Val> now;
  now.reserve(previous_nodes_.size());
  for (int p : previous_nodes_)
    now.push_back(eval(nodes_[static_cast<std::size_t>(p)].args[1], frame));
  first_tick_ = false;
  for (std::size_t i = 0; i < previous_nodes_.size(); ++i) {
    Previous& state = previous_[static_cast<std::size_t>(
        nodes_[static_cast<std::size_t>(previous_nodes_[i])].state)];
    state.seen = true;
    state.value = now[i];
  }
  return v;
}

bool CompiledExpression::evaluate_bool(const std::vector<Val>& frame, std::string& error,
                                       Reader* reader) {
  const Val v = evaluate(frame, error, reader);
  if (!error.empty()) return false;
  if (v.kind != Val::Kind::boolean) {
    error = std::string("the expression is ") + kind_name(v.kind) + ", not a boolean";
    return false;
  }
  return v.truth();
}

Val CompiledExpression::eval(int id, const std::vector<Val>& frame) {
  const N& n = nodes_[static_cast<std::size_t>(id)];
  switch (n.kind) {
    case K::constant: return n.constant;
    case K::variable: {
      if (reader_ != nullptr) reader_->reach(n.slot);
      const Val& v = frame[static_cast<std::size_t>(n.slot)];
      if (!v.known() && unset_.empty()) unset_ = n.name;
      return v;
    }
    case K::apply: {
      if (reader_ != nullptr &&
          (n.op == fretish::Op::logical_and || n.op == fretish::Op::logical_or ||
           n.op == fretish::Op::implies || n.op == fretish::Op::ite))
        return eval_lazily(n, frame);
      Val small[3];
      std::vector<Val> many;
      Val* args = small;
      if (n.args.size() > 3) {
        many.resize(n.args.size());
        args = many.data();
      }
      for (std::size_t i = 0; i < n.args.size(); ++i) args[i] = eval(n.args[i], frame);
      return fretish::apply(n.op, args, n.args.size());
    }
    case K::previous: {
      const Previous& p = previous_[static_cast<std::size_t>(n.state)];
      return p.seen ? p.value : eval(n.args[0], frame);
    }
    case K::first_tick: return Val::of_bool(first_tick_);
    case K::persisted:
    case K::occurred:
    case K::prev_occ: return Val::of_bool(temporal_[static_cast<std::size_t>(n.state)].value);
  }
  return {};
}

// fretish::apply's value, from the arguments it depends on: the ones it reads before it returns.
Val CompiledExpression::eval_lazily(const N& n, const std::vector<Val>& frame) {
  using fretish::Op;
  const std::size_t count = n.args.size();
  Val small[3];
  std::vector<Val> many;
  Val* args = small;
  if (count > 3) {
    many.resize(count);
    args = many.data();
  }
  const auto arg = [&](std::size_t k) { return args[k] = eval(n.args[k], frame); };
  switch (n.op) {
    case Op::logical_and:
    case Op::logical_or: {
      // The first known operand that decides, or that is not a boolean, is where apply stops.
      const bool decisive = n.op == Op::logical_or;
      std::size_t k = 0;
      while (k < count) {
        const Val a = arg(k++);
        if (a.known() && (a.kind != Val::Kind::boolean || a.truth() == decisive)) break;
      }
      return fretish::apply(n.op, args, k);
    }
    case Op::implies: {
      // A known premise that is not a boolean decides (a type error); a false one does when the
      // rest cannot be a known value of another kind (a fold of two or more never is): any
      // boolean then stands for the rest.
      const Val a = arg(0);
      if (a.known() && (a.kind != Val::Kind::boolean ||
                        (!a.truth() && (count > 2 || never_other_than_boolean(n.args[1]))))) {
        const Val decided[2] = {a, Val::of_bool(true)};
        return fretish::apply(Op::implies, decided, 2);
      }
      for (std::size_t k = 1; k < count; ++k) arg(k);
      return fretish::apply(Op::implies, args, count);
    }
    case Op::ite: {
      // The branch taken; the other only when it could make an integer branch real. Without a
      // known condition, the first branch's kind.
      const Val c = arg(0);
      if (c.known() && c.kind != Val::Kind::boolean) return fretish::apply(Op::ite, args, 3);
      if (!c.known()) {
        arg(1);
        return fretish::apply(Op::ite, args, 3);
      }
      const std::size_t taken = c.truth() ? 1 : 2;
      const Val out = arg(taken);
      if (out.kind == Val::Kind::number && out.integer) arg(3 - taken);
      return fretish::apply(Op::ite, args, 3);
    }
    default: break;
  }
  for (std::size_t k = 0; k < count; ++k) arg(k);
  return fretish::apply(n.op, args, count);
}

bool CompiledExpression::never_other_than_boolean(int id) const {
  using fretish::Op;
  const N& n = nodes_[static_cast<std::size_t>(id)];
  switch (n.kind) {
    case K::constant: return !n.constant.known() || n.constant.kind == Val::Kind::boolean;
    case K::variable: return reader_ != nullptr && reader_->boolean(n.slot);
    case K::apply:
      if (n.op == Op::ite)
        return never_other_than_boolean(n.args[1]) && never_other_than_boolean(n.args[2]);
      // The connectives and relations: a boolean, or no value.
      return n.op == Op::logical_not || n.op == Op::logical_and || n.op == Op::logical_or ||
             n.op == Op::logical_xor || n.op == Op::implies || n.op == Op::iff ||
             (n.op >= Op::eq && n.op <= Op::ge);
    case K::previous: return false;
    case K::first_tick:
    case K::persisted:
    case K::occurred:
    case K::prev_occ: return true;
  }
  return false;
}

}  // namespace uabt::monitor
