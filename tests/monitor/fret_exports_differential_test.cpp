// FRET's own exports load as they are, and every requirement in them is monitored with exactly
// the meaning of the past-time formula FRET wrote beside it (semantics.ptExpanded).
#include <gtest/gtest.h>

#include <random>

#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "monitor/monitor.hpp"
#include "monitor_test_support.hpp"

namespace uabt::testing {
namespace {

constexpr int kTraces = 600;

void check_export(const std::string& file, std::size_t expected_requirements) {
  const auto path = fret_reference(file);
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no FRET data";
  const std::string content = read_all(path);
  fretish::Domain domain;
  fretish::ParseResult parsed = fretish::parse_fret_json(content, file, domain);
  fretish::lower_durations(parsed.requirements, domain.tick_seconds, parsed.findings);
  EXPECT_FALSE(has_errors(parsed.findings))
      << (parsed.findings.empty() ? "" : parsed.findings[0].message);
  ASSERT_EQ(parsed.requirements.size(), expected_requirements);
  const nlohmann::json document = nlohmann::json::parse(content);

  monitor::Variables variables;
  for (const fretish::Variable& v : domain.variables) variables.id(v.name);
  const monitor::Resolver resolve = [&](const std::string& name) -> monitor::Resolved {
    if (const auto slot = variables.find(name)) return {monitor::Resolved::Kind::variable, *slot};
    return {};
  };
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> pick(0, 2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<std::size_t> length(1, 30);
  int both_verdicts = 0;
  for (const fretish::Requirement& r : parsed.requirements) {
    std::string formula;
    for (const auto& entry : document["requirements"])
      if (entry["reqid"] == r.id) formula = entry["semantics"]["ptExpanded"].get<std::string>();
    ASSERT_FALSE(formula.empty()) << r.id;
    const PtFormula oracle = PtFormula::parse(formula);
    std::string reason;
    ASSERT_NE(monitor::RequirementMonitor::compile(r, resolve, reason), nullptr)
        << r.id << ": " << reason;
    int violated = 0;
    for (int i = 0; i < kTraces; ++i) {
      // Each trace draws each boolean's density from {0.1, 0.5, 0.9} and each number's range
      // from {0}, {0, 1}, {0, 1, 2}, so that rare conjunctions and equalities occur.
      std::vector<double> density;
      std::vector<int> range;
      for (std::size_t k = 0; k < domain.variables.size(); ++k) {
        density.push_back(0.1 + 0.4 * pick(rng));
        range.push_back(pick(rng));
      }
      std::vector<OracleState> trace(length(rng));
      std::vector<std::vector<monitor::Val>> frames;
      for (auto& state : trace) {
        std::vector<monitor::Val> frame(variables.size());
        for (std::size_t k = 0; k < domain.variables.size(); ++k) {
          const fretish::Variable& v = domain.variables[k];
          const int slot = *variables.find(v.name);
          if (v.type == fretish::VarType::boolean) {
            const bool b = unit(rng) < density[k];
            state[v.name] = {false, b, 0, false};
            frame[static_cast<std::size_t>(slot)] = monitor::Val::of_bool(b);
          } else {
            const double x = std::uniform_int_distribution<int>(0, range[k])(rng);
            state[v.name] = {true, false, x, false};
            frame[static_cast<std::size_t>(slot)] = monitor::Val::of_number(x);
          }
        }
        frames.push_back(std::move(frame));
      }
      const std::vector<bool> expected = oracle.evaluate(trace);
      auto run = monitor::RequirementMonitor::compile(r, resolve, reason);
      for (std::size_t t = 0; t < trace.size(); ++t) {
        const bool got = run->step(frames[t]);
        ASSERT_FALSE(run->failed()) << r.id << ": " << run->error();
        ASSERT_EQ(got, expected[t]) << r.id << " at tick " << t << "\n" << trace_text(trace);
      }
      violated += expected.back() ? 0 : 1;
    }
    both_verdicts += violated > 0 && violated < kTraces ? 1 : 0;
  }
  // The random traces exercise both verdicts (FSM-007 needs five ticks of a rare conjunction;
  // the CLI tests give it a trace that violates it).
  EXPECT_GE(both_verdicts + 1, static_cast<int>(expected_requirements));
}

TEST(MonitorFretExports, LiquidMixer) {
  check_export("LM_reqts_and_vars.json", 12);
}

TEST(MonitorFretExports, FiniteStateMachine) {
  check_export("fsm_reqts_and_vars.json", 13);
}

}  // namespace
}  // namespace uabt::testing
