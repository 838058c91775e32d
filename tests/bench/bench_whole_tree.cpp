// Benchmark of the whole-tree checks (bb-read-before-write, bb-type-conflict, bb-literal-type,
// script-decided, script-out-of-range) on generated trees of 10,000 to 100,000 nodes: the
// cost must grow linearly with the tree.
#include <benchmark/benchmark.h>

#include <string>

#include "load/mission.hpp"
#include "verify/tree/blackboard_checks.hpp"

namespace {

using uabt::bt::Node;

Node leaf(const std::string& tag, std::vector<std::pair<std::string, std::string>> attributes) {
  Node n;
  n.tag = tag;
  n.attributes = std::move(attributes);
  return n;
}

Node control(const std::string& tag, std::vector<Node> children) {
  Node n;
  n.tag = tag;
  n.children = std::move(children);
  return n;
}

// A mission whose main tree is a Sequence of blocks of 12 nodes each: a Fallback that writes
// an entry on both branches, typed ports that pass it on, a script that reads it, and every
// 100th block a precondition over the domain. One read at the end has no write before it.
uabt::load::Mission generated(int nodes) {
  uabt::load::Mission m;
  m.name = "generated";
  m.layout = "uabt";
  m.tree.file = "mission.xml";
  uabt::fretish::Variable battery;
  battery.name = "battery";
  battery.type = uabt::fretish::VarType::real;
  battery.lower = "0";
  battery.upper = "100";
  m.domain.variables.push_back(battery);
  uabt::bt::NodeModel plan{"Action", "Plan", {{"output_port", "out", "double", "", ""}}, 0, 0, ""};
  uabt::bt::NodeModel follow{
      "Action",
      "Follow",
      {{"input_port", "in", "double", "", ""}, {"input_port", "speed", "double", "", ""}},
      0,
      0,
      ""};
  uabt::bt::NodeModel ready{"Condition", "Ready", {}, 0, 0, ""};
  m.nodes = std::vector<uabt::bt::NodeModel>{plan, follow, ready};
  std::vector<Node> blocks;
  int line = 1;
  for (int b = 0; b * 12 < nodes; ++b) {
    const std::string key = "k" + std::to_string(b % 512);
    std::vector<std::pair<std::string, std::string>> guard;
    if (b % 100 == 0) guard.push_back({"_skipIf", "battery > 50"});
    Node block = control(
        "Sequence",
        {control("Fallback", {control("Sequence", {leaf("Ready", {}),
                                                   leaf("Script", {{"code", key + " := 1"}})}),
                              leaf("Plan", {{"out", "{" + key + "}"}})}),
         leaf("ScriptCondition", {{"code", key + " < 5"}}),
         leaf("Follow", {{"in", "{" + key + "}"}, {"speed", "2.5"}}),
         control("IfThenElse", {leaf("Ready", {}), leaf("AlwaysSuccess", {}),
                                leaf("Script", {{"code", key + " += 1"}})}),
         leaf("Follow", {{"in", "{" + key + "}"}, {"speed", "1"}})});
    block.attributes = guard;
    for (Node* n : {&block}) n->line = ++line;
    blocks.push_back(std::move(block));
  }
  blocks.push_back(leaf("ScriptCondition", {{"code", "never_written > 0"}}));
  uabt::bt::TreeDef main;
  main.id = "MainTree";
  main.file = "mission.xml";
  main.root = control("Sequence", std::move(blocks));
  m.tree.main_tree = "MainTree";
  m.tree.trees.push_back(std::move(main));
  return m;
}

void BM_WholeTree(benchmark::State& state) {
  const uabt::load::Mission m = generated(static_cast<int>(state.range(0)));
  std::vector<uabt::Finding> findings;
  for (auto _ : state) {
    findings = uabt::verify::tree::check_blackboard_and_scripts(m, {});
    benchmark::DoNotOptimize(findings);
  }
  int read_before_write = 0;
  for (const auto& f : findings) read_before_write += f.check == "bb-read-before-write";
  if (read_before_write != 1) state.SkipWithError("expected exactly one bb-read-before-write");
  state.counters["nodes"] = static_cast<double>(state.range(0));
  state.counters["findings"] = static_cast<double>(findings.size());
  state.SetComplexityN(state.range(0));
}

}  // namespace

BENCHMARK(BM_WholeTree)
    ->Arg(10000)
    ->Arg(25000)
    ->Arg(50000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);
