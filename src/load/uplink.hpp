#pragma once
// The requirement half of an uplink merge (ARCHITECTURE §11): the package's optional uplink.json,
// placement and removal, and the record of where each requirement went.
#include <filesystem>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/requirement.hpp"
#include "load/mission.hpp"

namespace uabt::load {

// uplink.json: {"place": {"Storm": {"before": "Req2"}}, "remove": ["Req3"],
//               "retire": {"HammerPower": "reason"}, "weaken": {"LandSoon": "reason"}}
struct Placement {
  std::string requirement, relation, anchor;  // relation: "before" | "after"
  SourceLocation location;                    // the "Storm" key
  SourceLocation anchor_location;             // the "Req2" value
};
struct Removal {
  std::string requirement;
  SourceLocation location;
};
struct UplinkPlan {
  std::vector<Placement> place;  // in file order
  std::vector<Removal> remove;
  std::vector<GuaranteeConsent> consent;  // "retire" and "weaken", in file order
};

// Reads `path` (shown as `shown`). Every mistake is an `uplink-invalid` finding with its line
// and column; what could be read is kept so that one mistake gives one finding.
UplinkPlan read_uplink_plan(const std::filesystem::path& path, const std::string& shown,
                            std::vector<Finding>& findings);

// Merges a package's requirements onto `m.requirements`: removals, then each incoming
// requirement (an existing id is replaced in place, a new one appended), then placements.
// Unknown ids are `uplink-invalid` errors with the closest ids as a "did you mean" note.
// Appends one UplinkMerge per requirement to `m.merges`.
void merge_requirements(Mission& m, std::vector<fretish::Requirement> incoming,
                        const UplinkPlan& plan, const std::string& package);

// Once the merged set is classified: fills each record's adaptable node and priority, refuses
// a placement across adaptable nodes, and reports each record as an `uplink-merge` note.
void describe_merges(Mission& m);

}  // namespace uabt::load
