// Benchmarks of guard verification (DESIGN §5): the incremental verifier against a naive
// baseline that asks every question of a fresh solver, on synthetic missions whose answers are
// known, and the whole gate on the shipped MSL mission.
#include <benchmark/benchmark.h>

#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <z3++.h>

#include "gate/gate.hpp"
#include "load/mission.hpp"
#include "mission_generator.hpp"
#include "smt/encoder.hpp"
#include "verify/verify.hpp"

namespace {

using uabt::bench::ExpectedFinding;
using uabt::bench::GeneratedMission;
using uabt::bench::GeneratorMode;

// Generated missions live for the whole run in one temporary folder, removed at exit.
class Workspace {
 public:
  Workspace() {
    root_ = std::filesystem::temp_directory_path() / ("uabt-bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(root_);
  }
  ~Workspace() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

Workspace& workspace() {
  static Workspace w;
  return w;
}

struct Loaded {
  GeneratedMission generated;
  std::unique_ptr<uabt::load::Mission> mission;
  std::string error;
};

const Loaded& loaded(int nodes, int alternatives, GeneratorMode mode) {
  static std::map<std::tuple<int, int, int>, Loaded> cache;
  auto key = std::make_tuple(nodes, alternatives, static_cast<int>(mode));
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Loaded l;
  l.generated = uabt::bench::generate_mission(workspace().root(), nodes, alternatives, mode);
  if (auto m = uabt::load::load_mission(l.generated.dir, {}, l.error)) {
    l.mission = std::make_unique<uabt::load::Mission>(std::move(*m));
    if (!l.mission->findings.empty())
      l.error = "loader finding: " + l.mission->findings.front().check + ": " +
                l.mission->findings.front().message;
  }
  return cache.emplace(key, std::move(l)).first->second;
}

GeneratorMode mode_for(int nodes, int alternatives) {
  return nodes >= 3 && alternatives >= 4 ? GeneratorMode::planted : GeneratorMode::partition;
}

// "" when the findings are exactly the expected ones (requirements compared as sets).
std::string check_findings(const std::vector<uabt::Finding>& findings,
                           const std::vector<ExpectedFinding>& expected) {
  std::multiset<std::string> want, got;
  for (const auto& e : expected) {
    std::string s = e.check + "@" + e.adaptable;
    if (e.check != "guard-gap")
      for (const auto& r : e.requirements) s += " " + r;
    want.insert(s);
  }
  for (const auto& f : findings) {
    std::string s = f.check + "@" + f.adaptable;
    if (f.check != "guard-gap") {
      auto reqs = f.requirements;
      std::sort(reqs.begin(), reqs.end());
      for (const auto& r : reqs) s += " " + r;
    }
    got.insert(s);
  }
  if (want == got) return "";
  std::string msg = "findings differ; got:";
  for (const auto& s : got) msg += " [" + s + "]";
  msg += " want:";
  for (const auto& s : want) msg += " [" + s + "]";
  return msg;
}

void BM_Verify(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  const Loaded& l = loaded(n, k, mode_for(n, k));
  if (!l.mission) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  uabt::verify::Options options;
  uabt::verify::Result result;
  for (auto _ : state) {
    result = uabt::verify::verify_mission(*l.mission, options);
    benchmark::DoNotOptimize(result);
  }
  if (!l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
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

// The answers the naive baseline finds, per kind.
struct NaiveAnswers {
  std::uint64_t queries = 0;
  int overlaps = 0, gaps = 0, shadowed = 0, unsatisfiable = 0, inconsistent = 0;
};

// One fresh solver per question, loaded with D, asked whether `formula` is satisfiable.
bool naive_sat(uabt::smt::Encoder& encoder,
               const std::vector<uabt::smt::Encoder::DomainPart>& parts, const z3::expr& formula,
               NaiveAnswers& answers) {
  z3::solver solver(encoder.context());
  for (const auto& p : parts) solver.add(p.constraint);
  solver.add(formula);
  ++answers.queries;
  return solver.check() == z3::sat;
}

NaiveAnswers naive_verify(const uabt::load::Mission& mission) {
  NaiveAnswers answers;
  for (const auto& site : mission.adaptables) {
    uabt::smt::Encoder encoder(mission.domain);
    std::vector<uabt::Finding> findings;
    const auto parts = encoder.domain_parts(findings);
    auto& ctx = encoder.context();
    if (!naive_sat(encoder, parts, ctx.bool_val(true), answers)) {
      ++answers.inconsistent;
      continue;
    }
    std::vector<z3::expr> guards;
    bool has_default = false;
    for (const auto* r : mission.selections_for(site.id)) {
      if (!r->guard) {
        has_default = true;
        continue;
      }
      auto g = encoder.lower_condition(*r->guard, r->guard_location, findings);
      if (g) guards.push_back(*g);
    }
    z3::expr higher = ctx.bool_val(false);
    for (std::size_t i = 0; i < guards.size(); ++i) {
      if (!naive_sat(encoder, parts, guards[i], answers)) {
        ++answers.unsatisfiable;
      } else if (i > 0 && !naive_sat(encoder, parts, guards[i] && !higher, answers)) {
        ++answers.shadowed;
      }
      higher = higher || guards[i];
      for (std::size_t j = 0; j < i; ++j)
        if (naive_sat(encoder, parts, guards[j] && guards[i], answers)) ++answers.overlaps;
    }
    if (!has_default && naive_sat(encoder, parts, !higher, answers)) ++answers.gaps;
  }
  return answers;
}

void BM_NaiveVerify(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  const Loaded& l = loaded(n, k, mode_for(n, k));
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  NaiveAnswers answers;
  for (auto _ : state) {
    answers = naive_verify(*l.mission);
    benchmark::DoNotOptimize(answers);
  }
  int want_overlaps = 0, want_gaps = 0, want_shadowed = 0;
  for (const auto& e : l.generated.expected) {
    want_overlaps += e.check == "guard-overlap";
    want_gaps += e.check == "guard-gap";
    want_shadowed += e.check == "guard-shadowed";
  }
  if (answers.overlaps != want_overlaps || answers.gaps != want_gaps ||
      answers.shadowed != want_shadowed || answers.unsatisfiable || answers.inconsistent) {
    state.SkipWithError("naive baseline answers differ from the planted findings");
    return;
  }
  state.counters["solver_queries"] = static_cast<double>(answers.queries);
  state.counters["prefiltered"] = 0;
  state.counters["states"] = 0;
}

void BM_Gate(benchmark::State& state) {
  const std::filesystem::path dir =
      std::filesystem::path(UABT_SOURCE_DIR) / "missions/msl_curiosity";
  uabt::gate::Options options;
  bool passed = false;
  std::uint64_t queries = 0, prefiltered = 0, states = 0;
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
    prefiltered = outcome.verification.statistics.prefiltered;
    states = 0;
    for (const auto& c : outcome.verification.coverage) states += c.states;
    benchmark::DoNotOptimize(outcome);
  }
  if (!passed) {
    state.SkipWithError("the MSL mission did not pass the gate");
    return;
  }
  state.counters["solver_queries"] = static_cast<double>(queries);
  state.counters["prefiltered"] = static_cast<double>(prefiltered);
  state.counters["states"] = static_cast<double>(states);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (auto [n, k] : {std::pair{1, 8}, {1, 32}, {1, 128}, {3, 32}, {10, 32}}) b->Args({n, k});
}

BENCHMARK(BM_Verify)->Apply(sizes)->Unit(benchmark::kMillisecond);
// The large sizes take minutes on a 2-core machine: they run only with UABT_BENCH_LARGE=1.
void BM_VerifyLarge(benchmark::State& state) {
  if (!std::getenv("UABT_BENCH_LARGE")) {
    state.SkipWithError("skipped: set UABT_BENCH_LARGE=1 to run");
    for (auto _ : state) {
    }
    return;
  }
  BM_Verify(state);
}
BENCHMARK(BM_VerifyLarge)
    ->Args({100, 32})
    ->Args({1, 2048})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NaiveVerify)
    ->Args({1, 8})
    ->Args({1, 32})
    ->Args({3, 32})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Gate)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
