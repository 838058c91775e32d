// script-decided: a condition script whose value the domain fixes decides nothing: a child that
// can never run, a node that always fails, a precondition with no effect.
#include "verify/division.hpp"
#include "verify/script_reading.hpp"
#include "verify/tree/blackboard_checks.hpp"
#include "verify/tree/domain_questions.hpp"

namespace uabt::verify::tree {

namespace {

// What a condition that always (or never) holds does to its node.
std::string consequence(const ScriptSite& s, bool always) {
  const std::string& a = s.attribute;
  if (a == "code") return always ? "it always succeeds" : "it always fails";
  if (a == "_skipIf") return always ? "the node is always skipped" : "it never skips the node";
  if (a == "_failureIf")
    return always ? "the node always fails without running" : "it never fails the node";
  if (a == "_successIf")
    return always ? "the node always succeeds without running" : "it never ends the node";
  if (a == "_while") return always ? "it never stops the node" : "the node is always skipped";
  return always ? "it always holds" : "it never holds";
}

}  // namespace

std::vector<Finding> check_script_decided(const FlowGraph& g, const load::Mission& mission,
                                          DomainQuestions& questions) {
  std::vector<Finding> out;
  if (!questions.usable()) return out;
  for (const ScriptSite& s : g.scripts) {
    if (!s.condition || s.script->statements().size() != 1) continue;
    const ScriptReading r =
        read_script_expression(*s.script, s.script->statements().front(), mission.domain);
    if (!r.expr || !questions.over_domain(*r.expr)) continue;
    const DomainQuestions::Answer holds = questions.ask(*r.expr, s.location);
    if (!holds.typed || !holds.decided) continue;
    bool always = false;
    std::vector<std::string> reasons = holds.reasons;
    if (holds.possible) {
      const auto negated = fretish::make_expr(fretish::ExprKind::logical_not, {r.expr});
      const DomainQuestions::Answer fails = questions.ask(*negated, s.location);
      if (!fails.typed || !fails.decided || fails.possible) continue;
      always = true;
      reasons = fails.reasons;
    }
    const std::string where = s.attribute == "code" ? s.node_kind : s.node_kind + " " + s.attribute;
    Finding f = make_finding("script-decided",
                             "the condition `" + s.script->code() + "` of " + where + " is " +
                                 (always ? "always true" : "never true") + " in the domain, so " +
                                 consequence(s, always) + ": " +
                                 (reasons.empty() ? std::string("whatever the state")
                                                  : "because of " + listed_with_and(reasons)),
                             s.location);
    if (!always)
      f.notes.push_back("no state of the domain satisfies it");
    else if (!holds.witness.empty())
      f.witness = holds.witness;
    f.notes.push_back(
        "check the comparison against the variable's declared range, or remove the condition");
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace uabt::verify::tree
