#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "prove/prove.hpp"
#include "report/proofs.hpp"

namespace uabt::prove {

// The mission's world.json, or the unconstrained world when it has none. Throws WorldError.
WorldModel mission_world(const load::Mission& mission);

// Findings for the report: `prove-violated` and `prove-bounded` errors at the requirement,
// `fretish-unsupported` for a guarantee prove cannot read. `written` maps a requirement id to
// the file its counterexample was written to.
// `replay` gives the mission path and run options of the replay command a note shows.
std::vector<Finding> findings_of(const Result& result,
                                 const std::map<std::string, std::string>& written = {},
                                 const report::Proofs& replay = {});

// The tick-by-tick table of a counterexample, as text lines.
std::vector<std::string> table_lines(const Counterexample& cex);

// `uabt prove --format json`: the tool, mission and verdict around report::proofs_json of
// `proofs` (report_proofs of `result`), the same shape as the proofs in the gate's
// findings.json.
std::string result_json(const Result& result, const report::Proofs& proofs,
                        const std::string& mission, const std::string& version);

// What the report shows of a result: `written` maps a requirement id to the path its
// counterexample's scenario is (or will be) written to.
report::Proofs report_proofs(const Result& result,
                             const std::map<std::string, std::string>& written = {});

}  // namespace uabt::prove
