#pragma once
#include <string>

#include "gate/gate.hpp"

namespace uabt::gate {

// The gate's proof step (ARCHITECTURE §10): when the mission states guarantees and the gate has a
// compiled tree, proves them on it and adds the findings (and the `prove` stage) to the
// outcome's report. A world.json or model error is itself an error finding. The report's
// Proofs section gets every verdict and counterexample, named as `reporting` says.
void add_proofs(Outcome& outcome, const prove::Options& options,
                const ProofReporting& reporting = {});

// `text` with every place "compiled.xml:L:C" of a node of `compiled` (the outcome's compiled
// tree, which `prove` holds in memory) named by the line the user wrote: the node's line in
// mission.xml or an alternative, or the requirement a generated node implements.
std::string at_source(const std::string& text, const Outcome& outcome,
                      const bt::Document& compiled);
// at_source over every text of `result`: its notes (a tick that stops with an error), why the
// symbolic engine was chosen, the vacuity and every reason.
void name_sources(prove::Result& result, const Outcome& outcome, const bt::Document& compiled);

// For a gate that failed before its proof step: the report's Proofs section lists the
// mission's guarantees as not checked, with the reason. Nothing when it states none.
void add_proofs_not_run(Outcome& outcome, const std::string& reason);

}  // namespace uabt::gate
