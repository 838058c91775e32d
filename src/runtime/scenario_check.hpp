// A scenario checked against the mission it drives (DESIGN §8): every state value against
// the domain's declaration (type, range, enum), every name against what the mission reads,
// with "did you mean" for a likely typo.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "load/mission.hpp"
#include "runtime/scenario.hpp"

namespace uabt::runtime {

// The names a scenario may use for one mission (and the uplinks it may receive).
struct ScenarioVocabulary {
  std::map<std::string, fretish::Variable> variables;  // declared domain variables
  std::set<std::string> state;   // every name a condition, script or port reads or writes
  std::set<std::string> leaves;  // the robot's leaves (conditions and actions), by kind

  // Adds a loaded mission: its domain, mission.xml, alternatives and nodes.xml.
  void add(const load::Mission& mission);
  // True when `key` (Drill, or Drill(mode=rotary) as scenarios key one instance) is a leaf.
  bool is_leaf(const std::string& key) const;
};

// " (did you mean 'x'?)" for the closest of `known` within two edits (a third of the name at
// most), "" when none is close.
std::string did_you_mean_hint(const std::string& name, const std::set<std::string>& known);

// What is wrong with `value` for `var` ("is out of its range [0, 15]"), "" when it fits.
std::string misfit(const ScriptValue& value, const fretish::Variable& var);
// "wind = 1000 is out of its range [0, 15] (declared integer at domain.fret:1:1)", "" when
// the value fits.
std::string misfit_message(const std::string& name, const ScriptValue& value,
                           const fretish::Variable& var);

// "file:line:col: error: …" lines, empty when the scenario fits.
std::vector<std::string> check_scenario(const Scenario& scenario,
                                        const ScenarioVocabulary& vocabulary);

}  // namespace uabt::runtime
