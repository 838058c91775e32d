#pragma once
// A campaign scenario played in world.json's world (ARCHITECTURE §13): one deterministic resolution
// of the world model, so that a replay does not show what the contracts rule out.
#include <nlohmann/json_fwd.hpp>

#include "base/value.hpp"
#include "load/mission.hpp"
#include "prove/world_model.hpp"

namespace uabt::campaign {

// `state` (every declared variable valued) changed, where world.json's `initial` or the
// domain's assumptions do not hold in it, in the variables no selection guard reads (those are
// the targets'), to the first combination of nearby values that satisfies both; unchanged when
// none does.
State world_initial(const load::Mission& mission, const prove::WorldModel& world, State state);

// The scenario's "actions": for each action of world.json, its contract's first listed result
// after its fewest ticks, with the effect that result runs (as assignments, computed on
// `initial`) and the outputs it writes.
nlohmann::ordered_json world_actions(const prove::WorldModel& world, const State& initial);

}  // namespace uabt::campaign
