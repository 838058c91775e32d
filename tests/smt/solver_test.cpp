// smt::Solver: Z3's SMT core with a watchdog that stops a check once it has run too long.
#include <gtest/gtest.h>

#include <z3++.h>

#include "smt/solver.hpp"

namespace uabt::smt {
namespace {

// Fermat's cubes over positive integers: the SMT core cannot settle it and keeps searching.
z3::expr fermat(z3::context& c) {
  const z3::expr x = c.int_const("x"), y = c.int_const("y"), z = c.int_const("z");
  return x * x * x + y * y * y == z * z * z && x > 0 && y > 0 && z > 0;
}

TEST(Solver, TheWatchdogStopsACheckThatRunsTooLong) {
  z3::context c;
  Solver solver(c, 200);
  solver.push();
  solver.add(fermat(c));
  EXPECT_EQ(solver.check(), z3::unknown);
  EXPECT_EQ(solver.reason_unknown(), "timeout");
  solver.pop();
  // The interrupt does not stick to the context: the next question is answered.
  solver.add(c.int_const("x") > 3);
  EXPECT_EQ(solver.check(), z3::sat);
  EXPECT_EQ(solver.reason_unknown(), "");
}

TEST(Solver, AnInterruptBetweenChecksDoesNotCancelTheNextQuestion) {
  // The watchdog may fire just as a check returns. Interrupting the whole context then left
  // it cancelled, and the next push threw "push canceled" (seen in CI as a verify run that
  // crashed instead of answering).
  z3::context c;
  Solver solver(c, 10000);
  solver.add(c.int_const("x") > 3);
  ASSERT_EQ(solver.check(), z3::sat);
  solver.interrupt();
  EXPECT_NO_THROW(solver.push());
  solver.add(c.int_const("x") < 10);
  EXPECT_EQ(solver.check(), z3::sat);
  EXPECT_NO_THROW(solver.pop());
}

TEST(Solver, AnswersWithAssumptionsAndCores) {
  z3::context c;
  Solver solver(c, 10000);
  const z3::expr a = c.bool_const("a"), b = c.bool_const("b"), n = c.int_const("n");
  solver.add(z3::implies(a, n > 5));
  solver.add(z3::implies(b, n < 3));
  z3::expr_vector both(c);
  both.push_back(a);
  both.push_back(b);
  ASSERT_EQ(solver.check(both), z3::unsat);
  EXPECT_EQ(solver.unsat_core().size(), 2u);
  z3::expr_vector one(c);
  one.push_back(a);
  ASSERT_EQ(solver.check(one), z3::sat);
  EXPECT_GT(solver.model().eval(n, true).get_numeral_int(), 5);
}

TEST(Solver, NoLimitMeansNoWatchdog) {
  z3::context c;
  Solver solver(c, 0);
  solver.add(c.int_const("x") > 3);
  EXPECT_EQ(solver.check(), z3::sat);
}

}  // namespace
}  // namespace uabt::smt
