// Model checking (ARCHITECTURE §10) on the peers' benchmark families (prove_families.hpp): the
// whole `uabt prove` after the gate, per size and engine. A run whose verdicts or violation
// ticks differ from the family's known answers fails (SkipWithError); an engine this build
// does not have is skipped with the reason.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "bench_support.hpp"
#include "bt/xml_io.hpp"
#include "gate/gate.hpp"
#include "prove/world_model.hpp"
#include "prove_families.hpp"

namespace {

using namespace uabt;
using namespace uabt::bench;

const char* const kEngines[] = {"explicit", "symbolic"};

struct Gated {
  FamilyMission family;
  std::unique_ptr<load::Mission> mission;
  std::unique_ptr<bt::Document> compiled;
  prove::WorldModel world;
  std::string error;
};

// `variant`: the binary tree's counters; 1 for the re-checked checklist with its assumptions.
const Gated& gated(const std::string& name, int size, int variant) {
  static std::map<std::string, std::unique_ptr<Gated>> cache;
  const std::string key = name + "-" + std::to_string(size) + "-" + std::to_string(variant);
  auto& slot = cache[key];
  if (slot) return *slot;
  slot = std::make_unique<Gated>();
  Gated& g = *slot;
  const auto dir = workspace() / ("prove-" + key);
  g.family = name == "binary"      ? generate_binary_tree(dir, size, variant)
             : name == "preflight" ? generate_preflight(dir, size)
             : name == "recheck"   ? generate_recheck(dir, size, variant != 0)
             : name == "lunar"     ? generate_lunar(dir)
             : name == "disjuncts" ? generate_disjunct_site(dir, size)
             : name == "enum"      ? generate_enum_site(dir, size)
                                   : generate_checklist(dir, size);
  std::string error;
  auto mission = load::load_mission(dir, {}, error);
  if (!mission) {
    g.error = "load: " + error;
    return g;
  }
  gate::Outcome outcome = gate::check_mission(std::move(*mission), {}, "bench");
  if (outcome.compiled_xml.empty() || !outcome.passed()) {
    g.error = "the generated mission does not pass the gate";
    return g;
  }
  std::vector<Finding> findings;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  if (!doc) {
    g.error = "the compiled tree does not read back";
    return g;
  }
  g.mission = std::make_unique<load::Mission>(std::move(*outcome.mission));
  g.compiled = std::make_unique<bt::Document>(std::move(*doc));
  g.world = prove::mission_world(*g.mission);
  return g;
}

// "" when every guarantee gets the family's verdict (and violation tick).
std::string check_answers(const prove::Result& r, const FamilyMission& family) {
  if (r.answers.size() != family.verdicts.size()) return "wrong number of answers";
  for (const prove::Answer& a : r.answers) {
    const auto it = family.verdicts.find(a.requirement);
    if (it == family.verdicts.end()) return "unexpected guarantee " + a.requirement;
    if (it->second != prove::verdict_name(a.verdict))
      return a.requirement + ": " + prove::verdict_name(a.verdict) + ", expected " + it->second;
    const auto tick = family.violation_ticks.find(a.requirement);
    if (tick != family.violation_ticks.end() && a.depth != tick->second)
      return a.requirement + ": violated at tick " + std::to_string(a.depth) + ", expected " +
             std::to_string(tick->second);
  }
  return "";
}

void run_prove(benchmark::State& state, const Gated& g, const char* engine) {
  if (!g.error.empty()) {
    state.SkipWithError(g.error.c_str());
    return;
  }
  prove::Options options;
  options.engine = engine;
  prove::Result result;
  try {
    for (auto _ : state) {
      result = prove::prove(*g.mission, *g.compiled, g.world, options);
      benchmark::DoNotOptimize(result);
    }
  } catch (const std::exception& e) {
    // An engine this build does not have, or one that declines the mission.
    const std::string why = std::string("unsupported: ") + e.what();
    state.SkipWithError(why.c_str());
    return;
  }
  if (const std::string wrong = check_answers(result, g.family); !wrong.empty()) {
    state.SkipWithError(wrong.c_str());
    return;
  }
  state.counters["tree_nodes"] = g.family.tree_nodes;
  state.counters["states"] = static_cast<double>(result.states);
  state.counters["transitions"] = static_cast<double>(result.transitions);
}

// range(0): Fallback-tree nodes, range(1): counters, range(2): engine (0 explicit, 1 symbolic).
void BM_ProveBinaryTree(benchmark::State& state) {
  run_prove(state,
            gated("binary", static_cast<int>(state.range(0)), static_cast<int>(state.range(1))),
            kEngines[state.range(2)]);
}

// range(0): checks N, range(1): engine.
void BM_ProveChecklist(benchmark::State& state) {
  run_prove(state, gated("checklist", static_cast<int>(state.range(0)), 0),
            kEngines[state.range(1)]);
}

// range(0): sensor flags N, range(1): engine.
void BM_ProvePreflight(benchmark::State& state) {
  run_prove(state, gated("preflight", static_cast<int>(state.range(0)), 0),
            kEngines[state.range(1)]);
}

// range(0): sensor flags N, range(1): 1 with the assumptions that a flag once set stays set,
// range(2): engine.
void BM_ProveRecheck(benchmark::State& state) {
  run_prove(state,
            gated("recheck", static_cast<int>(state.range(0)), static_cast<int>(state.range(1))),
            kEngines[state.range(2)]);
}

// range(0): engine.
void BM_ProveLunar(benchmark::State& state) {
  run_prove(state, gated("lunar", 1, 0), kEngines[state.range(0)]);
}

const char* const kWideSelections[] = {"disjuncts", "enum"};

// range(0): 0 a guard of N disjuncts, 1 an enum of N values; range(1): N.
void BM_ProveWideSelection(benchmark::State& state) {
  run_prove(state, gated(kWideSelections[state.range(0)], static_cast<int>(state.range(1)), 0),
            kEngines[0]);
}

// The whole `uabt gate` in process, as the command runs it but for writing the reports: load,
// the checks, the proofs and the test campaign. The gate passes.
void BM_GateWideSelection(benchmark::State& state) {
  const Gated& g = gated(kWideSelections[state.range(0)], static_cast<int>(state.range(1)), 0);
  if (!g.error.empty()) {
    state.SkipWithError(g.error.c_str());
    return;
  }
  std::string wrong;
  for (auto _ : state) {
    std::string error;
    auto mission = load::load_mission(g.family.dir, {}, error);
    if (!mission) {
      wrong = "load: " + error;
      break;
    }
    gate::Options options;
    gate::Outcome outcome = gate::run_gate(std::move(*mission), options, "bench");
    gate::add_test_campaign(outcome, options, "tests");
    if (!outcome.passed() || !outcome.campaign) wrong = "the gate fails, or builds no campaign";
    benchmark::DoNotOptimize(outcome);
  }
  if (!wrong.empty()) state.SkipWithError(wrong.c_str());
}

// The scale checklist's rows: 6,000 and 60,000 disjuncts, 400 and 4,096 enum values.
void wide_selection_sizes(benchmark::internal::Benchmark* b) {
  b->Args({0, 6000})->Args({0, 60000})->Args({1, 400})->Args({1, 4096});
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_ProveWideSelection)->Apply(wide_selection_sizes);
BENCHMARK(BM_GateWideSelection)->Apply(wide_selection_sizes);
BENCHMARK(BM_ProveBinaryTree)
    ->ArgsProduct({{23, 71, 263, 1031, 2055}, {2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProveChecklist)
    ->ArgsProduct({{5, 10, 20, 50, 65}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
// The largest tree: 4 counters, the explicit engine only.
BENCHMARK(BM_ProveBinaryTree)->Args({2055, 4, 0})->Unit(benchmark::kMillisecond);
// The symbolic engine takes minutes beyond N = 10 and on the lunar sortie: explicit only there
// (prove_families.sh measures them as whole processes, with a time limit).
BENCHMARK(BM_ProvePreflight)
    ->ArgsProduct({{10, 20, 50, 100}, {0}})
    ->Args({10, 1})
    ->Unit(benchmark::kMillisecond);
// With the assumptions, the explicit engine offers a flag only their monitor reads at its loosest
// value, and follows once the branches of their reads that meet again, so both are linear in
// states (2 N + 3 with them; 2^N sets of flags seen set when every branch was followed).
BENCHMARK(BM_ProveRecheck)
    ->ArgsProduct({{10, 50, 100}, {0, 1}, {0}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProveLunar)->Arg(0)->Unit(benchmark::kMillisecond);
