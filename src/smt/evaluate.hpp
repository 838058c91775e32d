#pragma once
#include <optional>
#include <stdexcept>
#include <string>

#include "base/value.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"

namespace uabt::smt {

// Thrown when a condition has no value in a state (fretish/evaluate.hpp says when).
struct EvaluationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The truth value of a condition in a state, computed directly from the expression (no
// solver), so that it can check what the solver claims: fretish::evaluate over the state, the
// meaning every evaluator shares (ARCHITECTURE §14).
bool evaluate(const fretish::Expr& condition, const fretish::Domain& domain, const State& state);

// Like evaluate, but nullopt instead of an EvaluationError.
std::optional<bool> try_evaluate(const fretish::Expr& condition, const fretish::Domain& domain,
                                 const State& state);

// The state assigns every declared variable a value of its type within its bounds (enum
// values among the literals) and satisfies every assumption.
bool satisfies_domain(const fretish::Domain& domain, const State& state);

}  // namespace uabt::smt
