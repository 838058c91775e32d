#include "verify/node.hpp"

namespace uabt::verify::detail {

void check_overlaps(Node& node, Session& session) {
  auto& guards = node.guards;
  std::size_t later = 0;  // non-default guards after the current one
  for (const Guard& g : guards) later += g.is_default ? 0 : 1;
  for (std::size_t i = 0; i < guards.size(); ++i) {
    const Guard& a = guards[i];
    if (a.is_default) continue;
    --later;
    // Later non-default guards whose signatures clash with a's need no solver call; nor does
    // an unsatisfiable (or undecided, already reported) guard, which overlaps nothing.
    std::size_t asked = 0;
    for (const std::size_t j : node.meeting[i]) {
      if (j <= i) continue;
      const Guard& b = guards[j];
      if (b.is_default || a.satisfiable != Answer::sat || b.satisfiable != Answer::sat) continue;
      ++asked;
      Session::Scope scope(session);
      define(session, {&a, &b});
      const Answer both = session.check({a.literal, b.literal});
      if (both == Answer::unknown) {
        report_inconclusive(node, session, "whether " + label(a) + " and " + label(b) + " overlap",
                            b.requirement->location, {&a, &b});
        continue;
      }
      if (both == Answer::unsat) continue;
      const z3::model model = session.model();
      const State witness = session.encoder().state_of(model);
      const RegionCubes region =
          describe_region({&a, &b}, session, model, {a.literal, b.literal},
                          session.define(!(a.literal && b.literal), "notboth"));
      Finding f =
          node_finding(node, "guard-overlap",
                       label(a) + " and " + label(b) + " can both hold: the Fallback picks " +
                           a.requirement->alternative + " and " + b.requirement->alternative +
                           " is never considered in this state",
                       b.requirement->location);
      if (node.first_hit) {
        f.severity = Severity::note;
        f.notes.push_back("policy=\"first\" on " + node.adaptable + ": priority decides, " +
                          a.requirement->alternative + " runs in this state");
      } else if (node.options->allow_overlap) {
        f.severity = Severity::warning;
      }
      f.requirements = {a.requirement->id, b.requirement->id};
      f.alternatives = {a.requirement->alternative, b.requirement->alternative};
      f.witness = witness;
      const SourceLocation& other = a.requirement->location;
      f.related.push_back({other, "the other requirement, " + label(a)});
      for (const auto& cube : region.cubes) f.notes.push_back("both hold: " + cube);
      if (!region.more.empty()) f.notes.push_back("both hold: " + region.more);
      f.notes.push_back("if " + a.requirement->alternative +
                        " fails there, the Fallback falls through to " +
                        b.requirement->alternative);
      node.result->findings.push_back(std::move(f));
    }
    session.statistics().prefiltered += later - asked;
  }
}

}  // namespace uabt::verify::detail
