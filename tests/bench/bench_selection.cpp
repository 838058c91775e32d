// --selection optimized against Algorithm 1's layout (Fig. 4): condition nodes ticked per
// selection (average over the domain's states, and worst case), counted by the compiler and
// checked by ticking both compiled trees in the runtime engine once per cell of every node's
// state space; and compile time. `uabt_bench selection` prints the tables; BM_CompileSelection
// times the compiler.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "../selection_check.hpp"
#include "bench_selection.hpp"
#include "bench_support.hpp"
#include "compile/compile.hpp"

namespace uabt::bench {

namespace {

using Clock = std::chrono::steady_clock;

compile::Result compile_as(const load::Mission& m, compile::SelectionStyle style) {
  compile::Options options;
  options.selection = style;
  options.selection_forced = true;
  return compile::compile_mission(m, options);
}

// Median wall time of compiling the mission `runs` times.
double compile_ms(const load::Mission& m, compile::SelectionStyle style, int runs) {
  std::vector<double> times;
  for (int i = 0; i < runs; ++i) {
    const auto start = Clock::now();
    const compile::Result r = compile_as(m, style);
    benchmark::DoNotOptimize(r.document.trees.size());
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

struct Totals {
  int nodes = 0, optimized = 0, eight_plus = 0, half_met = 0, more = 0, engine_checked = 0;
  double worst_ratio = 0;  // optimized / Algorithm 1 average, over nodes with >= 8 alternatives
  std::string mismatch;
};

// Rows for one mission; per node unless `summary_only`.
void mission_rows(const std::string& name, const load::Mission& m, bool summary_only,
                  Totals& totals) {
  const compile::Result fig4 = compile_as(m, compile::SelectionStyle::sequence);
  const compile::Result opt = compile_as(m, compile::SelectionStyle::optimized);
  double a1_sum = 0, opt_sum = 0;
  int a1_worst = 0, opt_worst = 0;
  for (const compile::SelectionStats& s : opt.selection_stats) {
    ++totals.nodes;
    totals.optimized += s.optimized_used ? 1 : 0;
    // The compiler's counts against the engine's, for both trees.
    const auto e1 = testing::engine_count(m, fig4.document, s.adaptable);
    const auto e2 = testing::engine_count(m, opt.document, s.adaptable);
    const bool agree = e1.mismatch.empty() && e2.mismatch.empty() &&
                       std::abs(e1.cost.average - s.algorithm1.average) < 1e-9 &&
                       e1.cost.worst == s.algorithm1.worst &&
                       std::abs(e2.cost.average - s.optimized.average) < 1e-9 &&
                       e2.cost.worst == s.optimized.worst;
    if (agree) {
      ++totals.engine_checked;
    } else if (totals.mismatch.empty()) {
      totals.mismatch = name + "/" + s.adaptable + ": " + e1.mismatch + " " + e2.mismatch;
    }
    const double ratio = s.algorithm1.average > 0 ? s.optimized.average / s.algorithm1.average : 1;
    if (s.optimized.average > s.algorithm1.average + 1e-9) ++totals.more;
    if (s.requirements >= 8) {
      ++totals.eight_plus;
      totals.half_met += ratio <= 0.5 + 1e-9 ? 1 : 0;
      totals.worst_ratio = std::max(totals.worst_ratio, ratio);
    }
    a1_sum += s.algorithm1.average;
    opt_sum += s.optimized.average;
    a1_worst = std::max(a1_worst, s.algorithm1.worst);
    opt_worst = std::max(opt_worst, s.optimized.worst);
    if (!summary_only)
      std::printf("| %s | %s | %zu | %zu | %.2f | %d | %.2f | %d | %.2f | %s |\n", name.c_str(),
                  s.adaptable.c_str(), s.requirements, s.cells, s.algorithm1.average,
                  s.algorithm1.worst, s.optimized.average, s.optimized.worst, ratio,
                  s.optimized_used ? "decision" : ("Fig. 4: " + s.reason).c_str());
  }
  if (summary_only && !opt.selection_stats.empty()) {
    // The generator's node i ranges over (i mod 4): an enum, an integer, a real, an enum and
    // a boolean. One row per kind: the mean of the nodes' averages, the largest worst case.
    static const char* const kinds[] = {"enum", "integer", "real", "enum & boolean"};
    for (int kind = 0; kind < 4; ++kind) {
      double a1 = 0, o = 0;
      int w1 = 0, wo = 0, count = 0, used = 0;
      std::size_t reqs = 0, cells = 0;
      for (std::size_t i = 0; i < opt.selection_stats.size(); ++i) {
        if (static_cast<int>(i % 4) != kind) continue;
        const auto& s = opt.selection_stats[i];
        a1 += s.algorithm1.average;
        o += s.optimized.average;
        w1 = std::max(w1, s.algorithm1.worst);
        wo = std::max(wo, s.optimized.worst);
        used += s.optimized_used ? 1 : 0;
        reqs = s.requirements;
        cells = s.cells;
        ++count;
      }
      if (count == 0) continue;
      std::printf(
          "| %s | %d nodes: %s | %zu | %zu | %.2f | %d | %.2f | %d | %.2f | %d decision |\n",
          name.c_str(), count, kinds[kind], reqs, cells, a1 / count, w1, o / count, wo, o / a1,
          used);
    }
    const double n = static_cast<double>(opt.selection_stats.size());
    std::printf("| %s | all %zu nodes (mean) | | | %.2f | %d | %.2f | %d | %.2f | |\n",
                name.c_str(), opt.selection_stats.size(), a1_sum / n, a1_worst, opt_sum / n,
                opt_worst, opt_sum / a1_sum);
  }
}

}  // namespace

int selection_figures() {
  std::printf(
      "Condition nodes ticked per selection (average over the domain's states, by measure; "
      "worst case), Algorithm 1's layout (Fig. 4) against --selection optimized. Every count "
      "is checked by ticking both compiled trees in the runtime engine in one state of every "
      "cell.\n\n"
      "| mission | node | alternatives | cells | Fig. 4 avg | Fig. 4 worst | optimized avg | "
      "optimized worst | ratio | tree |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  Totals totals;
  std::vector<std::pair<std::string, const load::Mission*>> timed;
  std::vector<std::unique_ptr<load::Mission>> shipped;
  for (const char* name : {"msl_curiosity", "msl_curiosity_paper", "exploration"}) {
    std::string error;
    auto m = load::load_mission(std::string(UABT_SOURCE_DIR) + "/missions/" + name, {}, error);
    if (!m) {
      std::fprintf(stderr, "uabt_bench: %s: %s\n", name, error.c_str());
      return 1;
    }
    shipped.push_back(std::make_unique<load::Mission>(std::move(*m)));
    mission_rows(name, *shipped.back(), false, totals);
    timed.emplace_back(name, shipped.back().get());
  }
  for (const auto& [n, k] : std::vector<std::pair<int, int>>{{1, 32}, {1, 512}, {100, 32}}) {
    const Loaded& l = loaded(n, k, GeneratorMode::partition);
    if (!l.mission || !l.error.empty()) {
      std::fprintf(stderr, "uabt_bench: %s\n", l.error.c_str());
      return 1;
    }
    const std::string name = "generated " + std::to_string(n) + " x " + std::to_string(k);
    if (n == 1) {
      mission_rows(name, *l.mission, false, totals);
    } else {
      // 100 nodes: one row per kind of node (i mod 4), then the mean over all.
      mission_rows(name, *l.mission, true, totals);
    }
    timed.emplace_back(name, l.mission.get());
  }
  std::printf(
      "\nNodes: %d, decision structure used on %d; counts checked against the engine on %d; "
      "nodes where optimized ticks more on average: %d; nodes with >= 8 alternatives: %d, of "
      "which at most half of Fig. 4's average: %d (largest ratio %.3f)\n",
      totals.nodes, totals.optimized, totals.engine_checked, totals.more, totals.eight_plus,
      totals.half_met, totals.worst_ratio);
  if (!totals.mismatch.empty()) std::printf("ENGINE MISMATCH: %s\n", totals.mismatch.c_str());

  std::printf(
      "\nCompile time (median of 5 runs, whole mission, without writing XML):\n\n"
      "| mission | sequence ms | optimized ms | ratio |\n|---|---:|---:|---:|\n");
  for (const auto& [name, m] : timed) {
    const double a = compile_ms(*m, compile::SelectionStyle::sequence, 5);
    const double b = compile_ms(*m, compile::SelectionStyle::optimized, 5);
    std::printf("| %s | %.3f | %.3f | %.1fx |\n", name.c_str(), a, b, a > 0 ? b / a : 0.0);
  }
  return totals.mismatch.empty() && totals.more == 0 ? 0 : 1;
}

namespace {

void BM_CompileSelection(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const bool optimized = state.range(2) != 0;
  const Loaded& l = loaded(n, k, GeneratorMode::partition);
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  compile::Result result;
  for (auto _ : state) {
    result = compile_as(*l.mission, optimized ? compile::SelectionStyle::optimized
                                              : compile::SelectionStyle::sequence);
    benchmark::DoNotOptimize(result.document.trees.size());
  }
  if (!result.ok) state.SkipWithError("the generated mission did not compile");
}

// Args: adaptable nodes, alternatives each, 0 = Fig. 4 / 1 = optimized.
BENCHMARK(BM_CompileSelection)
    ->Args({1, 32, 0})
    ->Args({1, 32, 1})
    ->Args({1, 512, 0})
    ->Args({1, 512, 1})
    ->Args({100, 32, 0})
    ->Args({100, 32, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace uabt::bench
