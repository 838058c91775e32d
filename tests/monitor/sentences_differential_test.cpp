// FRETISH as written: every scope, condition and timing phrase goes through the parser,
// FRET's classification and the monitor, and must give FRET's formula for its key at every tick.
#include <gtest/gtest.h>

#include <random>

#include "fretish/parse.hpp"
#include "monitor/monitor.hpp"
#include "monitor_test_support.hpp"

namespace uabt::testing {
namespace {

struct Phrase {
  std::string text;
  std::string key;
};

const std::vector<Phrase> kScopes = {
    {"", "null"},
    {"in m, ", "in"},
    {"during m ", "in"},
    {"when in m ", "in"},
    {"if in mode m ", "in"},
    {"in m mode ", "in"},
    {"while m ", "in"},
    {"when not in m ", "notin"},
    {"if not in m ", "notin"},
    {"unless in m ", "notin"},
    {"except in m ", "notin"},
    {"except while m ", "notin"},
    {"only in m ", "onlyIn"},
    {"only during m ", "onlyIn"},
    {"only while m ", "onlyIn"},
    {"after m ", "after"},
    {"before m ", "before"},
    {"only after m ", "onlyAfter"},
    {"only before m ", "onlyBefore"},
};

const std::vector<Phrase> kConditions = {
    {"", "null"},
    {"upon c ", "regular"},
    {"when c, ", "regular"},
    {"if c is true ", "regular"},
    {"where c ", "regular"},
    {"unless c is false ", "regular"},
    {"whenever c ", "holding"},
};

const std::vector<Phrase> kTimings = {
    {"immediately ", "immediately"},
    {"initially ", "immediately"},
    {"at the first timepoint ", "immediately"},
    {"at the same timepoint ", "immediately"},
    {"at the next timepoint ", "next"},
    {"eventually ", "eventually"},
    {"", "null"},
    {"finally ", "finally"},
    {"at the last timepoint ", "finally"},
    {"always ", "always"},
    {"never ", "never"},
    {"within 3 ticks ", "within"},
    {"for 3 ticks ", "for"},
    {"after 3 ticks ", "after"},
    {"until s ", "until"},
    {"before s ", "before"},
};

monitor::Resolved resolve(const std::string& name) {
  static const std::vector<std::string> names = {"m", "c", "p", "s"};
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return {monitor::Resolved::Kind::variable, static_cast<int>(i)};
  return {};
}

TEST(MonitorSemantics, EveryPhraseMeansItsFretTemplate) {
  if (!std::filesystem::exists(fret_reference("semantics.json"))) GTEST_SKIP() << "no FRET data";
  const nlohmann::json semantics = fret_semantics();
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::size_t> length(1, 20);
  int checked = 0;
  for (const Phrase& scope : kScopes) {
    for (const Phrase& condition : kConditions) {
      for (const Phrase& timing : kTimings) {
        const std::string sentence =
            scope.text + condition.text + "the sw shall " + timing.text + "satisfy p";
        const fretish::ParseResult parsed =
            fretish::parse_requirements_file("X: " + sentence + "\n", "r.fret");
        ASSERT_EQ(parsed.requirements.size(), 1u) << sentence;
        std::string reason;
        auto monitor =
            monitor::RequirementMonitor::compile(parsed.requirements[0], resolve, {}, reason);
        ASSERT_NE(monitor, nullptr) << sentence << ": " << reason;
        const std::string key =
            scope.key + "," + condition.key + "," + timing.key + ",satisfaction";
        EXPECT_EQ(std::string(monitor::scope_key(monitor->shape().scope)) + "," +
                      monitor::condition_key(monitor->shape().condition),
                  scope.key + "," + condition.key)
            << sentence;
        const PtFormula oracle = PtFormula::parse(instantiate(
            semantics.at(key).at("ptExpanded").get<std::string>(), {{"scope_mode", "m"},
                                                                    {"regular_condition", "c"},
                                                                    {"post_condition", "p"},
                                                                    {"stop_condition", "s"},
                                                                    {"duration", "3"}}));
        for (int i = 0; i < 12; ++i) {
          const auto trace = random_boolean_trace(rng, {"m", "c", "p", "s"}, length(rng));
          const std::vector<bool> expected = oracle.evaluate(trace);
          auto run =
              monitor::RequirementMonitor::compile(parsed.requirements[0], resolve, {}, reason);
          for (std::size_t t = 0; t < trace.size(); ++t) {
            std::vector<monitor::Val> frame;
            for (const char* n : {"m", "c", "p", "s"})
              frame.push_back(monitor::Val::of_bool(trace[t].at(n).truth));
            const bool got = run->step(frame);
            ASSERT_FALSE(run->failed()) << run->error();
            ASSERT_EQ(got, expected[t]) << sentence << " at tick " << t << "\n"
                                        << trace_text(trace);
          }
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, static_cast<int>(kScopes.size() * kConditions.size() * kTimings.size()));
}

TEST(MonitorClassify, WhatHasNoMeaningOnATraceIsNamed) {
  const auto reason_for = [](const std::string& sentence, std::optional<double> tick = {}) {
    const fretish::ParseResult parsed =
        fretish::parse_requirements_file("X: " + sentence + "\n", "r.fret");
    EXPECT_EQ(parsed.requirements.size(), 1u) << sentence;
    if (parsed.requirements.empty()) return std::string();
    return monitor::classify(parsed.requirements[0], tick).reason;
  };
  EXPECT_EQ(reason_for("the sw shall with probability > 0.9 always satisfy p"),
            "probability 'with probability > 0.9': a run has no probability");
  EXPECT_EQ(reason_for("\"The rover is safe.\""),
            "freeform requirement: FRET does not formalize it");
  EXPECT_EQ(reason_for("the sw shall within 2 seconds satisfy p"),
            "timing 'within 2 seconds' is not in ticks and the domain declares no tick period "
            "(e.g. 'tick 100 ms' in domain.fret)");
  EXPECT_EQ(reason_for("the sw shall within 2 seconds satisfy p", 0.1), "");
  EXPECT_EQ(reason_for("the sw shall within 2.5 ticks satisfy p"),
            "timing 'within 2.5 ticks' is not a whole number of ticks");
}

TEST(MonitorClassify, DurationsInOtherUnitsRoundUpToTicks) {
  const auto ticks = [](const std::string& timing, double period) {
    const fretish::ParseResult parsed =
        fretish::parse_requirements_file("X: the sw shall " + timing + " satisfy p\n", "r.fret");
    EXPECT_EQ(parsed.requirements.size(), 1u) << timing;
    if (parsed.requirements.empty()) return std::uint64_t{0};
    const auto c = monitor::classify(parsed.requirements[0], period);
    EXPECT_TRUE(c.shape) << c.reason;
    return c.shape ? c.shape->duration : std::uint64_t{0};
  };
  EXPECT_EQ(ticks("within 2 seconds", 0.1), 20u);
  EXPECT_EQ(ticks("within 250 milliseconds", 0.1), 3u);
  EXPECT_EQ(ticks("for 300 millisecs", 0.1), 3u);
  EXPECT_EQ(ticks("after 1 minute", 2.0), 30u);
  EXPECT_EQ(ticks("within 7 ticks", 0.1), 7u);
}

}  // namespace
}  // namespace uabt::testing
