#include "conform/equivalence.hpp"

#include "base/diagnostics.hpp"

namespace uabt::conform {

Prover::Prover(const fretish::Domain& domain, unsigned timeout_ms)
    : encoder_(domain), solver_(encoder_.context(), timeout_ms) {
  // D once: ranges, enumeration membership, assumptions. Ill-typed assumptions are the
  // loader's and the verifier's to report; they are left out here as there.
  std::vector<Finding> ignored;
  for (const auto& part : encoder_.domain_parts(ignored)) solver_.add(part.constraint);
}

std::optional<z3::expr> Prover::lower(const fretish::ExprPtr& condition, std::string& error) {
  kept_.push_back(condition);
  std::vector<Finding> findings;
  auto lowered = encoder_.lower_condition(*condition, SourceLocation{}, findings);
  if (!lowered) {
    error.clear();
    for (const auto& f : findings) {
      if (f.severity != Severity::error) continue;
      error += (error.empty() ? "" : "; ") + f.message;
    }
    if (error.empty()) error = "it does not type check";
  }
  return lowered;
}

Proof Prover::never(const z3::expr& condition) {
  Proof proof;
  solver_.push();
  solver_.add(condition);
  ++queries_;
  const z3::check_result r = solver_.check();
  if (r == z3::unsat) {
    proof.answer = Answer::holds;
  } else if (r == z3::sat) {
    proof.answer = Answer::fails;
    proof.witness = encoder_.state_of(solver_.model());
  } else {
    proof.answer = Answer::unknown;
    proof.reason = solver_.reason_unknown();
  }
  solver_.pop();
  return proof;
}

Proof Prover::equivalent(const z3::expr& a, const z3::expr& b) {
  return never(a != b);
}

std::string describe(const State& state) {
  return state.empty() ? "any state" : format_state(state, " = ");
}

}  // namespace uabt::conform
