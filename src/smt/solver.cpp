#include "smt/solver.hpp"

#include <algorithm>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace uabt::smt {

Solver::Solver(z3::context& context, unsigned timeout_ms)
    : context_(context), solver_(context, z3::solver::simple()), timeout_(timeout_ms) {
  if (timeout_ms > 0) watchdog_ = std::jthread([this](std::stop_token stop) { watch(stop); });
}

Solver::~Solver() {
  if (watchdog_.joinable()) {
    watchdog_.request_stop();
    watchdog_.join();
  }
}

void Solver::watch(std::stop_token stop) {
  // Checks do not signal their start (that would cost a thread switch each): the watchdog
  // looks every quarter timeout, and sleeps until the deadline of the check it finds running.
  const auto period = std::max(timeout_ / 4, std::chrono::milliseconds(1));
  std::unique_lock lock(mutex_);
  while (!stop.stop_requested()) {
    if (active_ && !fired_) {
      const auto deadline = started_ + timeout_;
      if (std::chrono::steady_clock::now() >= deadline) {
        fired_ = true;
        interrupt();
        continue;
      }
      wake_.wait_until(lock, stop, deadline, [] { return false; });
    } else {
      wake_.wait_for(lock, stop, period, [] { return false; });
    }
  }
}

void Solver::interrupt() {
  // The solver's own interrupt reaches only a check in progress. The context's would also
  // cancel the context when the check has just returned (the watchdog fires as it ends), and
  // Z3 keeps that flag until the next check: the next push would throw "push canceled".
  Z3_solver_interrupt(context_, solver_);
}

void Solver::begin() {
  reason_.clear();
  if (!watchdog_.joinable()) return;
  std::lock_guard lock(mutex_);
  active_ = true;
  fired_ = false;
  started_ = std::chrono::steady_clock::now();
}

bool Solver::end() {
  if (!watchdog_.joinable()) return false;
  std::lock_guard lock(mutex_);
  active_ = false;
  return fired_;
}

namespace {

std::string without_parentheses(std::string reason) {
  // Z3 wraps some reasons in parentheses: "(incomplete (theory arithmetic))".
  if (reason.size() > 2 && reason.front() == '(' && reason.back() == ')')
    reason = reason.substr(1, reason.size() - 2);
  return reason.empty() ? "unknown" : reason;
}

}  // namespace

z3::check_result Solver::check() {
  z3::expr_vector none(context_);
  return check(none);
}

z3::check_result Solver::check(const z3::expr_vector& assumptions) {
  begin();
  z3::check_result answer = z3::unknown;
  try {
    answer = assumptions.empty() ? solver_.check() : solver_.check(assumptions);
  } catch (...) {
    end();
    throw;
  }
  const bool timed_out = end();
  if (answer == z3::unknown)
    reason_ = timed_out ? "timeout" : without_parentheses(solver_.reason_unknown());
  return answer;
}

std::uint64_t Solver::statistic(const std::string& key) const {
  const z3::stats stats = solver_.statistics();
  for (unsigned i = 0; i < stats.size(); ++i)
    if (stats.key(i) == key)
      return stats.is_uint(i) ? stats.uint_value(i)
                              : static_cast<std::uint64_t>(stats.double_value(i));
  return 0;
}

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);    // glibc's largest: blocks come from the heap
  mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);  // and the heap is not given back
#endif
}

}  // namespace uabt::smt
