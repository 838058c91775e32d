// The symbolic engine gives a script condition the engine's meaning: it encodes the one reading
// of the script language (verify/script_reading.hpp), so in every state it is true exactly where
// BT.CPP's script is. Random conditions, each state a ground term Z3 simplifies to its truth.
#include <gtest/gtest.h>

#include <iostream>

#include "prove/symbolic_value.hpp"
#include "script_conditions.hpp"

namespace uabt::prove {
namespace {

using testing::ConditionWriter;
using testing::engine_truth;
using testing::random_state;
using testing::rover_domain;
using testing::State;

TEST(SymbolicScripts, AgreeWithTheEngineOnRandomConditions) {
  const fretish::Domain domain = rover_domain();
  z3::context ctx;
  SymbolCodes codes;
  const int sand = codes.code("sand"), rocks = codes.code("rocks");
  const std::vector<SymType> types{SymType::integer, SymType::real, SymType::symbol};
  const std::vector<std::set<int>> domains{{}, {}, {sand, rocks}};
  const ScriptScope scope{
      [](const std::string& name) {
        return name == "battery" ? 0 : name == "slope" ? 1 : name == "terrain" ? 2 : -1;
      },
      &domain, &types, &domains, &codes};
  ConditionWriter writer(20261203);
  std::mt19937 random(11);
  int compared = 0, declined = 0, disagreements = 0;
  for (int k = 0; k < 1000; ++k) {
    const std::string code = writer.condition(2);
    const runtime::script::Program program = runtime::script::Program::parse(code);
    for (int i = 0; i < 10; ++i) {
      const State s = random_state(random);
      const std::optional<bool> engine = engine_truth(code, s);
      if (!engine) continue;
      std::vector<z3::expr> values{ctx.int_val(static_cast<int64_t>(s.battery)),
                                   real_literal(ctx, s.slope),
                                   ctx.int_val(s.terrain == "sand" ? sand : rocks)};
      try {
        const auto value = run_script(ctx, program, scope, values, ctx.bool_val(true), "test");
        ASSERT_TRUE(value) << code;
        const z3::expr truth = script_truth(*value, "test").simplify();
        ASSERT_TRUE(truth.is_true() || truth.is_false()) << code << ": " << truth;
        ++compared;
        if (truth.is_true() != *engine && ++disagreements <= 5)
          ADD_FAILURE() << code << " in battery=" << s.battery << " slope=" << s.slope
                        << " terrain=" << s.terrain << ": the engine says " << *engine;
      } catch (const SymbolicUnsupported& e) {
        if (++declined <= 5) ADD_FAILURE() << "declined: " << e.what();
      }
    }
  }
  std::cout << "symbolic scripts: " << compared << " states compared, " << declined << " declined, "
            << disagreements << " disagreements\n";
  EXPECT_EQ(disagreements, 0);
  EXPECT_EQ(declined, 0);
  EXPECT_GT(compared, 8000);
}

}  // namespace
}  // namespace uabt::prove
