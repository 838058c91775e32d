#include "verify/verify.hpp"

#include <set>

#include "smt/encoder.hpp"
#include "verify/coverage.hpp"
#include "verify/domain_check.hpp"
#include "verify/node.hpp"

namespace uabt::verify {

using detail::Answer;

namespace {

void names_in(const fretish::Expr& e, std::vector<std::string>& out) {
  if (e.kind == fretish::ExprKind::identifier) out.push_back(e.text);
  for (const auto& arg : e.args) names_in(*arg, out);
}

// Builds the node's guards; false when one of them does not type-check.
bool build_guards(detail::Node& node, const std::vector<const fretish::SelectionRequirement*>& reqs,
                  detail::Session& session) {
  smt::Encoder& encoder = session.encoder();
  bool well_typed = true;
  for (const auto* r : reqs) {
    detail::Guard g(encoder.context());
    g.requirement = r;
    g.is_default = r->guard == nullptr;
    if (!g.is_default) {
      auto formula = encoder.lower_condition(*r->guard, r->guard_location, node.result->findings);
      if (!formula) {
        well_typed = false;
        continue;
      }
      g.formula = *formula;
      g.signature = detail::signature_of(*r->guard, encoder.typing());
    }
    node.guards.push_back(std::move(g));
  }
  if (!well_typed) return false;
  for (auto& g : node.guards) g.literal = session.define(g.formula, "guard");
  return true;
}

}  // namespace

Result verify_mission(const load::Mission& mission, const Options& options) {
  Result result;
  smt::Encoder encoder(mission.domain);
  detail::Session session(encoder, options, result.statistics);

  const auto parts = encoder.domain_parts(result.findings);
  std::vector<const fretish::Expr*> assumptions;  // the well-typed ones, which D includes
  std::vector<std::string> assumed_names;
  for (const auto& a : mission.domain.assumptions) {
    if (!a.expr) continue;
    const smt::TypeInfo* t = encoder.typing().find(*a.expr);
    if (t == nullptr || t->sort != smt::Sort::boolean) continue;
    assumptions.push_back(a.expr.get());
    names_in(*a.expr, assumed_names);
  }
  const Answer domain = detail::check_domain(session, parts, result.findings);

  std::set<std::string> done;
  for (const auto& site : mission.adaptables) {
    if (!done.insert(site.id).second) continue;  // one analysis per node, however often used
    const auto reqs = mission.selections_for(site.id);
    Coverage cov;
    cov.adaptable = site.id;
    if (reqs.empty()) {
      cov.not_counted_reason = "no selection requirement names this adaptable node";
      result.coverage.push_back(std::move(cov));
      continue;
    }
    detail::Node node;
    node.adaptable = site.id;
    node.result = &result;
    node.options = &options;
    const bool well_typed = build_guards(node, reqs, session);
    if (!well_typed || domain != Answer::sat) {
      for (const auto* r : reqs) {
        AlternativeCoverage a;
        a.name = r->alternative;
        a.requirement = r->id;
        a.reachable = false;  // not decided
        cov.alternatives.push_back(a);
      }
      cov.not_counted_reason = !well_typed               ? "a guard does not type-check"
                               : domain == Answer::unsat ? "the domain is inconsistent"
                                                         : "the domain could not be decided";
      result.coverage.push_back(std::move(cov));
      continue;
    }
    detail::check_satisfiable_and_shadowed(node, session);
    detail::check_overlaps(node, session);
    std::vector<std::string> region;
    detail::check_gap(node, session, region);
    detail::check_vacuous_atoms(node, session, assumed_names);

    cov = detail::count_coverage(site.id, reqs, assumptions, mission.domain, encoder.typing());
    for (std::size_t k = 0; k < node.guards.size() && k < cov.alternatives.size(); ++k)
      cov.alternatives[k].reachable = node.guards[k].selectable == Answer::sat;
    cov.gap_region = std::move(region);
    result.coverage.push_back(std::move(cov));
  }
  sort_findings(result.findings);
  return result;
}

}  // namespace uabt::verify
