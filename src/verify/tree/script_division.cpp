// A division in a tree's script, checked as a guard's division is (verify/division.cpp): a
// divisor that is the literal zero, or that is zero in a state of the domain where the division
// is evaluated, is an error. BehaviorTree.CPP's script then gives infinity or fails.
#include "bt/script/ast.hpp"
#include "verify/division.hpp"
#include "verify/script_reading.hpp"
#include "verify/tree/blackboard_checks.hpp"
#include "verify/tree/domain_questions.hpp"

namespace uabt::verify::tree {

std::vector<Finding> check_script_divisions(const FlowGraph& g, const load::Mission& mission,
                                            DomainQuestions& questions, const Options& options) {
  using bt::script::Op;
  using fretish::ExprKind;
  std::vector<DivisionSource> sources;
  for (const ScriptSite& s : g.scripts) {
    const auto& nodes = s.script->nodes();
    const std::string where = s.attribute == "code" ? s.node_kind : s.node_kind + " " + s.attribute;
    for (const std::uint32_t st : s.script->statements()) {
      const bt::script::Expr& e = nodes[st];
      const bool assigns = bt::script::is_assignment(e.op);
      const ScriptReading r = read_script_expression(*s.script, assigns ? e.b : st, mission.domain);
      if (!r.expr || !questions.over_domain(*r.expr)) continue;
      fretish::ExprPtr expr = r.expr;
      if (e.op == Op::div_assign) {  // `x /= d` divides x by d
        expr = fretish::make_expr(
            ExprKind::div,
            {fretish::make_identifier(bt::script::entry_key(nodes[e.a].name)), expr});
        if (!questions.over_domain(*expr)) continue;
      }
      // A value is checked as the condition `value = value`: its divisions are the same.
      if (assigns) expr = fretish::make_expr(ExprKind::eq, {expr, expr});
      DivisionSource source;
      source.expr = std::move(expr);
      source.where = s.location;
      source.what = "the script `" + s.script->code() + "` of " + where;
      source.literal_zero = true;
      source.consequence = "BehaviorTree.CPP's script then gives infinity or fails";
      sources.push_back(std::move(source));
    }
  }
  if (sources.empty() || !questions.usable()) return {};
  return check_divisions(mission.domain, sources, options);
}

}  // namespace uabt::verify::tree
