#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <z3++.h>

#include "base/value.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "smt/encoder.hpp"
#include "smt/solver.hpp"

namespace uabt::conform {

enum class Answer { holds, fails, unknown };

// One solver question's answer: for `fails`, a full state (satisfying D) that shows it.
struct Proof {
  Answer answer = Answer::unknown;
  State witness;
  std::string reason;  // why the solver gave up (unknown)
};

// The solver side of conformance: one encoder (one z3 context) per run, D asserted once.
class Prover {
 public:
  Prover(const fretish::Domain& domain, unsigned timeout_ms);
  Prover(const Prover&) = delete;
  Prover& operator=(const Prover&) = delete;

  // Lowers a condition. nullopt when it is ill-typed; `error` then says why.
  std::optional<z3::expr> lower(const fretish::ExprPtr& condition, std::string& error);
  z3::expr truth(bool value) { return encoder_.context().bool_val(value); }
  z3::context& context() { return encoder_.context(); }

  // D ⊨ (a ↔ b)? `fails` comes with a state where they differ.
  Proof equivalent(const z3::expr& a, const z3::expr& b);
  // D ⊨ ¬condition? `fails` comes with a state where the condition holds.
  Proof never(const z3::expr& condition);

  std::uint64_t queries() const { return queries_; }

 private:
  // Keeps every expression the encoder typed alive: its typing is keyed by node address.
  std::vector<fretish::ExprPtr> kept_;
  smt::Encoder encoder_;
  smt::Solver solver_;
  std::uint64_t queries_ = 0;
};

// "OnDust = true, OnRocks = false, battery = 19"
std::string describe(const State& state);

}  // namespace uabt::conform
