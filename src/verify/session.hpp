#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <z3++.h>

#include "smt/encoder.hpp"
#include "smt/solver.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::detail {

enum class Answer { sat, unsat, unknown };

// One node's incremental solver: D is asserted once at the base; every question is asked as
// a set of assumption literals inside a Scope that holds only the definitions it needs.
// Definitions kept for the whole node would make every check assign every guard of it (Z3
// satisfies each asserted definition), so K questions over K guards would cost K^3. Counts
// the questions it sends to Z3.
//
// Z3 keeps its tables of literals at the largest size any scope gave them and walks them on
// every check: one question that defines every guard of a node of 2,000 (the default's
// shadowing, the gap) made each of the thousands of questions after it cost twice as much.
// Such a wide question is asked of a second solver, over the same base, so the questions
// about one or two guards stay as cheap as the node's first ones.
class Session {
 public:
  Session(smt::Encoder& encoder, const Options& options, Statistics& statistics);

  smt::Encoder& encoder() { return encoder_; }
  z3::context& context() { return encoder_.context(); }
  Statistics& statistics() { return statistics_; }

  // Asserts `formula` in the current scope.
  void add(const z3::expr& formula);

  // A scope that defines more guards than this at once is wide.
  static constexpr std::size_t kWideScope = 64;

  // Everything asserted while a Scope lives is retracted when it ends. Read models and cores
  // before it does. A wide scope opened outside every other scope is the second solver's:
  // every question until it ends goes there.
  class Scope {
   public:
    explicit Scope(Session& session, bool wide = false);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    Session& session_;
    smt::Solver* outer_;
  };

  Answer check(const std::vector<z3::expr>& assumptions = {});
  z3::model model() const { return solver_->model(); }
  // The solver questions go to now.
  const smt::Solver& solver() const { return *solver_; }
  // The assumptions of the last unsat check that suffice for unsat.
  std::vector<z3::expr> core() const;
  // Why the last check answered unknown ("timeout", "incomplete (theory arithmetic)", …).
  const std::string& reason_unknown() const { return reason_; }

  // A fresh literal asserted (in the current scope) equivalent to `formula`: questions about
  // the formula become assumption sets.
  z3::expr define(const z3::expr& formula, const char* prefix);
  // Asserts `literal` equivalent to `formula` in the current scope.
  void define(const z3::expr& literal, const z3::expr& formula) { add(literal == formula); }
  // A fresh literal that implies `formula`: enough to ask whether the formula is satisfiable.
  z3::expr guard(const z3::expr& formula, const char* prefix);

  // Deletion-based minimisation: the smallest subset of `candidates` (by dropping one at a
  // time) that, with `fixed`, stays unsat. Candidates whose removal makes the answer unknown
  // are kept, so the result is always a correct (if not always minimal) core.
  std::vector<z3::expr> minimise(const std::vector<z3::expr>& fixed,
                                 std::vector<z3::expr> candidates);

 private:
  smt::Encoder& encoder_;
  Statistics& statistics_;
  unsigned timeout_ms_;
  smt::Solver narrow_;
  std::unique_ptr<smt::Solver> wide_;  // made at the first wide scope
  smt::Solver* solver_;                // the one questions go to
  std::vector<z3::expr> base_;         // asserted outside every scope: both solvers hold it
  std::size_t depth_ = 0;              // scopes open
  std::string reason_;
};

}  // namespace uabt::verify::detail
