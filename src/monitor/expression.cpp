#include "monitor/expression.hpp"

#include <cmath>
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

namespace {

bool is_whole_number(const fretish::Expr& e) {
  if (e.kind != ExprKind::number || e.text.empty() || e.text.size() > 12) return false;
  for (char ch : e.text)
    if (ch < '0' || ch > '9') return false;
  return true;
}

}  // namespace

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
    case ExprKind::number: {
      const double x = std::strtod(e.text.c_str(), nullptr);
      const bool integer = e.text.find_first_of(".eE") == std::string::npos;
      n.constant = integer ? Val::of_integer(x) : Val::of_number(x);
      break;
    }
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
        if (!is_whole_number(*e.args[0])) {
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
      } else {
        n.kind = f.rfind("abs", 0) == 0   ? K::abs
                 : f.rfind("min", 0) == 0 ? K::min
                 : f.rfind("max", 0) == 0 ? K::max
                 : f == "ite"             ? K::ite
                                          : K::previous;
      }
      break;
    }
    case ExprKind::logical_not: n.kind = K::logical_not; break;
    case ExprKind::logical_and: n.kind = K::logical_and; break;
    case ExprKind::logical_or: n.kind = K::logical_or; break;
    case ExprKind::logical_xor: n.kind = K::logical_xor; break;
    case ExprKind::implies: n.kind = K::implies; break;
    case ExprKind::iff: n.kind = K::iff; break;
    case ExprKind::eq: n.kind = K::eq; break;
    case ExprKind::ne: n.kind = K::ne; break;
    case ExprKind::lt: n.kind = K::lt; break;
    case ExprKind::le: n.kind = K::le; break;
    case ExprKind::gt: n.kind = K::gt; break;
    case ExprKind::ge: n.kind = K::ge; break;
    case ExprKind::add: n.kind = K::add; break;
    case ExprKind::sub: n.kind = K::sub; break;
    case ExprKind::mul: n.kind = K::mul; break;
    case ExprKind::div: n.kind = K::div; break;
    case ExprKind::mod: n.kind = K::mod; break;
    case ExprKind::pow: n.kind = K::pow; break;
    case ExprKind::negate: n.kind = K::negate; break;
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
    const Val v = eval(node, frame, error);
    if (!error.empty()) return std::nullopt;
    if (v.kind != Val::Kind::boolean) {
      error = std::string("a boolean is needed, got ") + kind_name(v.kind);
      return std::nullopt;
    }
    return v.number != 0;
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

Val CompiledExpression::evaluate(const std::vector<Val>& frame, std::string& error) {
  if (!temporal_nodes_.empty() && !update_temporal(frame, error)) return {};
  const Val v = eval(root_, frame, error);
  // pre*: read this tick's argument values first, then store them all, so nested ones and
  // short-circuited branches see the same previous values.
  std::vector<Val> now;
  now.reserve(previous_nodes_.size());
  for (int p : previous_nodes_) {
    std::string ignored;
    now.push_back(eval(nodes_[static_cast<std::size_t>(p)].args[1], frame, ignored));
  }
  first_tick_ = false;
  for (std::size_t i = 0; i < previous_nodes_.size(); ++i) {
    Previous& state = previous_[static_cast<std::size_t>(
        nodes_[static_cast<std::size_t>(previous_nodes_[i])].state)];
    state.seen = true;
    state.value = now[i];
  }
  return v;
}

bool CompiledExpression::evaluate_bool(const std::vector<Val>& frame, std::string& error) {
  const Val v = evaluate(frame, error);
  if (!error.empty()) return false;
  if (v.kind != Val::Kind::boolean) {
    error = std::string("the expression is ") + kind_name(v.kind) + ", not a boolean";
    return false;
  }
  return v.number != 0;
}

Val CompiledExpression::eval(int id, const std::vector<Val>& frame, std::string& error) {
  const N& n = nodes_[static_cast<std::size_t>(id)];
  const auto arg = [&](std::size_t i) { return eval(n.args[i], frame, error); };
  const auto boolean = [&](std::size_t i) -> std::optional<bool> {
    const Val v = arg(i);
    if (!error.empty()) return std::nullopt;
    if (v.kind != Val::Kind::boolean) {
      error = std::string("a boolean is needed, got ") + kind_name(v.kind);
      return std::nullopt;
    }
    return v.number != 0;
  };
  bool integers = true;  // every number operand read so far is an integer
  const auto number = [&](std::size_t i) -> std::optional<double> {
    const Val v = arg(i);
    if (!error.empty()) return std::nullopt;
    if (v.kind != Val::Kind::number) {
      error = std::string("a number is needed, got ") + kind_name(v.kind);
      return std::nullopt;
    }
    integers = integers && v.integer;
    return v.number;
  };
  const auto result = [&](double x) { return integers ? Val::of_integer(x) : Val::of_number(x); };
  switch (n.kind) {
    case K::constant: return n.constant;
    case K::variable: {
      const Val& v = frame[static_cast<std::size_t>(n.slot)];
      if (v.kind == Val::Kind::missing && error.empty()) error = "'" + n.name + "' has no value";
      return v;
    }
    case K::logical_not: {
      const auto a = boolean(0);
      return a ? Val::of_bool(!*a) : Val{};
    }
    case K::logical_and:
    case K::logical_or: {
      const bool is_and = n.kind == K::logical_and;
      for (std::size_t i = 0; i < n.args.size(); ++i) {
        const auto a = boolean(i);
        if (!a) return {};
        if (*a != is_and) return Val::of_bool(!is_and);
      }
      return Val::of_bool(is_and);
    }
    case K::implies: {
      const auto a = boolean(0);
      if (!a) return {};
      if (!*a) return Val::of_bool(true);
      const auto b = boolean(1);
      return b ? Val::of_bool(*b) : Val{};
    }
    case K::logical_xor:
    case K::iff: {
      const auto a = boolean(0);
      const auto b = a ? boolean(1) : std::nullopt;
      if (!b) return {};
      return Val::of_bool(n.kind == K::iff ? *a == *b : *a != *b);
    }
    case K::eq:
    case K::ne: {
      const Val a = arg(0);
      const Val b = error.empty() ? arg(1) : Val{};
      if (!error.empty()) return {};
      if (a.kind != b.kind) {
        error = std::string("compares ") + kind_name(a.kind) + " with " + kind_name(b.kind);
        return {};
      }
      const bool same = a.kind == Val::Kind::symbol ? a.symbol == b.symbol : a.number == b.number;
      return Val::of_bool(n.kind == K::eq ? same : !same);
    }
    case K::lt:
    case K::le:
    case K::gt:
    case K::ge: {
      const auto a = number(0);
      const auto b = a ? number(1) : std::nullopt;
      if (!b) return {};
      switch (n.kind) {
        case K::lt: return Val::of_bool(*a < *b);
        case K::le: return Val::of_bool(*a <= *b);
        case K::gt: return Val::of_bool(*a > *b);
        default: return Val::of_bool(*a >= *b);
      }
    }
    case K::negate:
    case K::abs: {
      const auto a = number(0);
      if (!a) return {};
      return result(n.kind == K::negate ? -*a : std::fabs(*a));
    }
    case K::add:
    case K::sub:
    case K::mul:
    case K::div:
    case K::mod:
    case K::pow:
    case K::min:
    case K::max: {
      const auto a = number(0);
      const auto b = a ? number(1) : std::nullopt;
      if (!b) return {};
      switch (n.kind) {
        case K::add: return result(*a + *b);
        case K::sub: return result(*a - *b);
        case K::mul: return result(*a * *b);
        case K::min: return result(std::fmin(*a, *b));
        case K::max: return result(std::fmax(*a, *b));
        case K::pow: {
          // A negative integer exponent has a fraction for a result.
          if (*b < 0) integers = false;
          return result(std::pow(*a, *b));
        }
        default: break;
      }
      if (*b == 0) {
        error = "division by zero";
        return {};
      }
      // Integers: quotient truncated toward zero, remainder with the sign of the dividend.
      if (n.kind == K::div) return result(integers ? std::trunc(*a / *b) : *a / *b);
      return result(std::fmod(*a, *b));
    }
    case K::ite: {
      const auto c = boolean(0);
      if (!c) return {};
      return arg(*c ? 1 : 2);
    }
    case K::previous: {
      const Previous& p = previous_[static_cast<std::size_t>(n.state)];
      return p.seen ? p.value : arg(0);
    }
    case K::first_tick: return Val::of_bool(first_tick_);
    case K::persisted:
    case K::occurred:
    case K::prev_occ: return Val::of_bool(temporal_[static_cast<std::size_t>(n.state)].value);
  }
  return {};
}

}  // namespace uabt::monitor
