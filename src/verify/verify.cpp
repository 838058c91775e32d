#include "verify/verify.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <set>
#include <thread>

#include "smt/assign.hpp"
#include "smt/encoder.hpp"
#include "verify/coverage.hpp"
#include "verify/division.hpp"
#include "verify/domain_check.hpp"
#include "verify/node.hpp"
#include "verify/tree/blackboard_checks.hpp"
#include "verify/tree/tree_checks.hpp"

namespace uabt::verify {

using detail::Answer;

namespace {

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
  for (auto& g : node.guards) smt::assign(g.literal, encoder.fresh_literal("guard"));
  return true;
}

// A space that cannot be enumerated still lists its regions (ARCHITECTURE §5): the gap as the
// solver's cubes, each overlap as the conjunction of the two guards.
void regions_from_findings(Coverage& cov, const std::vector<Finding>& findings,
                           const std::vector<const fretish::SelectionRequirement*>& reqs) {
  auto constraint = [](std::string text) {
    RegionConstraint c;
    c.kind = RegionConstraint::Kind::linear;
    c.text = std::move(text);
    return c;
  };
  for (const auto& cube : cov.gap_region) {
    if (cube.rfind("\u2026", 0) == 0) continue;  // "… and more"
    Region r;
    r.exact = r.measured = false;
    if (cube != "every state of the domain") r.constraints.push_back(constraint(cube));
    for (const auto* q : reqs) r.requirements.push_back(q->id);
    cov.gap_regions.push_back(std::move(r));
  }
  for (const auto& f : findings) {
    if (f.check != "guard-overlap" || f.adaptable != cov.adaptable || f.requirements.size() != 2)
      continue;
    Region r;
    r.exact = r.measured = false;
    for (const auto& id : f.requirements)
      for (const auto* q : reqs)
        if (q->id == id && q->guard)
          r.constraints.push_back(constraint("(" + fretish::to_fretish(*q->guard) + ")"));
    r.requirements = f.requirements;
    cov.overlap_regions.push_back(std::move(r));
  }
}

// Where the space was measured exactly, the gap finding states its region as the coverage
// table does: each box with the assumption lines that cut it, instead of the solver's cubes,
// which bound the region by the guards' atoms alone and so take in states the domain's
// assumptions rule out.
void exact_gap_notes(Coverage& cov, std::vector<Finding>& findings) {
  if (!cov.measured || cov.gap_regions.empty()) return;
  for (const Region& r : cov.gap_regions)
    if (!r.exact || !r.measured) return;
  std::vector<std::string> region;
  for (const Region& r : cov.gap_regions) region.push_back(r.text());
  if (cov.gap_regions_omitted > 0)
    region.push_back("\u2026 and " + std::to_string(cov.gap_regions_omitted) + " more");
  for (Finding& f : findings) {
    if (f.check != "guard-gap" || f.adaptable != cov.adaptable) continue;
    std::vector<std::string> notes;
    bool placed = false;
    for (auto& note : f.notes) {
      if (note.rfind("uncovered: ", 0) != 0) {
        notes.push_back(std::move(note));
      } else if (!placed) {
        for (const auto& text : region) notes.push_back("uncovered: " + text);
        placed = true;
      }
    }
    f.notes = std::move(notes);
  }
  cov.gap_region = std::move(region);
}

// One adaptable node to analyse and its requirements in priority order (empty: none names it).
struct NodeJob {
  std::string adaptable;
  std::vector<const fretish::SelectionRequirement*> requirements;
};

// What one job found. The domain's own findings (its consistency, ill-typed assumptions) come
// out of every job alike; verify_mission keeps the first job's.
struct NodeOutcome {
  std::vector<Finding> domain_findings;
  Result node;  // the node's findings, its one coverage entry and the solver statistics
};

// Analyses one node in a Z3 context of its own. Nothing is shared with other nodes, so the
// answers, witnesses included, are the same whichever thread runs it and whatever ran before:
// the report does not depend on the number of cores.
NodeOutcome analyse_node(const load::Mission& mission, const NodeJob& job, const Options& options) {
  NodeOutcome out;
  Result& result = out.node;
  smt::Encoder encoder(mission.domain);
  detail::Session session(encoder, options, result.statistics);

  const auto parts = encoder.domain_parts(out.domain_findings);
  std::vector<const fretish::Expr*> assumptions;  // the well-typed ones, which D includes
  std::vector<std::string> assumed_names;
  for (const auto& a : mission.domain.assumptions) {
    if (!a.expr) continue;
    const smt::TypeInfo* t = encoder.typing().find(*a.expr);
    if (t == nullptr || t->sort != smt::Sort::boolean) continue;
    assumptions.push_back(a.expr.get());
    for (std::string& name : fretish::identifiers_of(*a.expr))
      assumed_names.push_back(std::move(name));
  }
  const Answer domain = detail::check_domain(session, parts, out.domain_findings);

  Coverage cov;
  cov.adaptable = job.adaptable;
  const auto& reqs = job.requirements;
  if (reqs.empty()) {
    cov.not_counted_reason = "no selection requirement names this adaptable node";
    result.coverage.push_back(std::move(cov));
    return out;
  }
  detail::Node node;
  node.adaptable = job.adaptable;
  node.result = &result;
  node.options = &options;
  node.first_hit = mission.first_hit(job.adaptable);
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
    return out;
  }
  std::vector<const detail::Signature*> signatures;
  for (const auto& g : node.guards) signatures.push_back(&g.signature);
  node.meeting = detail::meeting_candidates(signatures);
  detail::check_satisfiable_and_shadowed(node, session);
  detail::check_overlaps(node, session);
  std::vector<std::string> region;
  detail::check_gap(node, session, region);
  detail::check_vacuous_atoms(node, session, assumed_names);

  cov = detail::count_coverage(job.adaptable, reqs, assumptions, mission.domain, encoder.typing(),
                               result.findings);
  for (std::size_t k = 0; k < node.guards.size() && k < cov.alternatives.size(); ++k)
    cov.alternatives[k].reachable = node.guards[k].selectable == Answer::sat;
  cov.gap_region = std::move(region);
  exact_gap_notes(cov, result.findings);
  if (!cov.measured && !cov.bounded) regions_from_findings(cov, result.findings, reqs);
  result.coverage.push_back(std::move(cov));
  return out;
}

// Runs every job on up to `threads` threads (0: one per core); outcomes in job order.
std::vector<NodeOutcome> analyse_nodes(const load::Mission& mission,
                                       const std::vector<NodeJob>& jobs, const Options& options) {
  std::vector<NodeOutcome> outcomes(jobs.size());
  std::vector<std::exception_ptr> errors(jobs.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next++; k < jobs.size(); k = next++) {
      try {
        outcomes[k] = analyse_node(mission, jobs[k], options);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  unsigned threads = options.threads != 0 ? options.threads : std::thread::hardware_concurrency();
  threads = static_cast<unsigned>(std::clamp<std::size_t>(threads, 1, jobs.size()));
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  pool.clear();  // joins
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return outcomes;
}

// A node whose guard checks a broken input makes meaningless: one finding says so, instead of
// verdicts that would pretend to know.
void report_not_verified(const load::AdaptableSite& site, const std::string& reason,
                         Result& result) {
  Finding f = make_finding("verification-skipped", site.id + " is not verified because " + reason,
                           site.location);
  f.adaptable = site.id;
  f.notes.push_back("its guards are checked (overlap, gap, reachability) once that is fixed");
  result.findings.push_back(std::move(f));
  Coverage cov;
  cov.adaptable = site.id;
  cov.not_counted_reason = "not verified: " + reason;
  result.coverage.push_back(std::move(cov));
}

}  // namespace

Result verify_mission(const load::Mission& mission, const Options& options) {
  // A guard that divides by zero has no meaning where it does: its node's overlap, gap and
  // reachability would be verdicts about the solver's choice of quotient, so it is not verified.
  std::vector<Finding> divisions = check_divisions(mission, options);
  std::map<std::string, std::string> dividing_by_zero;  // adaptable node -> why
  for (const auto& f : divisions)
    if (!f.adaptable.empty() && !f.requirements.empty())
      dividing_by_zero.emplace(f.adaptable, "the guard of " + f.requirements.front() +
                                                " divides by zero in a state of the domain (" +
                                                f.location.file + ":" +
                                                std::to_string(f.location.line) + ")");
  std::vector<NodeJob> jobs;
  std::set<std::string> seen;
  Result skipped;
  std::vector<std::string> order;  // every node, mission order, for the coverage list
  for (const auto& site : mission.adaptables) {
    // One analysis per node, however often used; an <Adaptable> without ID is bt-structure's.
    if (site.id.empty() || !seen.insert(site.id).second) continue;
    order.push_back(site.id);
    if (auto it = mission.not_verified.find(site.id); it != mission.not_verified.end()) {
      report_not_verified(site, it->second, skipped);
      continue;
    }
    if (auto it = dividing_by_zero.find(site.id); it != dividing_by_zero.end()) {
      report_not_verified(site, it->second, skipped);
      continue;
    }
    jobs.push_back({site.id, mission.selections_for(site.id)});
  }
  // With no node to analyse, the domain is still checked (a job without requirements).
  const bool domain_only = jobs.empty();
  if (domain_only) jobs.push_back({});

  std::vector<NodeOutcome> outcomes = analyse_nodes(mission, jobs, options);
  Result result;
  result.findings = std::move(outcomes.front().domain_findings);
  std::vector<Coverage> analysed;
  for (auto& o : outcomes) {
    for (auto& f : o.node.findings) result.findings.push_back(std::move(f));
    if (!domain_only)
      for (auto& c : o.node.coverage) analysed.push_back(std::move(c));
    result.statistics.solver_queries += o.node.statistics.solver_queries;
    result.statistics.prefiltered += o.node.statistics.prefiltered;
  }
  for (auto& f : skipped.findings) result.findings.push_back(std::move(f));
  for (auto& f : divisions) result.findings.push_back(std::move(f));
  for (auto& f : tree::check_trees(mission)) result.findings.push_back(std::move(f));
  for (auto& f : tree::check_blackboard_and_scripts(mission, options))
    result.findings.push_back(std::move(f));
  for (const auto& id : order) {
    for (auto* list : {&analysed, &skipped.coverage})
      for (auto& c : *list)
        if (c.adaptable == id) result.coverage.push_back(std::move(c));
  }
  sort_findings(result.findings);
  return result;
}

}  // namespace uabt::verify
