// The test campaign's traps for a response judged after its trigger (Shape::judged): the
// past-time formula equals, at every tick of random traces, the judged ticks computed directly
// from their definition (templates.hpp) over the whole trace.
#include <gtest/gtest.h>

#include <optional>
#include <random>

#include "monitor_test_support.hpp"

namespace uabt::testing {
namespace {

using monitor::ConditionKind;
using monitor::Shape;
using monitor::TimingKind;

struct Tick {
  bool c = false, p = false, s = false, j = false;
};

// Whether timing `shape` judges the response at tick `now` of `trace` (null scope, regular
// condition), straight from the definitions: the latest trigger, and what held since.
bool judged(const Shape& shape, const std::vector<Tick>& trace, std::size_t now) {
  const auto trigger = [&](std::size_t t) { return trace[t].c && (t == 0 || !trace[t - 1].c); };
  // The latest trigger at or before `t`.
  const auto latest = [&](std::size_t t) -> std::optional<std::size_t> {
    for (std::size_t k = t + 1; k-- > 0;)
      if (trigger(k)) return k;
    return std::nullopt;
  };
  const auto all = [&](std::size_t from, std::size_t to, auto pred) {
    for (std::size_t k = from; k <= to; ++k)
      if (!pred(trace[k])) return false;
    return true;
  };
  const auto P = [](const Tick& t) { return t.p; };
  const auto nP = [](const Tick& t) { return !t.p; };
  const std::uint64_t d = shape.duration;
  const bool T = trigger(now);
  const std::optional<std::size_t> before = now == 0 ? std::nullopt : latest(now - 1);
  // `good` fails now for the first time since the latest trigger, at most d ticks after it.
  const auto first_fail = [&](auto good) {
    if (good(trace[now])) return false;
    return T || (before && all(*before, now - 1, good) && now - *before <= d);
  };
  switch (shape.timing) {
    case TimingKind::next: return now > 0 && trigger(now - 1);
    case TimingKind::eventually:
      return trace[now].p && (T || (before && all(*before, now - 1, nP)));
    case TimingKind::within: {
      const auto late = [&](std::size_t t) {
        for (std::size_t k = 0; k + d <= t; ++k)
          if (trigger(k) && all(k, t, nP)) return true;
        return false;
      };
      return first_fail(nP) || (late(now) && (now == 0 || !late(now - 1)));
    }
    case TimingKind::for_ticks: {
      const auto last = latest(now);
      return first_fail(P) || (last && now - *last == d && all(*last, now, P));
    }
    case TimingKind::after:
      return first_fail(nP) || (before && now - 1 - *before == d && all(*before, now - 1, nP));
    case TimingKind::until:
      return !trace[now].s &&
             (T || (before && all(*before, now - 1, [](const Tick& t) { return t.p && !t.s; })));
    case TimingKind::before: {
      const bool open = before && all(*before, now - 1, [](const Tick& t) { return !t.p && !t.s; });
      return (trace[now].p && !trace[now].s && (T || open)) || (trace[now].s && !T && open);
    }
    default: return false;
  }
}

TEST(JudgedTick, TheTrapFormulaIsTheDefinitionOnRandomTraces) {
  std::mt19937 rng(27);
  std::bernoulli_distribution coin(0.45);
  std::uniform_int_distribution<std::size_t> length(1, 18);
  for (TimingKind timing :
       {TimingKind::next, TimingKind::eventually, TimingKind::within, TimingKind::for_ticks,
        TimingKind::after, TimingKind::until, TimingKind::before})
    for (std::uint64_t d : {0u, 1u, 2u, 4u}) {
      Shape shape;
      shape.condition = ConditionKind::regular;
      shape.timing = timing;
      shape.duration = d;
      shape.judged = true;
      monitor::Formula f;
      const int root = monitor::build_requirement_formula(f, shape, monitor::Slots{});
      for (int n = 0; n < 400; ++n) {
        std::vector<Tick> trace(length(rng));
        for (auto& t : trace) t = {coin(rng), coin(rng), coin(rng), coin(rng)};
        monitor::FormulaMonitor run(f, root);
        bool reached = false;
        for (std::size_t t = 0; t < trace.size(); ++t) {
          reached = reached || (trace[t].j && judged(shape, trace, t));
          const bool inputs[5] = {false, trace[t].c, trace[t].p, trace[t].s, trace[t].j};
          ASSERT_EQ(run.step(inputs), !reached)
              << monitor::timing_key(timing) << " " << d << " at tick " << t;
        }
      }
    }
}

}  // namespace
}  // namespace uabt::testing
