#include <algorithm>

#include "verify/node.hpp"

namespace uabt::verify::detail {

namespace {

std::string join_labels(const std::vector<const Guard*>& guards, const char* last_joiner) {
  std::string out;
  for (std::size_t k = 0; k < guards.size(); ++k) {
    if (k > 0) out += k + 1 == guards.size() ? last_joiner : ", ";
    out += label(*guards[k]);
  }
  return out;
}

void report_unsatisfiable(Node& node, const Guard& g, bool under_domain) {
  Finding f =
      node_finding(node, "guard-unsatisfiable",
                   "the guard of " + label(g) + " can never hold" +
                       (under_domain ? " under the domain's declarations and assumptions" : "") +
                       ": " + g.requirement->alternative + " can never run",
                   g.requirement->guard_location);
  f.requirements = {g.requirement->id};
  f.alternatives = {g.requirement->alternative};
  f.notes.push_back("guard: " + fretish::to_fretish(*g.requirement->guard));
  node.result->findings.push_back(std::move(f));
}

void report_shadowed(Node& node, Session& session, const Guard& g,
                     const std::vector<const Guard*>& hiders, const z3::model& model) {
  const State witness = session.encoder().state_of(model);
  Finding f = node_finding(node, "guard-shadowed",
                           label(g) + " is never selected: whenever its guard holds, " +
                               join_labels(hiders, " or ") + " holds too and comes first",
                           g.requirement->guard_location);
  f.requirements = {g.requirement->id};
  f.alternatives = {g.requirement->alternative};
  for (const Guard* h : hiders) {
    f.requirements.push_back(h->requirement->id);
    f.alternatives.push_back(h->requirement->alternative);
  }
  for (const Guard* h : hiders) {
    if (model.eval(h->formula, true).is_true()) {
      f.notes.push_back("in the witness state " + g.requirement->id +
                        "'s guard holds but the Fallback selects " + label(*h));
      break;
    }
  }
  f.witness = witness;
  node.result->findings.push_back(std::move(f));
}

}  // namespace

void check_satisfiable_and_shadowed(Node& node, Session& session) {
  const fretish::Domain& domain = session.encoder().domain();
  const bool constrained =
      !domain.assumptions.empty() ||
      std::any_of(domain.variables.begin(), domain.variables.end(), [](const auto& v) {
        return !v.lower.empty() || !v.upper.empty() || v.type == fretish::VarType::enumeration;
      });
  for (std::size_t i = 0; i < node.guards.size(); ++i) {
    Guard& g = node.guards[i];
    // Only earlier guards that can overlap g can hide any part of it.
    std::vector<const Guard*> candidates;
    for (const std::size_t k : node.meeting[i]) {
      if (k >= i) break;
      if (node.guards[k].satisfiable != Answer::unsat) candidates.push_back(&node.guards[k]);
    }
    session.statistics().prefiltered += i - candidates.size();
    if (g.is_default) {
      g.satisfiable = Answer::sat;  // the domain is consistent
      ++session.statistics().prefiltered;
    } else if (g.signature.contradictory) {
      g.satisfiable = g.selectable = Answer::unsat;
      ++session.statistics().prefiltered;
      report_unsatisfiable(node, g, false);
      continue;
    }
    Session::Scope scope(session, candidates.size() + 1 > Session::kWideScope);
    define(session, {&g});
    define(session, candidates);
    // First ask whether some state selects g: in the usual case that settles both questions.
    std::vector<z3::expr> query{g.literal};
    for (const Guard* e : candidates) query.push_back(!e->literal);
    const Answer selected = session.check(query);
    if (selected == Answer::unknown) {
      report_inconclusive(node, session, "whether " + label(g) + " can be selected",
                          g.requirement->guard_location, {&g});
      continue;
    }
    if (selected == Answer::sat) {
      g.satisfiable = g.selectable = Answer::sat;
      continue;
    }
    g.selectable = Answer::unsat;
    const std::vector<z3::expr> core = session.core();
    if (candidates.empty()) {
      g.satisfiable = Answer::unsat;
      report_unsatisfiable(node, g, constrained);
      continue;
    }
    if (!g.is_default) {
      g.satisfiable = session.check({g.literal});
      if (g.satisfiable == Answer::unknown) {
        report_inconclusive(node, session, "whether the guard of " + label(g) + " can hold",
                            g.requirement->guard_location, {&g});
        continue;
      }
      if (g.satisfiable == Answer::unsat) {
        report_unsatisfiable(node, g, constrained);
        continue;
      }
    }
    // A default that the guards above it cover completely is a safety net, not a defect:
    // coverage shows it unreachable, no finding.
    if (g.is_default) continue;
    const z3::model witness = session.model();
    std::vector<z3::expr> hiding;
    for (const Guard* e : candidates) {
      const z3::expr negated = !e->literal;
      if (std::any_of(core.begin(), core.end(),
                      [&](const z3::expr& c) { return z3::eq(c, negated); }))
        hiding.push_back(negated);
    }
    hiding = session.minimise({g.literal}, hiding);
    std::vector<const Guard*> hiders;
    for (const Guard* e : candidates)
      for (const auto& h : hiding)
        if (z3::eq(h, !e->literal)) hiders.push_back(e);
    report_shadowed(node, session, g, hiders, witness);
  }
}

}  // namespace uabt::verify::detail
