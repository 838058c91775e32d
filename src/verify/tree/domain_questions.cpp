#include "verify/tree/domain_questions.hpp"

#include "verify/domain_check.hpp"

namespace uabt::verify::tree {

DomainQuestions::DomainQuestions(const load::Mission& mission, const Options& options)
    : mission_(mission), encoder_(mission.domain), session_(encoder_, options, statistics_) {
  std::vector<Finding> ignored;  // the domain's own findings are verify's
  parts_ = encoder_.domain_parts(ignored);
  for (const auto& p : parts_) literals_.push_back(session_.guard(p.constraint, "domain"));
  ready_ = detail::domain_known(mission.domain) && session_.check(literals_) == detail::Answer::sat;
}

bool DomainQuestions::over_domain(const fretish::Expr& e) const {
  if (e.kind == fretish::ExprKind::identifier && mission_.domain.find(e.text) == nullptr &&
      mission_.domain.enum_owning(e.text) == nullptr)
    return false;
  for (const auto& a : e.args)
    if (a && !over_domain(*a)) return false;
  return true;
}

DomainQuestions::Answer DomainQuestions::ask(const fretish::Expr& condition,
                                             const SourceLocation& where) {
  Answer out;
  if (!ready_) return out;
  std::vector<Finding> typing;
  const auto lowered = encoder_.lower_condition(condition, where, typing);
  if (!lowered) return out;
  out.typed = true;
  detail::Session::Scope scope(session_);
  const z3::expr question = session_.guard(*lowered, "script");
  std::vector<z3::expr> assumptions = literals_;
  assumptions.push_back(question);
  const detail::Answer answer = session_.check(assumptions);
  if (answer == detail::Answer::unknown) {
    out.decided = false;
    return out;
  }
  if (answer == detail::Answer::sat) {
    out.possible = true;
    out.witness = encoder_.state_of(session_.model());
    return out;
  }
  std::vector<z3::expr> core;
  for (const auto& c : session_.core())
    if (!z3::eq(c, question)) core.push_back(c);
  core = session_.minimise({question}, core);
  for (std::size_t k = 0; k < parts_.size(); ++k)
    for (const auto& c : core)
      if (z3::eq(c, literals_[k])) out.reasons.push_back(parts_[k].description);
  return out;
}

}  // namespace uabt::verify::tree
