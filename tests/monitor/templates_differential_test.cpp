// Differential tests: for every scope × condition × timing of FRET's template table, the
// monitor's verdict equals FRET's own past-time formula (ptExpanded, instantiated) at every tick
// of random traces, for several durations.
#include <gtest/gtest.h>

#include <random>

#include "monitor_test_support.hpp"

namespace uabt::testing {
namespace {

using monitor::Formula;
using monitor::FormulaMonitor;
using monitor::Shape;

struct Mismatch {
  std::string what;
  int count = 0;
};

// Runs `shape` against FRET's formula `text` on `traces` random traces; records the first
// mismatch.
void compare(const Shape& shape, const std::string& text, std::mt19937& rng, int traces,
             Mismatch& mismatch) {
  const PtFormula oracle = PtFormula::parse(text);
  Formula f;
  const int root = monitor::build_requirement_formula(f, shape, monitor::Slots{0, 1, 2, 3});
  const std::vector<std::string> names = {"m", "c", "p", "s"};
  std::uniform_int_distribution<std::size_t> length(1, 26);
  for (int i = 0; i < traces; ++i) {
    const auto trace = random_boolean_trace(rng, names, length(rng));
    const std::vector<bool> expected = oracle.evaluate(trace);
    FormulaMonitor run(f, root);
    for (std::size_t t = 0; t < trace.size(); ++t) {
      bool inputs[4];
      for (std::size_t k = 0; k < 4; ++k) inputs[k] = trace[t].at(names[k]).truth;
      const bool got = run.step(inputs);
      if (got != expected[t]) {
        if (mismatch.count++ == 0)
          mismatch.what = "tick " + std::to_string(t) + ": monitor " + (got ? "true" : "false") +
                          ", FRET " + (expected[t] ? "true" : "false") + "\n" + text + "\n" +
                          trace_text(trace);
        return;
      }
    }
  }
}

TEST(MonitorSemantics, EveryFretTemplateAtEveryTick) {
  if (!std::filesystem::exists(fret_reference("semantics.json"))) GTEST_SKIP() << "no FRET data";
  const nlohmann::json semantics = fret_semantics();
  std::mt19937 rng(16);
  int keys = 0;
  for (const auto& [key, entry] : semantics.items()) {
    const auto parts = split_key(key);
    ASSERT_EQ(parts.size(), 4u) << key;
    if (parts[3] != "satisfaction") continue;
    Shape shape = shape_from_key(key);
    const bool timed = parts[2] == "within" || parts[2] == "for" || parts[2] == "after";
    for (std::uint64_t d :
         timed ? std::vector<std::uint64_t>{0, 1, 2, 3, 5} : std::vector<std::uint64_t>{1}) {
      shape.duration = d;
      const std::string text =
          instantiate(entry["ptExpanded"].get<std::string>(), {{"scope_mode", "m"},
                                                               {"regular_condition", "c"},
                                                               {"post_condition", "p"},
                                                               {"stop_condition", "s"},
                                                               {"duration", std::to_string(d)}});
      Mismatch mismatch;
      compare(shape, text, rng, 120, mismatch);
      EXPECT_EQ(mismatch.count, 0) << key << " duration " << d << "\n" << mismatch.what;
    }
    ++keys;
  }
  EXPECT_EQ(keys, 288);
}

// A verdict declared final once violated never comes back: what `uabt run` relies on to report
// a violation at the tick it happens.
TEST(MonitorSemantics, SafetyVerdictsNeverRecover) {
  if (!std::filesystem::exists(fret_reference("semantics.json"))) GTEST_SKIP() << "no FRET data";
  const nlohmann::json semantics = fret_semantics();
  std::mt19937 rng(7);
  int recovering = 0;
  for (const auto& [key, entry] : semantics.items()) {
    Shape shape = shape_from_key(key);
    shape.duration = 2;
    Formula f;
    const int root = monitor::build_requirement_formula(f, shape, monitor::Slots{0, 1, 2, 3});
    bool recovered = false;
    for (int i = 0; i < 300 && !recovered; ++i) {
      const auto trace = random_boolean_trace(rng, {"m", "c", "p", "s"}, 24);
      FormulaMonitor run(f, root);
      bool was_false = false;
      for (const auto& state : trace) {
        const bool in[4] = {state.at("m").truth, state.at("c").truth, state.at("p").truth,
                            state.at("s").truth};
        const bool v = run.step(in);
        if (was_false && v) recovered = true;
        was_false = was_false || !v;
      }
    }
    if (monitor::verdict_is_final_once_violated(shape)) {
      EXPECT_FALSE(recovered) << key << " is declared final once violated but recovers";
    } else {
      recovering += recovered ? 1 : 0;
      EXPECT_TRUE(recovered) << key << " never recovers: it could be reported at once";
    }
  }
  EXPECT_GT(recovering, 0);
}

}  // namespace
}  // namespace uabt::testing
