#include "verify/node.hpp"

namespace uabt::verify::detail {

void check_overlaps(Node& node, Session& session) {
  auto& guards = node.guards;
  for (std::size_t i = 0; i < guards.size(); ++i) {
    const Guard& a = guards[i];
    if (a.is_default) continue;
    for (std::size_t j = i + 1; j < guards.size(); ++j) {
      const Guard& b = guards[j];
      if (b.is_default) continue;
      // An unsatisfiable (or undecided, already reported) guard overlaps nothing; guards whose
      // conjuncts clash on one variable are disjoint.
      if (a.satisfiable != Answer::sat || b.satisfiable != Answer::sat ||
          disjoint(a.signature, b.signature)) {
        ++session.statistics().prefiltered;
        continue;
      }
      const Answer both = session.check({a.literal, b.literal});
      if (both == Answer::unknown) {
        report_inconclusive(node, session, "whether " + label(a) + " and " + label(b) + " overlap",
                            b.requirement->location, {&a, &b});
        continue;
      }
      if (both == Answer::unsat) continue;
      const State witness = session.encoder().state_of(session.model());
      Finding f =
          node_finding(node, "guard-overlap",
                       label(a) + " and " + label(b) + " can both hold: the Fallback picks " +
                           a.requirement->alternative + " and " + b.requirement->alternative +
                           " is never considered in this state",
                       b.requirement->location);
      if (node.options->allow_overlap) f.severity = Severity::warning;
      f.requirements = {a.requirement->id, b.requirement->id};
      f.alternatives = {a.requirement->alternative, b.requirement->alternative};
      f.witness = witness;
      f.notes.push_back("if " + a.requirement->alternative +
                        " fails there, the Fallback falls through to " +
                        b.requirement->alternative);
      node.result->findings.push_back(std::move(f));
    }
  }
}

}  // namespace uabt::verify::detail
