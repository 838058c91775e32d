// Throughput of the tick engine (ARCHITECTURE §8) on a 10,002-node tree of built-in nodes whose
// every tick visits 9,002 of them: controls, a decorator, scripts reading and writing the
// blackboard, and a robot condition answered by the simulated world.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bt/xml_io.hpp"
#include "runtime/engine.hpp"
#include "runtime/scenario.hpp"
#include "runtime/world.hpp"

namespace {

// A block of 10 nodes; with x = 0 and OnRocks unset (false) a tick visits 9 of them: the
// first Sequence fails at its ScriptCondition, the second succeeds, the last leaf is skipped.
constexpr const char* kBlock = R"(      <Fallback>
        <Sequence>
          <ScriptCondition code="x &gt; 5"/>
          <AlwaysSuccess/>
        </Sequence>
        <Sequence>
          <Inverter>
            <OnRocks/>
          </Inverter>
          <Script code="y += 1"/>
          <AlwaysSuccess/>
        </Sequence>
        <AlwaysSuccess/>
      </Fallback>
)";

std::string tree_xml(int blocks, const std::string& root = "Sequence") {
  std::string xml =
      "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
      "  <BehaviorTree ID=\"MainTree\">\n    <" +
      root + ">\n      <Script code=\"x := 0; y := 0\"/>\n";
  for (int b = 0; b < blocks; ++b) xml += kBlock;
  xml += "    </" + root +
         ">\n  </BehaviorTree>\n  <TreeNodesModel>\n"
         "    <Condition ID=\"OnRocks\"/>\n  </TreeNodesModel>\n</root>\n";
  return xml;
}

void run_tick_benchmark(benchmark::State& state, const std::string& root) {
  std::vector<uabt::Finding> findings;
  const auto doc = uabt::bt::parse_document(tree_xml(static_cast<int>(state.range(0)), root),
                                            "bench.xml", findings);
  if (!doc) {
    state.SkipWithError("the benchmark tree does not parse");
    return;
  }
  uabt::runtime::SimWorld world(uabt::runtime::parse_scenario("{}", "bench.json"),
                                doc->node_models);
  world.log_conditions(false);
  auto engine = uabt::runtime::Engine::build(*doc, world);
  world.apply_initial(engine.blackboard());
  for (auto _ : state) {
    if (engine.tick() != uabt::runtime::NodeStatus::success) {
      state.SkipWithError("the benchmark tree did not succeed");
      return;
    }
  }
  if (engine.stats().errors != 0) {
    state.SkipWithError("the benchmark tree raised tick errors");
    return;
  }
  state.counters["tree_nodes"] = static_cast<double>(engine.node_count());
  state.counters["node_ticks_per_s"] = benchmark::Counter(
      static_cast<double>(engine.stats().node_ticks), benchmark::Counter::kIsRate);
}

void BM_Tick(benchmark::State& state) {
  run_tick_benchmark(state, "Sequence");
}

// The same tree under a SequenceWithMemory: in BT.CPP 4.10 every block that succeeds yields
// (wake-up signal), so one tick is 1,001 root passes that each resume at the next block. The
// node ticks are those of BM_Tick plus one root tick per pass: the cost of the wake-up loop.
void BM_TickWakeUp(benchmark::State& state) {
  run_tick_benchmark(state, "SequenceWithMemory");
}

BENCHMARK(BM_Tick)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TickWakeUp)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
