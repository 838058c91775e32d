// script-out-of-range: an assignment to a domain variable whose value lies outside the
// variable's declared range in every state of the domain writes a state the domain excludes.
#include "base/diagnostics.hpp"
#include "bt/script/ast.hpp"
#include "verify/division.hpp"
#include "verify/script_reading.hpp"
#include "verify/tree/blackboard_checks.hpp"
#include "verify/tree/domain_questions.hpp"

namespace uabt::verify::tree {

std::vector<Finding> check_script_range(const FlowGraph& g, const load::Mission& mission,
                                        DomainQuestions& questions) {
  using bt::script::Op;
  std::vector<Finding> out;
  if (!questions.usable()) return out;
  for (const ScriptSite& s : g.scripts) {
    const auto& nodes = s.script->nodes();
    for (const std::uint32_t st : s.script->statements()) {
      const bt::script::Expr& e = nodes[st];
      if (e.op != Op::assign_create && e.op != Op::assign) continue;
      const std::string name = bt::script::entry_key(nodes[e.a].name);
      const fretish::Variable* v = mission.domain.find(name);
      if (v == nullptr || !v->declared || !v->invalid.empty() ||
          (v->type != fretish::VarType::integer && v->type != fretish::VarType::real) ||
          (v->lower.empty() && v->upper.empty()))
        continue;
      const ScriptReading r = read_script_expression(*s.script, e.b, mission.domain);
      if (!r.expr || !questions.over_domain(*r.expr)) continue;
      std::vector<fretish::ExprPtr> inside;
      if (!v->lower.empty())
        inside.push_back(
            fretish::make_expr(fretish::ExprKind::ge, {r.expr, fretish::make_number(v->lower)}));
      if (!v->upper.empty())
        inside.push_back(
            fretish::make_expr(fretish::ExprKind::le, {r.expr, fretish::make_number(v->upper)}));
      const auto in_range = inside.size() == 1
                                ? inside.front()
                                : fretish::make_expr(fretish::ExprKind::logical_and, inside);
      const DomainQuestions::Answer fits = questions.ask(*in_range, s.location);
      if (!fits.typed || !fits.decided || fits.possible) continue;
      // A value that reads the state: one state where it is outside, as the witness.
      DomainQuestions::Answer example;
      if (!fretish::identifiers_of(*r.expr).empty())
        example = questions.ask(*fretish::make_expr(fretish::ExprKind::logical_not, {in_range}),
                                s.location);
      const std::string range = fretish::declaration_text(*v);
      const std::string value = fretish::to_fretish(*r.expr);
      const std::string where =
          s.attribute == "code" ? s.node_kind : s.node_kind + " " + s.attribute;
      Finding f = make_finding("script-out-of-range",
                               "`" + s.script->code() + "` of " + where + " assigns " + name +
                                   " the value " + value + ", which is outside " + range +
                                   " in every state of the domain" +
                                   (example.possible && !example.witness.empty()
                                        ? " (e.g. " + format_state(example.witness) + ")"
                                        : std::string()),
                               s.location);
      if (example.possible) f.witness = example.witness;
      f.notes.push_back("the robot's " + name +
                        " cannot take that value: fix the value, or widen the declaration in "
                        "domain.fret if the range is wrong");
      out.push_back(std::move(f));
    }
  }
  return out;
}

}  // namespace uabt::verify::tree
