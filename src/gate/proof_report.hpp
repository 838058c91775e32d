#pragma once
// What the gate and `uabt prove` show of a proof: prove returns plain data, rendered here.
#include <map>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "prove/prove.hpp"
#include "report/proofs.hpp"

namespace uabt::gate {

// Findings for the report: `prove-violated` and `prove-bounded` errors at the requirement,
// `fretish-unsupported` for a guarantee prove cannot read. `written` maps a requirement id to
// the file its counterexample was written to.
// `replay` gives the mission path and run options of the replay command a note shows.
std::vector<Finding> findings_of(const prove::Result& result,
                                 const std::map<std::string, std::string>& written = {},
                                 const report::Proofs& replay = {});

// The tick-by-tick table of a counterexample, as text lines.
std::vector<std::string> table_lines(const prove::Counterexample& cex);

// `uabt prove --format json`: the tool, mission and verdict around report::proofs_json of
// `proofs` (report_proofs of `result`), the same shape as the proofs in the gate's
// findings.json.
std::string result_json(const prove::Result& result, const report::Proofs& proofs,
                        const std::string& mission, const std::string& version);

// What the report shows of one answer of a result of `engine`; its counterexample's scenario
// is (or will be) written to `scenario_file` ("" when it is not written).
report::ProofAnswer report_answer(const prove::Answer& answer, const std::string& engine,
                                  const std::string& scenario_file = "");

// What the report shows of a result: `written` maps a requirement id to the path its
// counterexample's scenario is (or will be) written to.
report::Proofs report_proofs(const prove::Result& result,
                             const std::map<std::string, std::string>& written = {});

}  // namespace uabt::gate
