#pragma once
// What the benchmarks and the command-line modes of uabt_bench share: generated missions
// (cached, in one temporary folder removed at exit), the check of the verifier's answers
// against the planted findings, and the naive baseline.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "mission_generator.hpp"

namespace uabt::bench {

struct Loaded {
  GeneratedMission generated;
  std::unique_ptr<load::Mission> mission;
  std::string error;  // "" when the mission loaded without a finding
};

// The folder generated missions are written to (removed when the program ends).
const std::filesystem::path& workspace();

// Generates (once per argument set) and loads a mission.
const Loaded& loaded(int nodes, int alternatives, GeneratorMode mode, int tree_nodes = 1);

// Planted when the size allows it (N >= 3, K >= 4), a partition otherwise.
GeneratorMode mode_for(int nodes, int alternatives);

// "" when the findings are exactly the expected ones (requirements compared as sets).
std::string check_findings(const std::vector<Finding>& findings,
                           const std::vector<ExpectedFinding>& expected);

// How the naive baseline builds its fresh solvers.
enum class NaiveSolver {
  default_strategy,  // z3::solver(context): Z3's default, tactic preprocessing on every check
  smt_core,          // Z3's SMT core, as uabt uses it
};

// The answers the naive baseline finds, per kind.
struct NaiveAnswers {
  std::uint64_t queries = 0;
  int overlaps = 0, gaps = 0, shadowed = 0, unsatisfiable = 0, inconsistent = 0;
};

// Every question of ARCHITECTURE §5 asked of a fresh solver loaded with D: consistency, each guard
// satisfiable, each guard shadowed by the disjunction of those before it, every pair for
// overlap, the gap.
NaiveAnswers naive_verify(const load::Mission& mission, NaiveSolver solver);

// "" when the naive answers match the planted findings.
std::string check_naive(const NaiveAnswers& answers, const std::vector<ExpectedFinding>& expected);

}  // namespace uabt::bench
