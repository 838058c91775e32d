#include "verify/division.hpp"

#include <cctype>
#include <optional>

#include "base/diagnostics.hpp"
#include "smt/encoder.hpp"
#include "smt/types.hpp"
#include "verify/domain_check.hpp"
#include "verify/session.hpp"

namespace uabt::verify {

namespace {

using fretish::Expr;
using fretish::ExprKind;
using fretish::ExprPtr;

// One division and the conditions under which it is evaluated at all.
struct Division {
  const Expr* division;
  std::vector<ExprPtr> context;
};

// What holds on the way down to a subexpression: a conjunction's other operands (the `&` and
// the operand taken, so that a wide conjunction costs one entry, not one per sibling), the
// premise of `=>`, the condition (or its negation) of an ite branch.
struct ContextPart {
  const Expr* conjunction = nullptr;  // every operand of it but `taken`
  std::size_t taken = 0;
  ExprPtr condition;  // when `conjunction` is null
};

std::vector<ExprPtr> conditions_of(const std::vector<ContextPart>& path) {
  std::vector<ExprPtr> out;
  for (const ContextPart& part : path) {
    if (!part.conjunction) {
      out.push_back(part.condition);
      continue;
    }
    for (std::size_t j = 0; j < part.conjunction->args.size(); ++j)
      if (j != part.taken) out.push_back(part.conjunction->args[j]);
  }
  return out;
}

// Every division whose divisor is not a number, with the conjuncts that hold wherever its
// value matters.
void collect(const ExprPtr& e, std::vector<ContextPart>& path, std::vector<Division>& out) {
  if (!e) return;
  const auto& args = e->args;
  if ((e->kind == ExprKind::div || e->kind == ExprKind::mod) && args.size() == 2 && args[1] &&
      args[1]->kind != ExprKind::number && !smt::is_literal_zero(*args[1]))
    out.push_back({e.get(), conditions_of(path)});
  for (std::size_t i = 0; i < args.size(); ++i) {
    bool added = true;
    if (e->kind == ExprKind::logical_and)
      path.push_back({e.get(), i, nullptr});
    else if (e->kind == ExprKind::implies && i == 1)
      path.push_back({nullptr, 0, args[0]});
    else if (e->kind == ExprKind::call && e->text == "ite" && args.size() == 3 && i > 0)
      path.push_back(
          {nullptr, 0, i == 1 ? args[0] : fretish::make_expr(ExprKind::logical_not, {args[0]})});
    else
      added = false;
    collect(args[i], path, out);
    if (added) path.pop_back();
  }
}

// A domain with its parts asserted, ready for questions; nullopt when it is empty or undecided.
struct DomainSession {
  explicit DomainSession(const fretish::Domain& domain, const Options& options)
      : encoder(domain), session(encoder, options, statistics) {
    std::vector<Finding> ignored;  // the domain's own findings are verify's
    ready = detail::domain_known(domain) &&
            detail::check_domain(session, encoder.domain_parts(ignored), ignored) ==
                detail::Answer::sat;
  }
  // A state where `question` holds.
  std::optional<State> witness(const Expr& question, const SourceLocation& where) {
    std::vector<Finding> typing;
    const auto lowered = encoder.lower_condition(question, where, typing);
    if (!lowered) return std::nullopt;
    detail::Session::Scope scope(session);
    session.add(*lowered);
    if (session.check() != detail::Answer::sat) return std::nullopt;
    return encoder.state_of(session.model());
  }
  smt::Encoder encoder;
  Statistics statistics;
  detail::Session session;
  bool ready = false;
};

// Every division in `e` whose divisor is written as zero (`x / 0`, `x mod -0.0`).
void literal_zero_divisions(const Expr& e, std::vector<const Expr*>& out) {
  if ((e.kind == ExprKind::div || e.kind == ExprKind::mod) && e.args.size() == 2 && e.args[1] &&
      smt::is_literal_zero(*e.args[1]))
    out.push_back(&e);
  for (const ExprPtr& a : e.args)
    if (a) literal_zero_divisions(*a, out);
}

ExprPtr is_zero(const ExprPtr& divisor) {
  return fretish::make_expr(ExprKind::eq, {divisor, fretish::make_number("0")});
}

}  // namespace

std::optional<State> zero_divisor_state(const fretish::Domain& domain,
                                        const fretish::ExprPtr& divisor, const Options& options) {
  DomainSession d(domain, options);
  if (!d.ready) return std::nullopt;
  return d.witness(*is_zero(divisor), {});
}

std::vector<Finding> check_divisions(const load::Mission& mission, const Options& options) {
  std::vector<DivisionSource> sources;
  for (const auto& s : mission.selections)
    if (s.guard) sources.push_back({s.guard, s.guard_location, "the guard of " + s.id, &s});
  for (const auto& r : mission.properties) {
    const std::string what = (fretish::is_assumption(r) ? "assumption " : "guarantee ") + r.id;
    if (r.scope && r.scope->condition) sources.push_back({r.scope->condition, r.location, what});
    for (const auto& c : r.conditions)
      if (c.expr) sources.push_back({c.expr, r.location, what});
    if (r.response) sources.push_back({r.response, r.location, what});
    if (r.timing.stop_condition) sources.push_back({r.timing.stop_condition, r.location, what});
  }
  for (const auto& a : mission.domain.assumptions)
    if (a.expr) sources.push_back({a.expr, a.location, "assumption " + a.name});
  return check_divisions(mission.domain, sources, options);
}

std::vector<Finding> check_divisions(const fretish::Domain& domain_declared,
                                     const std::vector<DivisionSource>& sources,
                                     const Options& options) {
  std::vector<std::pair<const DivisionSource*, Division>> divisions;
  bool literal_zero = false;
  for (const DivisionSource& s : sources) {
    literal_zero |= s.literal_zero;
    std::vector<Division> found;
    std::vector<ContextPart> path;
    collect(s.expr, path, found);
    for (auto& d : found) divisions.emplace_back(&s, std::move(d));
  }
  std::vector<Finding> out;
  if (divisions.empty() && !literal_zero) return out;

  DomainSession domain(domain_declared, options);
  if (!domain.ready) return out;
  for (const DivisionSource& s : sources) {
    if (!s.literal_zero || !s.expr) continue;
    std::vector<const Expr*> by_zero;
    literal_zero_divisions(*s.expr, by_zero);
    for (const Expr* d : by_zero)
      out.push_back(make_finding(
          "arith-division-by-zero",
          "'" + fretish::to_fretish(*d) + "' in " + s.what + " divides by zero: " + s.consequence,
          s.where));
  }
  for (const auto& [source, d] : divisions) {
    const ExprPtr divisor = d.division->args[1];
    const ExprPtr zero = is_zero(divisor);
    // With its context when that can be lowered (a property may read observables the domain
    // does not type), else over the domain alone.
    std::vector<ExprPtr> with_context = d.context;
    with_context.push_back(zero);
    const ExprPtr question =
        with_context.size() > 1 ? fretish::make_expr(ExprKind::logical_and, with_context) : zero;
    std::vector<Finding> typing;
    const bool typed = domain.encoder.lower_condition(*question, source->where, typing).has_value();
    const std::optional<State> found = domain.witness(typed ? *question : *zero, source->where);
    if (!found) continue;
    const State& witness = *found;
    const SourceLocation at = start_of(d.division->range, source->where);
    Finding f = make_finding("guard-division-by-zero",
                             "'" + fretish::to_fretish(*d.division) + "' in " + source->what +
                                 " divides by zero when " + fretish::to_fretish(*divisor) +
                                 " = 0, which the domain allows (" + format_state(witness) +
                                 "): " + source->consequence,
                             at);
    f.witness = witness;
    if (source->selection != nullptr) {
      f.adaptable = source->selection->adaptable;
      f.requirements = {source->selection->id};
    }
    f.notes.push_back(
        "make the divisor non-zero where it is used (e.g. `d != 0 & x / d > 2`), or multiply "
        "out the comparison");
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace uabt::verify
