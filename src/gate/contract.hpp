#pragma once
// The mission's guarantees as the contract of the mission (ARCHITECTURE §11): an uplink may change
// what they say only explicitly.
#include "gate/gate.hpp"
#include "load/mission.hpp"

namespace uabt::gate {

// For `merged` (gated, with `running` the version on board): every guarantee of `running` that
// the package restates or removes is proved, as `running` states it, on the merged mission
// (its compiled tree, the same world.json). One it no longer satisfies is an error,
// `uplink-guarantee-weakened` (restated under its id) or `uplink-guarantee-removed`, with its
// counterexample, a warning when uplink.json consents ("retire" / "weaken" with a reason);
// one it still satisfies is a note (`uplink-guarantee-restated`, or removed and still holding),
// and a consent it does not need is `uplink-consent-unneeded`. Fills
// `merged.report.uplink->contract` (which must be set), each guarantee's status before and
// after.
void check_contract(const load::Mission& running, Outcome& merged, const Options& options);

}  // namespace uabt::gate
