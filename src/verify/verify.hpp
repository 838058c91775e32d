#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"

namespace uabt::verify {

// Terrain coverage of one adaptable node (DESIGN §5): how the domain's discrete state space
// is split among the alternatives. Exact when `counted`; otherwise `not_counted_reason` says
// why (a real variable, or more than 2^24 discrete states).
struct AlternativeCoverage {
  std::string name;                  // alternative
  std::string requirement;           // requirement id
  std::uint64_t states = 0;          // states in which this alternative is the one selected
  std::uint64_t enabled_states = 0;  // states in which its guard holds
  bool reachable = true;  // some state selects it (decided by the solver, also when uncounted)
};

struct Coverage {
  std::string adaptable;
  bool counted = false;
  std::string not_counted_reason;
  std::uint64_t states = 0;                       // size of the domain (states satisfying D)
  std::vector<AlternativeCoverage> alternatives;  // priority order, default last
  std::uint64_t gap_states = 0;                   // no guard holds
  std::uint64_t overlap_states = 0;               // two or more non-default guards hold
  std::vector<std::string> gap_region;            // the uncovered region as a few readable cubes
  std::vector<std::string> variables;             // the variables the guards range over
};

struct Options {
  bool allow_overlap = false;   // guard-overlap becomes a warning
  unsigned timeout_ms = 10000;  // per solver query; unknown → verification-inconclusive
  unsigned threads = 0;         // 0: one per core
};

struct Statistics {
  std::uint64_t solver_queries = 0;
  std::uint64_t prefiltered = 0;  // questions answered without the solver
};

struct Result {
  std::vector<Finding> findings;   // verify-stage findings only (not the loader's)
  std::vector<Coverage> coverage;  // one per adaptable node, mission order
  Statistics statistics;
};

// Guard verification of every adaptable node of a loaded mission (DESIGN §5).
Result verify_mission(const load::Mission& mission, const Options& options);

}  // namespace uabt::verify
