#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "verify/impact.hpp"

namespace uabt::report {

// `uabt diff` output: per adaptable node, which states change their selected alternative.
// JSON numbers are numbers. A node over real variables gives null counts and its measured
// shares; a space that was neither counted nor measured gives null counts and shares.
std::string impact_text(const verify::Impact& impact);
std::string impact_json(const verify::Impact& impact);

// The node list of impact_json, shared with the gate's report of an uplink.
nlohmann::ordered_json impact_nodes_json(const verify::Impact& impact);

// "20.0% of the space", "33.3% (1/3) of the space": a measured share of a node whose variables
// are not all discrete, in the words of the coverage section.
std::string space_share(const verify::Exact& share);

// One `uplink-behaviour-change` note per adaptable node whose selection changes, located at
// the node in `mission` (the merged version), each move as a note with its count, share and
// example state.
std::vector<Finding> behaviour_change_findings(const verify::Impact& impact,
                                               const load::Mission& mission);

}  // namespace uabt::report
