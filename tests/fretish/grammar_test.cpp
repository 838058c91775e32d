// The grammars themselves: PEGTL's analysis finds no rule that can loop without progress.
#include <gtest/gtest.h>

#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/domain.hpp"
#include "grammar/fretish.hpp"

namespace uabt::testing {
namespace {

TEST(FretishGrammar, AnalyzeFindsNoIssues) {
  EXPECT_EQ(tao::pegtl::analyze<grammar::requirement>(), 0u);
  EXPECT_EQ(tao::pegtl::analyze<grammar::expression_text>(), 0u);
  EXPECT_EQ(tao::pegtl::analyze<grammar::label>(), 0u);
  EXPECT_EQ(tao::pegtl::analyze<grammar::domain_line>(), 0u);
}

template <typename Rule>
bool matches_whole(const std::string& text) {
  tao::pegtl::memory_input in(text, "");
  return tao::pegtl::parse<tao::pegtl::seq<Rule, tao::pegtl::eof>>(in);
}

TEST(FretishGrammar, Tokens) {
  using namespace grammar;
  EXPECT_TRUE(matches_whole<identifier>("OnDust"));
  EXPECT_TRUE(matches_whole<identifier>("a.b_c%d9"));
  EXPECT_TRUE(matches_whole<identifier>("\"quoted id\""));
  EXPECT_TRUE(matches_whole<identifier>("index"));  // starts with the keyword "in"
  EXPECT_TRUE(matches_whole<identifier>("whenx"));
  EXPECT_FALSE(matches_whole<identifier>("in"));
  EXPECT_FALSE(matches_whole<identifier>("SHALL"));
  EXPECT_FALSE(matches_whole<identifier>("ticks"));
  EXPECT_FALSE(matches_whole<identifier>("microseconds"));
  EXPECT_FALSE(matches_whole<identifier>("_x"));
  EXPECT_FALSE(matches_whole<identifier>("9x"));
  EXPECT_TRUE(matches_whole<number>("12"));
  EXPECT_TRUE(matches_whole<number>("0.5"));
  EXPECT_TRUE(matches_whole<number>("1E-3"));
  EXPECT_FALSE(matches_whole<number>("-1"));  // a sign is an operator
  EXPECT_TRUE(matches_whole<kw_unit>("Millisecs"));
  EXPECT_TRUE(matches_whole<kw_unit>("hour"));
  EXPECT_TRUE(matches_whole<label>("FSM-002 :"));
}

}  // namespace
}  // namespace uabt::testing
