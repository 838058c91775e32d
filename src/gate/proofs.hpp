#pragma once
#include <string>
#include <vector>

#include "gate/gate.hpp"

namespace uabt::gate {

// Proving a checked mission, for the gate, its contract and `uabt prove`: the guarantees of
// `mission` (checked.mission, or a copy with other guarantees) on `checked`'s compiled tree as
// read back, in `mission`'s world.json, every message naming the line the user wrote (a node's
// line in mission.xml or an alternative, or the requirement a generated node implements).
// `warnings` gets world.json's warnings before the proof starts. Throws prove::WorldError when
// world.json cannot be used, std::runtime_error when the tree does not read back or prove fails.
prove::Result prove_checked(const Outcome& checked, const load::Mission& mission,
                            const prove::Options& options,
                            std::vector<Finding>* warnings = nullptr);

// The gate's proof step (ARCHITECTURE §10): when the mission states guarantees and the gate has a
// compiled tree, proves them on it and adds the findings (and the `prove` stage) to the
// outcome's report. A world.json or model error is itself an error finding. The report's
// Proofs section gets every verdict and counterexample, named as `reporting` says.
void add_proofs(Outcome& outcome, const prove::Options& options,
                const ProofReporting& reporting = {});

// For a gate that failed before its proof step: the report's Proofs section lists the
// mission's guarantees as not checked, with the reason. Nothing when it states none.
void add_proofs_not_run(Outcome& outcome, const std::string& reason);

}  // namespace uabt::gate
