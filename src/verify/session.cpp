#include "verify/session.hpp"

#include <algorithm>

namespace uabt::verify::detail {

Session::Session(smt::Encoder& encoder, const Options& options, Statistics& statistics)
    : encoder_(encoder),
      statistics_(statistics),
      timeout_ms_(options.timeout_ms),
      narrow_(encoder.context(), options.timeout_ms),
      solver_(&narrow_) {}

void Session::add(const z3::expr& formula) {
  solver_->add(formula);
  if (depth_ > 0) return;
  base_.push_back(formula);
  if (wide_) wide_->add(formula);
}

Session::Scope::Scope(Session& session, bool wide) : session_(session), outer_(session.solver_) {
  if (wide && session_.depth_ == 0) {
    if (!session_.wide_) {
      session_.wide_ = std::make_unique<smt::Solver>(session_.context(), session_.timeout_ms_);
      for (const auto& f : session_.base_) session_.wide_->add(f);
    }
    session_.solver_ = session_.wide_.get();
  }
  session_.solver_->push();
  ++session_.depth_;
}

Session::Scope::~Scope() {
  --session_.depth_;
  session_.solver_->pop();
  session_.solver_ = outer_;
}

Answer Session::check(const std::vector<z3::expr>& assumptions) {
  ++statistics_.solver_queries;
  reason_.clear();
  try {
    z3::expr_vector literals(context());
    for (const auto& a : assumptions) literals.push_back(a);
    switch (solver_->check(literals)) {
      case z3::sat: return Answer::sat;
      case z3::unsat: return Answer::unsat;
      case z3::unknown: break;
    }
    reason_ = solver_->reason_unknown();
  } catch (const z3::exception& e) {
    // Z3 gives up on some inputs by throwing (resource limits, unsupported operators).
    reason_ = e.msg();
  }
  if (reason_.empty()) reason_ = "unknown";
  return Answer::unknown;
}

std::vector<z3::expr> Session::core() const {
  std::vector<z3::expr> out;
  const z3::expr_vector c = solver_->unsat_core();
  for (unsigned i = 0; i < c.size(); ++i) out.push_back(c[i]);
  return out;
}

z3::expr Session::define(const z3::expr& formula, const char* prefix) {
  z3::expr literal = encoder_.fresh_literal(prefix);
  add(literal == formula);
  return literal;
}

z3::expr Session::guard(const z3::expr& formula, const char* prefix) {
  z3::expr literal = encoder_.fresh_literal(prefix);
  add(z3::implies(literal, formula));
  return literal;
}

std::vector<z3::expr> Session::minimise(const std::vector<z3::expr>& fixed,
                                        std::vector<z3::expr> candidates) {
  for (std::size_t k = 0; k < candidates.size();) {
    std::vector<z3::expr> trial = fixed;
    for (std::size_t j = 0; j < candidates.size(); ++j)
      if (j != k) trial.push_back(candidates[j]);
    if (check(trial) == Answer::unsat) {
      // Keep only what the new core still needs: often drops several candidates at once.
      const std::vector<z3::expr> c = core();
      std::vector<z3::expr> kept;
      for (std::size_t j = 0; j < candidates.size(); ++j) {
        if (j == k) continue;
        const bool in_core = std::any_of(
            c.begin(), c.end(), [&](const z3::expr& x) { return z3::eq(x, candidates[j]); });
        if (in_core) kept.push_back(candidates[j]);
      }
      candidates = std::move(kept);
      // Candidates before k were each needed, so they are all kept and position k now holds
      // the next untried one.
      continue;
    }
    ++k;
  }
  return candidates;
}

}  // namespace uabt::verify::detail
