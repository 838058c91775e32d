#include "verify/node.hpp"

namespace uabt::verify::detail {

std::string label(const Guard& g) {
  return g.requirement->id + " (" + g.requirement->alternative + ")";
}

void define(Session& session, const std::vector<const Guard*>& guards) {
  for (const Guard* g : guards) session.define(g->literal, g->formula);
}

Finding node_finding(const Node& node, const std::string& check, std::string message,
                     const SourceLocation& location) {
  Finding f = make_finding(check, std::move(message), location);
  f.adaptable = node.adaptable;
  return f;
}

void report_inconclusive(Node& node, Session& session, const std::string& question,
                         const SourceLocation& location, const std::vector<const Guard*>& guards) {
  Finding f = node_finding(
      node, "verification-inconclusive",
      "could not decide " + question + ": Z3 answered unknown (" + session.reason_unknown() + ")",
      location);
  for (const Guard* g : guards) {
    f.requirements.push_back(g->requirement->id);
    f.alternatives.push_back(g->requirement->alternative);
  }
  f.notes.push_back(
      "the gate fails closed: simplify the guard (nonlinear arithmetic is the usual "
      "cause) or raise the per-query timeout");
  node.result->findings.push_back(std::move(f));
}

}  // namespace uabt::verify::detail
