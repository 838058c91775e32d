// Benchmarks of guard verification (ARCHITECTURE §5): the incremental verifier against a naive
// baseline that asks every question of a fresh solver, on synthetic missions whose answers are
// known, and the whole gate on the shipped MSL mission.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>

#include "bench_support.hpp"
#include "gate/gate.hpp"
#include "verify/verify.hpp"
#include "verify_families.hpp"

namespace {

using namespace uabt::bench;

// Whether a node's shares are exact; coverage before the exact measure had no such field.
template <typename C>
std::uint64_t measured_flag(const C& c) {
  if constexpr (requires { c.measured; })
    return c.measured ? 1 : 0;
  else
    return 0;
}

void BM_Verify(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  const Loaded& l = loaded(n, k, mode_for(n, k));
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  uabt::verify::Options options;
  options.threads = static_cast<unsigned>(state.range(2));
  uabt::verify::Result result;
  for (auto _ : state) {
    result = uabt::verify::verify_mission(*l.mission, options);
    benchmark::DoNotOptimize(result);
  }
  if (auto msg = check_findings(result.findings, l.generated.expected); !msg.empty()) {
    state.SkipWithError(msg.c_str());
    return;
  }
  std::uint64_t states = 0;
  for (const auto& c : result.coverage) states += c.states;
  state.counters["solver_queries"] = static_cast<double>(result.statistics.solver_queries);
  state.counters["prefiltered"] = static_cast<double>(result.statistics.prefiltered);
  state.counters["states"] = static_cast<double>(states);
}

// Real-valued nodes (range(2): 0 intervals over one real, 1 bounds on r + s): the cost of
// measuring the coverage exactly. `measured` counts the nodes whose shares are exact.
void BM_VerifyReal(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  const auto mode = state.range(2) == 0 ? GeneratorMode::real : GeneratorMode::real_sum;
  const Loaded& l = loaded(n, k, mode);
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  uabt::verify::Result result;
  for (auto _ : state) {
    result = uabt::verify::verify_mission(*l.mission, {});
    benchmark::DoNotOptimize(result);
  }
  if (auto msg = check_findings(result.findings, {}); !msg.empty()) {
    state.SkipWithError(msg.c_str());
    return;
  }
  std::uint64_t measured = 0;
  for (const auto& c : result.coverage) measured += measured_flag(c);
  state.counters["solver_queries"] = static_cast<double>(result.statistics.solver_queries);
  state.counters["measured"] = static_cast<double>(measured);
}

void BM_NaiveVerify(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  const auto kind = static_cast<NaiveSolver>(state.range(2));
  const Loaded& l = loaded(n, k, mode_for(n, k));
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  NaiveAnswers answers;
  for (auto _ : state) {
    answers = naive_verify(*l.mission, kind);
    benchmark::DoNotOptimize(answers);
  }
  if (auto msg = check_naive(answers, l.generated.expected); !msg.empty()) {
    state.SkipWithError(msg.c_str());
    return;
  }
  state.counters["solver_queries"] = static_cast<double>(answers.queries);
}

void BM_Gate(benchmark::State& state) {
  const std::filesystem::path dir =
      std::filesystem::path(UABT_SOURCE_DIR) / "missions/msl_curiosity";
  uabt::gate::Options options;
  bool passed = false;
  std::uint64_t queries = 0;
  for (auto _ : state) {
    std::string error;
    auto mission = uabt::load::load_mission(dir, {}, error);
    if (!mission) {
      state.SkipWithError(error.c_str());
      return;
    }
    auto outcome = uabt::gate::run_gate(std::move(*mission), options, "bench");
    passed = outcome.passed();
    queries = outcome.verification.statistics.solver_queries;
    benchmark::DoNotOptimize(outcome);
  }
  if (!passed) {
    state.SkipWithError("the MSL mission did not pass the gate");
    return;
  }
  state.counters["solver_queries"] = static_cast<double>(queries);
}

// One guard of `atoms` atoms on the MSL mission's navigation node. Layout 0: atoms over ten
// integers joined at random by & and | (most end up vacuous: the guard collapses under the
// domain); layout 1: (v0 > c | v1 < d) & (v2 > c | …) over distinct integers, where every atom
// matters and each needs its own question.
std::filesystem::path long_guard_mission(int atoms, int layout) {
  namespace fs = std::filesystem;
  const fs::path dir =
      workspace() / ("long_guard_" + std::to_string(atoms) + "_" + std::to_string(layout));
  if (fs::exists(dir)) return dir;
  fs::copy(fs::path(UABT_SOURCE_DIR) / "missions/msl_curiosity", dir, fs::copy_options::recursive);
  std::string domain = "boolean OnDust, OnRocks\n", guard;
  if (layout == 0) {
    for (int v = 0; v < 10; ++v) domain += "integer v" + std::to_string(v) + " in [0, 20]\n";
    static const char* const kOps[] = {"<", ">", "<=", ">=", "=", "!="};
    unsigned seed = 1;
    auto next = [&seed] { return (seed = seed * 1103515245u + 12345u) >> 16; };
    for (int i = 0; i < atoms; ++i) {
      if (i > 0) guard += next() % 2 ? " & " : " | ";
      guard += "v" + std::to_string(next() % 10) + " " + kOps[next() % 6] + " " +
               std::to_string(next() % 21);
    }
  } else {
    for (int v = 0; v < atoms; ++v) domain += "integer v" + std::to_string(v) + " in [0, 20]\n";
    for (int i = 0; i + 1 < atoms; i += 2)
      guard += std::string(i > 0 ? " & " : "") + "(v" + std::to_string(i) + " > " +
               std::to_string(i % 17) + " | v" + std::to_string(i + 1) + " < " +
               std::to_string(3 + i % 11) + ")";
  }
  std::ofstream(dir / "domain.fret") << domain;
  std::ofstream(dir / "requirements.fret")
      << "Req1: In navigation if OnDust & (" << guard
      << ") Mission shall satisfy selected_alt = on_dust\n"
         "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
         "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  return dir;
}

// Verifies the generated mission at `dir` and counts the findings of `check` as `counter`.
// Loads the mission at `dir` and verifies it once per iteration: the last result, nullopt (the
// run marked failed) when the mission does not load.
std::optional<uabt::verify::Result> verify_each_iteration(benchmark::State& state,
                                                          const std::filesystem::path& dir) {
  std::string error;
  auto mission = uabt::load::load_mission(dir, {}, error);
  if (!mission) {
    state.SkipWithError(error.c_str());
    return std::nullopt;
  }
  uabt::verify::Result result;
  for (auto _ : state) {
    result = uabt::verify::verify_mission(*mission, {});
    benchmark::DoNotOptimize(result);
  }
  state.counters["solver_queries"] = static_cast<double>(result.statistics.solver_queries);
  return result;
}

void verify_generated(benchmark::State& state, const std::filesystem::path& dir,
                      const std::string& check, const char* counter) {
  const auto result = verify_each_iteration(state, dir);
  if (!result) return;
  std::uint64_t counted = 0;
  for (const auto& f : result->findings) counted += f.check == check ? 1 : 0;
  state.counters[counter] = static_cast<double>(counted);
}

void BM_VerifyLongGuard(benchmark::State& state) {
  verify_generated(
      state, long_guard_mission(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))),
      "guard-vacuous-atom", "vacuous");
}

// One adaptable node with `requirements` requirements whose guards are sliding windows
// `x >= i & x <= i + width` over one integer, each its own alternative, and a default: every
// requirement overlaps the `width` next ones, so the node has about requirements × width
// guard-overlap findings, each with a witness and a region.
std::filesystem::path overlapping_mission(int requirements, int width) {
  namespace fs = std::filesystem;
  const fs::path dir =
      workspace() / ("overlapping_" + std::to_string(requirements) + "_" + std::to_string(width));
  if (fs::exists(dir)) return dir;
  fs::create_directories(dir / "alternatives/nav");
  std::ofstream(dir / "domain.fret") << "integer x in [0, " << requirements + width + 10 << "]\n";
  std::ofstream fret(dir / "requirements.fret");
  auto alternative = [&](const std::string& name) {
    std::ofstream(dir / "alternatives/nav" / (name + ".xml"))
        << "<root BTCPP_format=\"4\"><BehaviorTree ID=\"" << name
        << "\"><AlwaysSuccess/></BehaviorTree></root>\n";
  };
  for (int i = 0; i < requirements; ++i) {
    const std::string name = "a" + std::to_string(i);
    fret << "R" << i << ": In nav if x >= " << i << " & x <= " << i + width
         << " Mission shall satisfy selected_alt = " << name << "\n";
    alternative(name);
  }
  fret << "Default: In nav Mission shall satisfy selected_alt = fallback\n";
  alternative("fallback");
  std::ofstream(dir / "mission.xml")
      << "<root BTCPP_format=\"4\" main_tree_to_execute=\"M\"><BehaviorTree ID=\"M\">"
         "<Sequence><Adaptable ID=\"nav\"/></Sequence></BehaviorTree></root>\n";
  return dir;
}

void BM_VerifyOverlapping(benchmark::State& state) {
  verify_generated(
      state,
      overlapping_mission(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))),
      "guard-overlap", "overlaps");
}

// The scale families (verify_families.hpp), family 0 a ported Sequence of N actions, 1 one guard
// of N disjuncts, 2 N real-valued grid guards: verify must report exactly the family's findings.
void BM_VerifyFamily(benchmark::State& state) {
  const int family = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  const std::filesystem::path dir =
      workspace() / ("family_" + std::to_string(family) + "_" + std::to_string(n));
  const VerifyFamily f = family == 0   ? generate_ported_sequence(dir, n)
                         : family == 1 ? generate_disjunct_guard(dir, n)
                                       : generate_real_grid(dir, n);
  const auto result = verify_each_iteration(state, dir);
  if (!result) return;
  std::map<std::string, std::size_t> findings;
  for (const auto& finding : result->findings) ++findings[finding.check];
  if (findings != f.findings) state.SkipWithError("verify's findings are not the family's");
}

// Args: nodes, alternatives, threads (0: one per core).
BENCHMARK(BM_Verify)
    ->Args({1, 8, 0})
    ->Args({1, 32, 0})
    ->Args({1, 128, 0})
    ->Args({3, 32, 0})
    ->Args({10, 32, 0})
    ->Args({10, 32, 1})
    ->Unit(benchmark::kMillisecond);
// The sizes of the issue's targets: a few seconds each.
BENCHMARK(BM_Verify)
    ->Name("BM_VerifyLarge")
    ->Args({100, 32, 0})
    ->Args({100, 32, 1})
    ->Args({1, 2048, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
// Args: nodes, alternatives, layout (0: intervals of one real, 1: bounds on r + s).
BENCHMARK(BM_VerifyReal)
    ->Args({1, 32, 0})
    ->Args({1, 32, 1})
    ->Args({100, 32, 0})
    ->Args({100, 32, 1})
    ->Unit(benchmark::kMillisecond);
// Args: nodes, alternatives, solver (0: Z3's default strategy, 1: the SMT core uabt uses).
BENCHMARK(BM_NaiveVerify)
    ->Args({1, 8, 0})
    ->Args({1, 8, 1})
    ->Args({1, 32, 0})
    ->Args({1, 32, 1})
    ->Args({3, 32, 0})
    ->Args({3, 32, 1})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Gate)->Unit(benchmark::kMillisecond);
// Args: atoms in the guard, layout (see long_guard_mission). Beyond 1,000 atoms a guard's atoms
// are not checked one by one (verification-skipped), so 2,000 counts no vacuous atom.
BENCHMARK(BM_VerifyLongGuard)
    ->Args({400, 0})
    ->Args({2000, 0})
    ->Args({100, 1})
    ->Args({400, 1})
    ->Args({2000, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// Args: requirements on the node, window width (overlaps per requirement).
BENCHMARK(BM_VerifyOverlapping)
    ->Args({100, 5})
    ->Args({100, 200})
    ->Args({2000, 5})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// Args: family (0 a ported Sequence, 1 one guard of disjuncts, 2 a grid of real guards), size:
// the scale checklist's rows.
BENCHMARK(BM_VerifyFamily)
    ->Args({0, 200000})
    ->Args({1, 6000})
    ->Args({2, 2048})
    ->Args({2, 10008})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
