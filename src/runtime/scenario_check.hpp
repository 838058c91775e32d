// A scenario checked against the mission it drives (ARCHITECTURE §8): every state value against
// the domain's declaration (type, range, enum), every name against what the mission reads,
// with "did you mean" for a likely typo.
#pragma once
#include <map>
#include <optional>
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
  // The ports nodes.xml (or a tree's <TreeNodesModel>) declares, by node ID.
  std::map<std::string, std::vector<bt::Port>> ports;

  // Adds a loaded mission: its domain, mission.xml, alternatives and nodes.xml.
  void add(const load::Mission& mission);
  // True when `key` (Drill, or Drill(mode=rotary) as scenarios key one instance) is a leaf.
  bool is_leaf(const std::string& key) const;
  // What is wrong with `value` as what `action` (Drill, or Drill(mode=rotary)) writes to its
  // output port `port`: not an output (or inout) port nodes.xml declares for it, with "did you
  // mean", or a value of another type than the port's; "" when it fits. `at_value`: the
  // value, not the port's name, is wrong.
  std::string output_misfit(const std::string& action, const std::string& port,
                            const ScriptValue& value, bool& at_value) const;
  // The type declared for what a scenario gives state variable `key`: the domain's; nullopt
  // when the domain does not declare it.
  std::optional<fretish::VarType> state_type(const std::string& key) const;
  // The type of what `action` writes to its output port `port`: the port's type in nodes.xml
  // as a domain type (double a real, int an integer, ...); nullopt when it declares none.
  std::optional<fretish::VarType> output_type(const std::string& action,
                                              const std::string& port) const;
};

// `value`, when a number, as the type `declared` gives it (fretish::number_is_integer): the
// integer 12 becomes the real 12 for a real variable, the real 12.0 the integer 12 for an
// integer one; any other value is left as it is.
void type_number(ScriptValue& value, std::optional<fretish::VarType> declared);
// Every number of `scenario` typed by what it is for: a state value (initial, events,
// effects) by the domain's declaration, an output by its port's type. A number for a name
// nothing declares keeps the type JSON gives it. check_scenario judges the typed scenario.
void type_numbers(Scenario& scenario, const ScenarioVocabulary& vocabulary);

// " (did you mean 'x'?)" for the closest of `known` (uabt::NameIndex's rule), "" when none is
// close.
std::string did_you_mean_hint(const std::string& name, const std::set<std::string>& known);

// What is wrong with `value` for `var` ("is out of its range [0, 15]"), "" when it fits.
std::string misfit(const ScriptValue& value, const fretish::Variable& var);
// "wind = 1000 is out of its range [0, 15] (declared integer at domain.fret:1:1)", "" when
// the value fits.
std::string misfit_message(const std::string& name, const ScriptValue& value,
                           const fretish::Variable& var);

// "file:line:col: error: …" lines, empty when the scenario (its numbers typed, type_numbers)
// fits.
std::vector<std::string> check_scenario(const Scenario& scenario,
                                        const ScenarioVocabulary& vocabulary);

}  // namespace uabt::runtime
