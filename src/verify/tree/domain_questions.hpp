#pragma once
// Questions about BT.CPP scripts asked of the domain (its declared ranges, enums and
// assumptions) in one verify Session, each domain part behind its own literal so that an
// answer "never" names the parts that decide it.
#include <optional>
#include <string>
#include <vector>

#include "base/value.hpp"
#include "fretish/expr.hpp"
#include "load/mission.hpp"
#include "smt/encoder.hpp"
#include "verify/session.hpp"

namespace uabt::verify::tree {

class DomainQuestions {
 public:
  DomainQuestions(const load::Mission& mission, const Options& options);

  // false: the domain is empty, undecided or has an invalid declaration (verify reports
  // that), or the condition does not
  // type-check over it; no question is answered then.
  bool usable() const { return ready_; }

  struct Answer {
    bool typed = false;                // the condition type-checks over the domain
    bool possible = false;             // some state of the domain satisfies it
    bool decided = true;               // false: the solver could not tell
    State witness;                     // a state that satisfies it, when possible
    std::vector<std::string> reasons;  // when impossible: the domain parts that rule it out
  };
  Answer ask(const fretish::Expr& condition, const SourceLocation& where);

  // Whether every name the expression reads is a variable or condition of the domain.
  bool over_domain(const fretish::Expr& e) const;

 private:
  const load::Mission& mission_;
  smt::Encoder encoder_;
  Statistics statistics_;
  detail::Session session_;
  std::vector<smt::Encoder::DomainPart> parts_;
  std::vector<z3::expr> literals_;
  bool ready_ = false;
};

}  // namespace uabt::verify::tree
