#pragma once
// Guarantee targets of a campaign (DESIGN §13): FLIP-style obligations of every guarantee with
// a trigger, solved by the prove engines over world.json and checked by the runtime monitor.
#include "campaign/campaign.hpp"
#include "prove/reach.hpp"

namespace uabt::campaign {

// The mission directory holds a world.json.
bool has_world_file(const load::Mission& mission);

// The goals of the guarantee targets, in target order (a goal's id is its target's id): per
// guarantee with a trigger, the trigger firing, then each atom of its condition and of its
// response true and false, deciding it.
std::vector<prove::Goal> guarantee_goals(const load::Mission& mission);

// Adds the guarantee targets (when options.criteria has Criterion::guarantee) to `c`: their
// verdicts, and the scenarios that reach them, each replayed with the runtime's monitor and
// chosen by greedy set cover; placed before the behaviour changes' scenarios.
void add_guarantee_targets(const load::Mission& mission, const Replayer& replayer,
                           const Options& options, Campaign& c);

}  // namespace uabt::campaign
