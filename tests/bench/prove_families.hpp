#pragma once
// The model-checking benchmark families of the peers (BehaVerify, MoVe4BT), generated as real
// mission directories (mission.xml, domain.fret, requirements.fret, world.json) for
// `uabt prove`.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace uabt::bench {

struct FamilyMission {
  std::filesystem::path dir;
  int tree_nodes = 0;  // BT nodes of the mission's tree (= of the compiled tree)
  // The verdict each guarantee must get, and the tick of a violated one's counterexample.
  std::map<std::string, std::string> verdicts;
  std::map<std::string, std::uint64_t> violation_ticks;
};

// BehaVerify's binary tree: a complete binary tree of `fallback_nodes` Fallback nodes and
// leaves (odd, >= 3) under a KeepRunningUntilFailure root. In left-to-right order the leaves
// alternate between a check `vv_j >= K` (a ScriptCondition) and an action that increments or
// decrements one of `counters` counters vv_j (`vv = vv < 8 ? vv + 1 : vv`), each ending in one tick
// with success or failure, nondeterministically. The counters start at 0 and range over [0, 8].
// Guarantees: `Bounded` (always vv_0 <= 8: proved) and `BelowMax` (always vv_0 < 8: violated at
// tick 8, when the first action has incremented vv_0 eight times).
FamilyMission generate_binary_tree(const std::filesystem::path& dir, int fallback_nodes,
                                   int counters = 3);

// A checklist: a Sequence of N Fallback[IsOk_i, Repair_i] and then Work, under ForceSuccess and
// KeepRunningUntilFailure (3 N + 4 nodes). Repair_i takes 2 or 3 ticks, succeeds (IsOk_i =
// true) or fails (the checklist starts over); Work takes 2 ticks. Every IsOk_i starts false.
// Guarantees: `Ready` (always Work.running -> every IsOk_i: proved) and `NeverWorks` (always
// !Work.running: violated at tick N + 1, when the last repair ends and Work starts).
FamilyMission generate_checklist(const std::filesystem::path& dir, int checks);

}  // namespace uabt::bench
