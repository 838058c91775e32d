#pragma once
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"

namespace uabt::verify::tree {

// Whole-tree static checks (ARCHITECTURE §13) over the mission tree and every alternative (an
// uplink's included, once merged): each finding at the element or attribute it concerns, with
// the path from its <BehaviorTree> as related locations. Linear in the size of the trees.
std::vector<Finding> check_trees(const load::Mission& mission);

}  // namespace uabt::verify::tree
