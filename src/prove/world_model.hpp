#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include "base/finding.hpp"

#include "base/location.hpp"
#include "fretish/expr.hpp"
#include "runtime/script/value.hpp"
#include "runtime/status.hpp"

namespace uabt::load {
struct Mission;
}

namespace uabt::prove {

// What an action may do (world.json, ARCHITECTURE §10): run for `min_ticks`..`max_ticks` ticks
// (RUNNING before), end with one of `results`, and then run its effect script.
struct ActionContract {
  std::string name;  // as world.json keys it: Drill, IsArmInPosition(function=drilling)
  std::int64_t min_ticks = 1, max_ticks = 1;
  std::vector<runtime::NodeStatus> results;  // success and/or failure
  std::string on_success, on_failure;        // BT.CPP scripts, "" for none
  // "outputs": the value it writes to each output port `{key}` when it ends, by port name; a
  // port not listed gets any value of its entry the mission distinguishes.
  std::map<std::string, runtime::ScriptValue, std::less<>> outputs;
  SourceLocation location;
};

// world.json: {"initial": "<FRETISH expression>", "actions": {"Drill": {"ticks": [5, 30],
// "results": ["success", "failure"], "on_success": "IsDug = true"}, "PlanOrbit": {"outputs":
// {"waypoint": 3}}}}. Without a file the
// world is unconstrained: every initial state of the domain, every action free.
struct WorldModel {
  std::string file;          // displayed path, "" without a world.json
  fretish::ExprPtr initial;  // nullptr: every state of the domain
  std::map<std::string, ActionContract, std::less<>> actions;
  // What is worth saying but does not stop the proof (an action no tree of the mission runs).
  std::vector<Finding> warnings;

  const ActionContract* find(std::string_view qualified, std::string_view plain) const;
};

// A world.json that is not valid JSON, not of the shape above, or whose scripts or initial
// expression do not parse. The message starts with "file:line:col: error: ".
class WorldError : public std::runtime_error {
 public:
  WorldError(SourceLocation where, const std::string& message, std::string check_id = "load-file")
      : std::runtime_error(
            where.file +
            (where.line > 0 ? ":" + std::to_string(where.line) + ":" + std::to_string(where.column)
                            : "") +
            ": error: " + message),
        location(std::move(where)),
        text(message),
        check(std::move(check_id)) {}
  SourceLocation location;
  std::string text;
  std::string check;  // the finding it makes in the gate's report
};

// With `mission`, world.json is also checked against it as scenarios are (ARCHITECTURE §8): every
// action is a leaf of the mission, every name an effect writes is a domain variable or a
// condition, and every value an effect writes fits its declaration ("did you mean" for a
// likely typo); the error is at the name or the value.
WorldModel parse_world(std::string_view text, const std::string& file,
                       const load::Mission* mission = nullptr);
// A path that is not a regular file (a directory) is an error too.
WorldModel load_world(const std::filesystem::path& path, const std::string& display,
                      const load::Mission* mission = nullptr);
// The mission's world.json, or the unconstrained world when it has none. Throws WorldError.
WorldModel mission_world(const load::Mission& mission);

// The names a script assigns (`x = …`, `x := …`, `x += …`), in order: the state an effect
// writes (bt::script::Script::assigned). None for a script that does not parse, which the
// mission's checks and the world's loading refuse.
std::vector<std::string> assigned_names(std::string_view script);

}  // namespace uabt::prove
