// The verifier's solver session: a question over many guards at once (the default's
// shadowing, the gap) is asked of a second solver over the same base, so that it does not make
// the thousands of pairwise questions of a large node slower; answers do not depend on where a
// question went.
#include <gtest/gtest.h>

#include <vector>

#include "smt/encoder.hpp"
#include "smt/expr_support.hpp"
#include "verify/session.hpp"

namespace uabt::testing {
namespace {

using verify::detail::Answer;
using verify::detail::Session;

class SessionTest : public ::testing::Test {
 protected:
  fretish::Domain domain_ = domain("integer x in [0, 3000]\n");
  smt::Encoder encoder_{domain_};
  verify::Options options_;
  verify::Statistics statistics_;
  Session session_{encoder_, options_, statistics_};
  z3::expr x_ = encoder_.find_slot("x")->constant;

  void SetUp() override { session_.add(x_ >= 0 && x_ <= 3000); }

  // The window guard x in [i, i + 5], as the node's guards are defined: a literal equivalent to it.
  z3::expr window(int i) { return session_.define(x_ >= i && x_ <= i + 5, "guard"); }

  // A question about one guard in a scope of its own, as the pairwise checks ask it.
  Answer ask_one(int i) {
    Session::Scope scope(session_);
    return session_.check({window(i)});
  }
};

TEST_F(SessionTest, AQuestionOverManyGuardsDoesNotGrowTheSolverOfThePairwiseQuestions) {
  ASSERT_EQ(ask_one(0), Answer::sat);
  const smt::Solver& narrow = session_.solver();
  const std::uint64_t before = narrow.statistic("mk bool var");
  ASSERT_GT(before, 0u);
  {
    // Some state outside all 1,000 windows: the default's question on a node of 1,000 guards.
    Session::Scope scope(session_, 1000 > Session::kWideScope);
    std::vector<z3::expr> none;
    for (int i = 0; i < 1000; ++i) none.push_back(!window(i));
    EXPECT_EQ(session_.check(none), Answer::sat);
    EXPECT_NE(&session_.solver(), &narrow);
  }
  EXPECT_EQ(&session_.solver(), &narrow);
  ASSERT_EQ(ask_one(1), Answer::sat);
  // The narrow solver made the few variables of one more window, not the thousands of the
  // wide question (Z3 keeps its tables at their largest size and walks them on every check).
  EXPECT_LT(narrow.statistic("mk bool var") - before, 50u);
}

TEST_F(SessionTest, AWideQuestionSeesTheBaseAssertedBeforeAndAfterItsSolverIsMade) {
  auto ask_wide = [&](const z3::expr& question) {
    Session::Scope scope(session_, true);
    return session_.check({session_.define(question, "question")});
  };
  EXPECT_EQ(ask_wide(x_ == 3001), Answer::unsat);  // outside the base's range
  EXPECT_EQ(ask_wide(x_ == 7), Answer::sat);
  session_.add(x_ != 7);  // the wide solver exists now: it must learn this too
  EXPECT_EQ(ask_wide(x_ == 7), Answer::unsat);
  EXPECT_EQ(ask_wide(x_ == 8), Answer::sat);
  {
    Session::Scope scope(session_);
    EXPECT_EQ(session_.check({session_.define(x_ == 7, "question")}), Answer::unsat);
  }
}

TEST_F(SessionTest, AWideScopeInsideAnotherScopeStaysWithTheDefinitionsItNeeds) {
  Session::Scope outer(session_);
  const z3::expr low = window(0);  // defined in the narrow solver's scope only
  const smt::Solver& narrow = session_.solver();
  Session::Scope inner(session_, true);
  EXPECT_EQ(&session_.solver(), &narrow);
  EXPECT_EQ(session_.check({low, session_.define(x_ == 4, "question")}), Answer::sat);
  EXPECT_EQ(session_.check({low, session_.define(x_ == 9, "question")}), Answer::unsat);
}

}  // namespace
}  // namespace uabt::testing
