#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace uabt::bench {

// How the guards of a synthetic mission are laid out.
enum class GeneratorMode {
  partition,  // every node: K-1 pairwise disjoint guards plus a default, no finding
  planted,    // as partition, with one overlap, one gap and one shadowed guard planted
  real,       // a partition where every node ranges over a real variable (intervals)
  real_sum,   // a partition where every node's guards bound r + s (two reals: polygons)
};

// A finding the verifier must report for a planted mission.
struct ExpectedFinding {
  std::string check;
  std::string adaptable;
  std::vector<std::string> requirements;  // sorted
};

struct GeneratedMission {
  std::filesystem::path dir;
  std::vector<ExpectedFinding> expected;  // empty for a partition
};

// Writes a mission with `nodes` adaptable nodes of `alternatives` alternatives each under
// `parent` (which must exist). Node i ranges over, by i mod 4: an enumeration of K literals,
// a bounded integer, a bounded real, an enumeration conjoined with a boolean. Planted missions
// need nodes >= 3 and alternatives >= 4: node 0 gets an overlap, node 1 a gap (no default),
// node 2 a shadowed guard (which also overlaps the guard that hides it).
// Each alternative's tree has `tree_nodes` BT nodes (a Sequence of tree_nodes - 1 leaves; 1 is
// a lone leaf), for compile and load benchmarks.
GeneratedMission generate_mission(const std::filesystem::path& parent, int nodes, int alternatives,
                                  GeneratorMode mode, int tree_nodes = 1);

}  // namespace uabt::bench
