#include "prove/property_formula.hpp"

#include <cstdlib>
#include <map>

namespace uabt::prove {

namespace {

using fretish::Expr;
using fretish::ExprKind;

const char* const previous_reason =
    "preBool/preInt/preReal read the value of an earlier tick, which prove's finite state does "
    "not keep: not supported by prove";

class Builder {
 public:
  Builder(PropertyFormula& out, const monitor::Resolver& resolve) : out_(out), resolve_(resolve) {}

  bool is_ftp(const Expr& e) const {
    return e.kind == ExprKind::identifier && e.text == "FTP" &&
           resolve_(e.text).kind == monitor::Resolved::Kind::unknown;
  }

  // Whether `e` reads an earlier tick: a temporal function, FTP, or (only_previous) pre*.
  bool temporal(const Expr& e, bool only_previous = false) const {
    const bool previous = e.kind == ExprKind::call && e.text.rfind("pre", 0) == 0;
    if (previous ||
        (!only_previous &&
         ((e.kind == ExprKind::call && monitor::is_temporal_function(e.text)) || is_ftp(e))))
      return true;
    for (const auto& a : e.args)
      if (a && temporal(*a, only_previous)) return true;
    return false;
  }

  // The node of boolean expression `e`; `left` is FRET's $Left$ for the temporal functions
  // (-1 in the scope's mode, where FRET expands them without it). -1 when prove cannot read it.
  int node(const fretish::ExprPtr& e, int left) {
    monitor::Formula& f = out_.formula;
    if (!temporal(*e)) return atom(e);
    const auto arg = [&](std::size_t i) { return node(e->args[i], left); };
    switch (e->kind) {
      case ExprKind::logical_not: {
        const int a = arg(0);
        return a < 0 ? -1 : f.negation(a);
      }
      case ExprKind::logical_and:
      case ExprKind::logical_or: {
        int acc = -1;
        for (std::size_t i = 0; i < e->args.size(); ++i) {
          const int a = arg(i);
          if (a < 0) return -1;
          acc = i == 0                             ? a
                : e->kind == ExprKind::logical_and ? f.conjunction(acc, a)
                                                   : f.disjunction(acc, a);
        }
        return acc;
      }
      case ExprKind::logical_xor:
      case ExprKind::implies:
      case ExprKind::iff: {
        const int a = arg(0);
        const int b = a < 0 ? -1 : arg(1);
        if (b < 0) return -1;
        if (e->kind == ExprKind::implies) return f.implication(a, b);
        const int same =
            f.disjunction(f.conjunction(a, b), f.conjunction(f.negation(a), f.negation(b)));
        return e->kind == ExprKind::iff ? same : f.negation(same);
      }
      case ExprKind::identifier: return f.first_tick();  // FTP: FRET's (Z FALSE)
      case ExprKind::call:
        if (monitor::is_temporal_function(e->text) || e->text.rfind("pre", 0) == 0)
          return call(e, left);
        break;
      default: break;
    }
    if (temporal(*e, true)) {
      why(previous_reason);
      return -1;
    }
    why("`" + fretish::to_fretish(*e) +
        "` reads an earlier tick inside a value; prove reads persisted, occurred, prevOcc and "
        "FTP under !, &, |, xor, -> and <-> only");
    return -1;
  }

  std::string unsupported;

 private:
  void why(const std::string& text) {
    if (unsupported.empty()) unsupported = text;
  }

  int atom(const fretish::ExprPtr& e) {
    const std::string key = fretish::to_fretish(*e);
    const auto [it, added] = index_.emplace(key, static_cast<int>(out_.atoms.size()));
    if (added) out_.atoms.push_back(e);
    return out_.formula.input(it->second);
  }

  // FRET's expansions (xform.js, pastTemporalConditions; without $Left$ in the mode), as
  // monitor::CompiledExpression evaluates them.
  int call(const fretish::ExprPtr& e, int left) {
    monitor::Formula& f = out_.formula;
    const std::string& name = e->text;
    if (!monitor::is_temporal_function(name) || e->args.size() != 2) {
      why(previous_reason);
      return -1;
    }
    const bool in_mode = left < 0;
    const int L = in_mode ? f.constant(false) : left;
    if (name == "prevOcc") {
      const int p = node(e->args[0], left);
      const int q = p < 0 ? -1 : node(e->args[1], left);
      if (q < 0) return -1;
      const int pq = f.conjunction(p, q);
      // The mode: Y((!p) S (p & q)).
      if (in_mode) return f.yesterday(f.since(f.negation(p), pq));
      // $Left$ | Y(((!$Left$ & !p) S p) => ((!$Left$ & !p) S (p & q))).
      const int quiet = f.conjunction(f.negation(L), f.negation(p));
      return f.disjunction(L, f.yesterday(f.implication(f.since(quiet, p), f.since(quiet, pq))));
    }
    // persisted(n, p), occurred(n, p): n is a whole number (checked by the monitor's compile).
    const std::uint64_t n = std::strtoull(e->args[0]->text.c_str(), nullptr, 10);
    const int p = node(e->args[1], left);
    if (p < 0) return -1;
    if (name == "persisted")  // (H[<=n] p) & (H[<n] !$Left$)
      return f.conjunction(f.negation(f.once_within(f.negation(p), n)),
                           f.negation(f.once_below(L, n)));
    // ((!$Left$) S p) & (O[<=n] p)
    return f.conjunction(f.since(f.negation(L), p), f.once_within(p, n));
  }

  PropertyFormula& out_;
  const monitor::Resolver& resolve_;
  std::map<std::string, int> index_;  // atom text -> input
};

}  // namespace

PropertyFormula build_property_formula(const monitor::Shape& shape,
                                       const std::array<fretish::ExprPtr, 5>& parts,
                                       const monitor::Resolver& resolve) {
  PropertyFormula out;
  Builder b(out, resolve);
  monitor::Formula& f = out.formula;
  int nodes[5] = {-1, -1, -1, -1, -1};
  nodes[0] = parts[0] ? b.node(parts[0], -1) : -2;
  bool later = false;  // a temporal function after the mode counts from $Left$
  for (std::size_t i = 1; i < 5; ++i) later = later || (parts[i] && b.temporal(*parts[i]));
  const int mode = nodes[0] == -2 ? f.constant(false) : nodes[0];
  const int left = later && mode >= 0 ? monitor::build_scope_start_at(f, shape.scope, mode) : -1;
  for (std::size_t i = 1; i < 5; ++i) nodes[i] = parts[i] ? b.node(parts[i], left) : -2;
  out.unsupported = b.unsupported;
  if (!out.unsupported.empty()) return out;
  monitor::Slots slots;
  slots.nodes = true;
  int* fields[5] = {&slots.mode, &slots.condition, &slots.response, &slots.stop, &slots.judged};
  for (std::size_t i = 0; i < 5; ++i) *fields[i] = nodes[i] == -2 ? f.constant(false) : nodes[i];
  out.mode = nodes[0] == -2 ? -1 : nodes[0];
  out.condition = nodes[1] == -2 ? -1 : nodes[1];
  out.root = monitor::build_requirement_formula(f, shape, slots);
  return out;
}

}  // namespace uabt::prove
