#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/requirement.hpp"

namespace uabt::fretish {

// A timing as written: "within 200 ms", "for 3 ticks", "within 5", "until done", "always".
std::string timing_text(const Timing& t);

// Where a requirement is lowered (a mission's properties once its domain is known, the
// requirements `uabt monitor` reads with its --domain), every duration becomes whole ticks,
// once: Timing::ticks. A duration in ticks must be whole; one in a unit of time needs the tick
// period (`tick_seconds`, from `tick 100 ms` in domain.fret) and is rounded up to whole ticks.
// One that cannot be converted is a `property-timing` error at the duration's line and column
// (Timing::unconverted keeps its reason).
void lower_durations(std::vector<Requirement>& requirements, std::optional<double> tick_seconds,
                     std::vector<Finding>& findings);

}  // namespace uabt::fretish
