#pragma once
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "monitor/property_check.hpp"

namespace uabt::gate {

// The observables a run of the mission has (ARCHITECTURE §10): domain variables, condition leaves,
// `<node>.success/.failure/.running` for every node of the trees the run instantiates
// (load::run_trees; by `name` or by ID; a label several nodes share means any of them),
// `<adaptable>` and `<adaptable>.selected`. A label only trees outside the run have (an
// alternative no requirement selects, one an uplink retired, a tree nothing calls) is in
// `not_observable`, with why.
monitor::Observables mission_observables(const load::Mission& m);

// The static checks of the mission's properties (references, types, timing).
std::vector<Finding> check_mission_properties(const load::Mission& m);

}  // namespace uabt::gate
