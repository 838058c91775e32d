#pragma once
#include <string>
#include <vector>

#include <z3++.h>

#include "smt/encoder.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::detail {

enum class Answer { sat, unsat, unknown };

// The run's one incremental solver: D is asserted once, and every question is asked as a set
// of assumption literals, so learnt facts carry over from one question to the next. Counts
// the questions it sends to Z3.
class Session {
 public:
  Session(smt::Encoder& encoder, const Options& options, Statistics& statistics);

  smt::Encoder& encoder() { return encoder_; }
  z3::context& context() { return encoder_.context(); }
  Statistics& statistics() { return statistics_; }

  void add(const z3::expr& formula) { solver_.add(formula); }
  void push() { solver_.push(); }
  void pop() { solver_.pop(); }

  Answer check(const std::vector<z3::expr>& assumptions = {});
  z3::model model() const { return solver_.get_model(); }
  // The assumptions of the last unsat check that suffice for unsat.
  std::vector<z3::expr> core() const;
  // Why the last check answered unknown ("timeout", "incomplete (theory arithmetic)", …).
  const std::string& reason_unknown() const { return reason_; }

  // A fresh literal asserted equivalent to `formula`: questions about the formula become
  // assumption sets.
  z3::expr define(const z3::expr& formula, const char* prefix);
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
  z3::solver solver_;
  std::string reason_;
};

}  // namespace uabt::verify::detail
