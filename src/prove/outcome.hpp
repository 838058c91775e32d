#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "gate/gate.hpp"
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

// JSON (`uabt prove --format json`).
std::string result_json(const Result& result, const std::string& mission,
                        const std::string& version);

// The gate's proof step (DESIGN §10): when the mission states guarantees and the gate has a
// compiled tree, proves them on it and adds the findings (and the `prove` stage) to the
// outcome's report. A world.json or model error is itself an error finding.
// The report's Proofs section also gets every verdict and counterexample; `scenario_dir` is
// where the reports put the counterexamples' scenarios (write_reports writes them there as
// counterexamples/<id>.json; "" when they are not written), as the user sees that path.
// `replay` gives the mission path and run options of the replay commands (as the user typed
// them); they go to the Proofs section too.
void add_proofs(gate::Outcome& outcome, const Options& options,
                const std::string& scenario_dir = "", const report::Proofs& replay = {});

// For a gate that failed before its proof step: the report's Proofs section lists the
// mission's guarantees as not checked, with the reason. Nothing when it states none.
void add_proofs_not_run(gate::Outcome& outcome, const std::string& reason);

// What the report shows of a result: `written` maps a requirement id to the path its
// counterexample's scenario is (or will be) written to.
report::Proofs report_proofs(const Result& result,
                             const std::map<std::string, std::string>& written = {});

}  // namespace uabt::prove
