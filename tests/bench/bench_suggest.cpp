// "Did you mean" on a large vocabulary: the observables of a tree of N named nodes (N x 3
// `<name>.success/.failure/.running`) and Q misspelt references, answered from the one
// NameIndex (base/suggest.hpp), against the baseline every stage used before it: the edit
// distance to every name, per reference.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "base/suggest.hpp"

namespace {

std::vector<std::string> observables(std::int64_t nodes) {
  std::vector<std::string> out;
  for (std::int64_t k = 0; k < nodes; ++k)
    for (const char* suffix : {".success", ".failure", ".running"})
      out.push_back("Hop" + std::to_string(k) + suffix);
  return out;
}

// `Hpo<7k>.running`: a swap, and a number that is no node's for k beyond N/7.
std::vector<std::string> misspelt(std::int64_t queries) {
  std::vector<std::string> out;
  for (std::int64_t k = 0; k < queries; ++k)
    out.push_back("Hpo" + std::to_string(k * 7) + ".running");
  return out;
}

void BM_DidYouMean(benchmark::State& state) {
  const auto names = observables(state.range(0));
  const auto queries = misspelt(state.range(1));
  std::size_t suggested = 0;
  for (auto _ : state) {
    const uabt::NameIndex index(names);
    for (const auto& q : queries) suggested += index.closest(q).size();
  }
  state.counters["suggested"] =
      static_cast<double>(suggested) / static_cast<double>(state.iterations());
}

// The baseline: every reference compared with every name.
void BM_DidYouMeanScan(benchmark::State& state) {
  const auto names = observables(state.range(0));
  const auto queries = misspelt(state.range(1));
  std::size_t suggested = 0;
  for (auto _ : state)
    for (const auto& q : queries)
      for (const auto& n : names)
        if (n != q && uabt::edit_distance(q, n) <= 2) ++suggested;
  state.counters["suggested"] =
      static_cast<double>(suggested) / static_cast<double>(state.iterations());
}

}  // namespace

BENCHMARK(BM_DidYouMean)->Args({50000, 200})->Args({50000, 2000})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DidYouMeanScan)->Args({50000, 200})->Iterations(1)->Unit(benchmark::kMillisecond);
