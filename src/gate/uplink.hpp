#pragma once
#include <filesystem>
#include <string>

#include "gate/gate.hpp"
#include "load/mission.hpp"

namespace uabt::gate {

// `uabt gate MISSION --uplink DIR` (ARCHITECTURE §11): gates `merged` (the mission with the package
// merged by load_mission) and reports, beside the verdict, where the merge put each
// requirement and the behaviour change from `running` (the version on board): per adaptable
// node, which states move from which alternative to which, as `uplink-behaviour-change`
// notes and as `report.uplink`.
Outcome run_uplink_gate(const load::Mission& running, load::Mission merged, const Options& options,
                        const std::string& tool_version);

// Writes `mission` as a mission directory in `dir` (ARCHITECTURE §2 layout, created or emptied of
// an earlier merged mission): mission.xml and the alternatives as read, nodes.xml when the mission
// has one, requirements.fret in merged priority order, domain.fret with the declared variables and
// assumptions. Gating `dir` gives the same verdict and compiled tree as gating the merge. Throws
// std::runtime_error when a file cannot be written.
void write_merged_mission(const load::Mission& mission, const std::filesystem::path& dir);

}  // namespace uabt::gate
