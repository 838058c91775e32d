#pragma once
// The selection targets a campaign's first runs miss, searched for in the world model `uabt
// prove` explores (ARCHITECTURE §10): an action without a world.json contract may run, succeed or
// fail on any tick and a contract bounds it; the environment may change on any tick what no
// action writes. A target is reached by prove's run to it, replayed as `uabt run` runs it;
// unreachable only when prove shows that no run gets there.
#include <string>

#include "campaign/campaign.hpp"
#include "prove/reach.hpp"

namespace uabt::campaign {

// The goal of reaching `condition` (FRETISH, on the node's variables) at a tick in which the
// node is ticked: its mode and the condition, every variable of the node read so that the
// witness's scenario gives each one a value.
prove::Goal node_goal(const load::Mission& mission, const Model& model, std::size_t node,
                      const std::string& condition, const std::string& id);

// Of a goal prove's search did not reach (any verdict but violated): true where it shows that no
// run reaches it, else false with why it is not decided in `reason` (also set for world.json
// leaving no run). One wording for selection targets and guarantee targets.
bool unreached(const prove::Reach& answer, std::string& reason);

// Searches for each selection target of `c` that no run of its scenarios covers and that the
// domain does not rule out, with prove's world model (options.world, else the unconstrained
// one): adds a scenario for the targets its runs reach (scenarios named "<node>-00", numbered
// by the caller), and says of the others why they are unreachable or not decided.
void reach_in_world(const load::Mission& mission, const Model& model, const Replayer& replayer,
                    const Options& options, Campaign& c);

}  // namespace uabt::campaign
