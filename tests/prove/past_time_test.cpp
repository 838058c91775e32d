// The model checker's past-time state equals the monitoring stage's FormulaMonitor.
#include <gtest/gtest.h>

#include <random>

#include "monitor/formula.hpp"
#include "monitor/templates.hpp"
#include "prove/past_time.hpp"

namespace uabt::testing {
namespace {

using namespace monitor;

TEST(PastTime, EqualsTheMonitorOnRandomTracesOfEveryShape) {
  const ScopeKind scopes[] = {ScopeKind::null,       ScopeKind::in,         ScopeKind::notin,
                              ScopeKind::only_in,    ScopeKind::after,      ScopeKind::before,
                              ScopeKind::only_after, ScopeKind::only_before};
  const ConditionKind conditions[] = {ConditionKind::null, ConditionKind::regular,
                                      ConditionKind::holding};
  const TimingKind timings[] = {
      TimingKind::immediately, TimingKind::next,  TimingKind::eventually, TimingKind::finally,
      TimingKind::always,      TimingKind::never, TimingKind::within,     TimingKind::for_ticks,
      TimingKind::after,       TimingKind::until, TimingKind::before};
  std::mt19937 rng(17);
  int shapes = 0;
  for (ScopeKind s : scopes)
    for (ConditionKind c : conditions)
      for (TimingKind t : timings) {
        Shape shape{s, c, t, 2};
        Formula f;
        const int root = build_requirement_formula(f, shape, Slots{});
        FormulaMonitor reference(f, root);
        prove::PastTimeLayout layout(f, root);
        auto state = layout.initial();
        std::vector<char> scratch;
        for (int tick = 0; tick < 40; ++tick) {
          bool inputs[4];
          for (bool& b : inputs) b = rng() % 3 != 0;
          ASSERT_EQ(layout.step(inputs, state, scratch), reference.step(inputs))
              << scope_key(s) << "," << condition_key(c) << "," << timing_key(t) << " tick "
              << tick;
        }
        ++shapes;
      }
  EXPECT_EQ(shapes, 8 * 3 * 11);
}

}  // namespace
}  // namespace uabt::testing
