// Benchmarks of loading and compiling a large mission (ARCHITECTURE §4): 100 adaptable nodes x 10
// alternatives x 100 BT nodes per alternative = 100,000 nodes in the alternatives' trees.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_support.hpp"
#include "bt/xml_io.hpp"
#include "compile/compile.hpp"

namespace {

using namespace uabt::bench;

std::size_t count_nodes(const uabt::bt::Node& node) {
  std::size_t n = 1;
  for (const auto& child : node.children) n += count_nodes(child);
  return n;
}

std::size_t count_nodes(const uabt::bt::Document& doc) {
  std::size_t n = 0;
  for (const auto& tree : doc.trees) n += count_nodes(tree.root);
  return n;
}

void BM_Load(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const int m = static_cast<int>(state.range(2));
  const Loaded& l = loaded(n, k, GeneratorMode::partition, m);  // generated once, outside
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  for (auto _ : state) {
    std::string error;
    auto mission = uabt::load::load_mission(l.generated.dir, {}, error);
    if (!mission || !mission->findings.empty()) {
      state.SkipWithError("the generated mission does not load cleanly");
      return;
    }
    benchmark::DoNotOptimize(mission);
  }
}

void BM_Compile(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const int m = static_cast<int>(state.range(2));
  const Loaded& l = loaded(n, k, GeneratorMode::partition, m);
  if (!l.mission || !l.error.empty()) {
    state.SkipWithError(l.error.c_str());
    return;
  }
  uabt::compile::Result result;
  std::string xml;
  for (auto _ : state) {
    result = uabt::compile::compile_mission(*l.mission, {});
    xml = uabt::bt::write_document(result.document);
    benchmark::DoNotOptimize(xml);
  }
  if (!result.ok) {
    state.SkipWithError("the generated mission did not compile");
    return;
  }
  state.counters["bt_nodes"] = static_cast<double>(count_nodes(result.document));
  state.counters["xml_bytes"] = static_cast<double>(xml.size());
}

// Args: adaptable nodes, alternatives each, BT nodes per alternative tree.
BENCHMARK(BM_Load)->Args({100, 10, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Compile)->Args({10, 10, 100})->Args({100, 10, 100})->Unit(benchmark::kMillisecond);

}  // namespace
