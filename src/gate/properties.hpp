#pragma once
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "monitor/property_check.hpp"

namespace uabt::gate {

// The observables a run of the mission has (ARCHITECTURE §10): domain variables, condition leaves,
// `<node>.success/.failure/.running` for every node of the mission and of the alternatives a
// requirement selects (by `name` or by ID; a label several nodes share means any of them),
// `<adaptable>` and `<adaptable>.selected`. A label only an unselected alternative has (one an
// uplink retired) is in `not_observable`, with why.
monitor::Observables mission_observables(const load::Mission& m);

// The static checks of the mission's properties (references, types, timing).
std::vector<Finding> check_mission_properties(const load::Mission& m);

}  // namespace uabt::gate
