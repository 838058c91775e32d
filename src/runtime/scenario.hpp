#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "runtime/script/value.hpp"
#include "runtime/status.hpp"

namespace uabt::runtime {

using StateAssignment = std::vector<std::pair<std::string, ScriptValue>>;  // file order

// One start of an action as a counterexample scripts it: how long it runs, how it ends and
// what it then writes.
struct ActionRun {
  std::int64_t ticks = 1;
  NodeStatus result = NodeStatus::success;
  StateAssignment effects;
  StateAssignment outputs;  // by output port name
};

struct ActionSpec {
  std::int64_t ticks = 1;   // completes on its `ticks`-th tick; RUNNING before
  StateAssignment effects;  // applied when it completes
  // "outputs": the value it writes to each of its output ports `{key}` when it completes,
  // by port name (nodes.xml gives the direction); a port not listed is not written.
  StateAssignment outputs;
  NodeStatus result = NodeStatus::success;
  // "runs": the n-th start of the action (counted over every leaf it names) follows runs[n];
  // starts beyond the list follow ticks/result/effects above.
  std::vector<ActionRun> runs;
};

struct ScenarioEvent {
  std::int64_t at = 0;  // applied before tick `at` (ticks count from 1)
  StateAssignment set;
  std::string uplink;  // an uplink package directory (the manager's business), "" if none
  int index = 0;       // position in the file's "events" array
};

// A runtime scenario (ARCHITECTURE §8):
//   {"max_ticks": 2000,
//    "initial": {"OnDust": true, "battery": 90, "terrain": "dust"},
//    "actions": {"Drill": {"ticks": 30, "effects": {"IsDug": true}, "result": "success"}},
//    (an action may also list "runs": [{"ticks": 3, "result": "failure", "effects": {…}}, …]
//     and "outputs": {"waypoint": 3}, what it writes to its output ports, as may a run)
//    "events": [{"at": 15, "set": {"OnDust": false}}, {"at": 40, "uplink": "uplinks/on_mud"}]}
// JSON booleans, integers, reals and strings become state values (strings hold enum values);
// a number's type is what JSON writes until type_numbers (scenario_check.hpp) gives it the
// type its variable is declared.
// A counterexample `uabt prove` writes also says which guarantee it violates:
//   "counterexample_of": "CoolBit"
struct Scenario {
  std::string file;  // displayed path
  // The guarantee this scenario is a counterexample of ("" for any other scenario): `uabt run`
  // replays it even on a mission that does not pass the gate's checks, as `uabt prove` proved it.
  std::string counterexample_of;
  std::int64_t max_ticks = 2000;
  StateAssignment initial;
  std::map<std::string, ActionSpec, std::less<>> actions;
  std::vector<ScenarioEvent> events;  // by `at`, file order within one tick

  // Where each member's key and each value starts in the file, by JSON pointer ("/initial/
  // battery"), as (line, column).
  std::map<std::string, std::pair<int, int>, std::less<>> key_positions, value_positions;

  // True when `key` is a state variable the scenario sets anywhere (initial, events,
  // effects).
  bool mentions_state(std::string_view key) const;
  // "file:line:col" of the member `pointer` (its key, or its value), "file" if unknown.
  std::string where(std::string_view pointer, bool value = false) const;
};

// A scenario file that is not valid JSON or not of the shape above. The message names the
// file, and line:col for JSON syntax errors ("scenarios/a.json:3:14: ...").
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Scenario parse_scenario(std::string_view text, const std::string& file);
// Reads and parses; `display` is the path shown in messages (default: `path` as given).
Scenario load_scenario(const std::filesystem::path& path, const std::string& display = "");

}  // namespace uabt::runtime
