#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/requirement.hpp"

namespace uabt::monitor {

// What a property may read, with its type (ARCHITECTURE §10 observables).
struct Observables {
  enum class Type { boolean, number, name };
  std::map<std::string, Type> variables;
  std::set<std::string> literals;  // names that are values: alternatives, none, enum literals
  // Names a property may not read although they look like observables, with the reason
  // (e.g. the last node with that label was in an alternative an uplink retired).
  std::map<std::string, std::string> not_observable;
};

// Static checks of mission properties before a run: every name is an observable or a value
// (`property-reference`, with the closest observables as a note), every part is a boolean and
// relations compare alike (`property-type`), and the timing has a meaning in ticks
// (`property-timing`; a duration that could not be converted was reported where the
// requirements were lowered, fretish/durations.hpp, and is not reported again).
std::vector<Finding> check_properties(const std::vector<fretish::Requirement>& properties,
                                      const Observables& observables);

}  // namespace uabt::monitor
