#pragma once
#include <cstdint>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"
#include "load/mission.hpp"

namespace uabt::conform {

struct Options {
  unsigned timeout_ms = 10000;  // per solver query; unknown → verification-inconclusive
};

struct Result {
  std::vector<Finding> findings;  // compiled-*, bt-structure, verification-inconclusive
  std::uint64_t solver_queries = 0;
};

// Translation validation (ARCHITECTURE §6): does `compiled` — uabt's output, the paper's
// generator's, or a hand-edited tree — implement the mission's requirements? No <Adaptable> left;
// outside the selection trees it equals mission.xml; each adaptable node calls a Fallback whose
// branches are, in priority order, [guard equivalent to the requirement's under D, alternative
// equal to its source file]; every SubTree resolves; BT.CPP's load rules hold. Findings are located
// in the compiled file and carry the node path (`navigation/Fallback/Sequence[1]/Inverter[0]`).
Result conform_tree(const load::Mission& mission, const bt::Document& compiled,
                    const Options& options = {});

}  // namespace uabt::conform
