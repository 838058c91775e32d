#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include <z3++.h>

namespace uabt::smt {

// The solver every stage asks its questions of, with a per-check time limit.
//
// It is Z3's SMT core without the default strategy's preprocessing tactics: the default
// `z3::solver` runs a tactic pipeline on every check made without assumptions and sets itself
// up on the first check, which costs 5 to 17 ms for a handful of boolean guards; the core
// answers the same questions in well under a millisecond, incrementally, with unsat cores.
//
// The time limit is kept by one watchdog thread per solver that interrupts the solver when a
// check has run too long. Z3's own `timeout` parameter hands every check to a timer thread and
// back, which on a busy machine costs more than the small checks the gate makes (measured:
// 30% of the time of 100 nodes x 32 alternatives). A check is interrupted after between
// `timeout` and 1.25 `timeout`.
class Solver {
 public:
  // `timeout_ms` 0: no limit (and no thread).
  Solver(z3::context& context, unsigned timeout_ms);
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  void add(const z3::expr& formula) { solver_.add(formula); }
  void push() { solver_.push(); }
  void pop() { solver_.pop(); }
  z3::check_result check();
  z3::check_result check(const z3::expr_vector& assumptions);
  z3::model model() const { return solver_.get_model(); }
  z3::expr_vector unsat_core() const { return solver_.unsat_core(); }
  // One of the counters Z3 keeps for this solver since it was made ("mk bool var": the
  // Boolean variables it has created, "num checks", …); 0 for one it has not counted.
  std::uint64_t statistic(const std::string& key) const;
  // Stops the check in progress, if any; a no-op between checks. Any thread may call it.
  void interrupt();
  // Why the last check answered unknown: "timeout" when the watchdog stopped it, otherwise
  // Z3's reason without its parentheses ("incomplete (theory arithmetic)", …).
  const std::string& reason_unknown() const { return reason_; }

 private:
  void watch(std::stop_token stop);
  void begin();
  bool end();  // true when the watchdog interrupted the check

  z3::context& context_;
  mutable z3::solver solver_;
  std::chrono::milliseconds timeout_;
  std::string reason_;

  std::mutex mutex_;
  std::condition_variable_any wake_;
  bool active_ = false;  // a check is running
  bool fired_ = false;   // and the watchdog interrupted it
  std::chrono::steady_clock::time_point started_;
  std::jthread watchdog_;  // last: started once everything it reads exists
};

// Keeps freed memory in the process, for programs that make many Z3 contexts (one per
// adaptable node). A context allocates and frees tens of megabytes; by default glibc hands
// large blocks back to the kernel on every free and page-faults them in again for the next
// context (measured: a third of the time of 100 nodes x 32 alternatives). Call once, first
// thing in main.
void keep_freed_memory();

}  // namespace uabt::smt
