// Cost of the FRETISH monitors (ARCHITECTURE §10): nanoseconds per requirement per tick for each
// timing, with durations from 1 to 100,000 ticks (the cost must not depend on N), and a
// 10,000-tick trace checked against 200 requirements of every scope, condition and timing.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "monitor/property_set.hpp"

namespace {

using uabt::monitor::Val;

const char* const kTimings[] = {
    "immediately",    "at the next timepoint", "eventually",    "finally", "always",  "never",
    "within N ticks", "for N ticks",           "after N ticks", "until s", "before s"};
const char* const kScopes[] = {"",         "in m ",     "when not in m ", "only in m ",
                               "after m ", "before m ", "only after m ",  "only before m "};
const char* const kConditions[] = {"", "upon c ", "whenever c "};

std::string with_duration(std::string timing, int n) {
  const auto at = timing.find('N');
  if (at != std::string::npos) timing.replace(at, 1, std::to_string(n));
  return timing;
}

std::vector<uabt::fretish::Requirement> parse(const std::string& text) {
  auto parsed = uabt::fretish::parse_requirements_file(text, "bench.fret");
  uabt::fretish::lower_durations(parsed.requirements, {}, parsed.findings);
  if (uabt::has_errors(parsed.findings)) throw std::runtime_error(parsed.findings[0].message);
  return parsed.requirements;
}

// A random trace over `variables` booleans, as frames.
std::vector<std::vector<Val>> random_frames(std::size_t variables, std::size_t ticks) {
  std::mt19937 rng(42);
  std::bernoulli_distribution coin(0.5);
  std::vector<std::vector<Val>> frames(ticks, std::vector<Val>(variables));
  for (auto& frame : frames)
    for (auto& v : frame) v = Val::of_bool(coin(rng));
  return frames;
}

struct Setup {
  uabt::monitor::Variables variables;
  uabt::monitor::Symbols symbols;
};

// One requirement "upon c the sw shall <timing> satisfy p", one tick per iteration.
void BM_MonitorTiming(benchmark::State& state) {
  const std::string timing =
      with_duration(kTimings[state.range(0)], static_cast<int>(state.range(1)));
  const auto requirements = parse("R: in m upon c the sw shall " + timing + " satisfy p\n");
  Setup setup;
  for (const char* n : {"m", "c", "p", "s"}) setup.variables.id(n);
  uabt::monitor::PropertySet set(requirements, {}, {&setup.variables, &setup.symbols, {}});
  const auto frames = random_frames(4, 4096);
  std::uint64_t tick = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(set.step(frames[tick & 4095], tick));
    ++tick;
  }
  state.SetLabel(timing);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MonitorTiming)
    ->ArgsProduct({benchmark::CreateDenseRange(0, 10, 1), {1}})
    ->ArgsProduct({{6, 7, 8}, {10, 1000, 100000}});

// 200 requirements over 20 variables, every scope × condition × timing in turn; the whole
// 10,000-tick trace per iteration.
void BM_MonitorTrace(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  const std::size_t ticks = static_cast<std::size_t>(state.range(1));
  std::string text;
  int i = 0;
  for (int k = 0; k < count; ++k, ++i) {
    const auto v = [&](int offset) { return "v" + std::to_string((k + offset) % 20); };
    std::string timing = with_duration(kTimings[i % 11], 1 + k % 7);
    if (timing == "until s" || timing == "before s")
      timing = timing.substr(0, timing.size() - 1) + v(3);
    std::string scope = kScopes[(i / 11) % 8];
    if (!scope.empty()) scope = scope.substr(0, scope.size() - 2) + v(1) + " ";
    std::string condition = kConditions[(i / 88) % 3];
    if (!condition.empty()) condition = condition.substr(0, condition.size() - 2) + v(2) + " ";
    text += "R" + std::to_string(k) + ": " + scope + condition + "the sw shall " + timing +
            " satisfy " + v(0) + " | !" + v(4) + "\n";
  }
  const auto requirements = parse(text);
  Setup setup;
  for (int k = 0; k < 20; ++k) setup.variables.id("v" + std::to_string(k));
  const auto frames = random_frames(20, ticks);
  for (auto _ : state) {
    uabt::monitor::PropertySet set(requirements, {}, {&setup.variables, &setup.symbols, {}});
    for (std::size_t t = 0; t < ticks; ++t) benchmark::DoNotOptimize(set.step(frames[t], t));
  }
  state.SetItemsProcessed(state.iterations() * count * static_cast<std::int64_t>(ticks));
  state.counters["ns/req/tick"] = benchmark::Counter(
      static_cast<double>(state.iterations() * count * static_cast<std::int64_t>(ticks)),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}
BENCHMARK(BM_MonitorTrace)->Args({200, 10000})->Unit(benchmark::kMillisecond);

}  // namespace
