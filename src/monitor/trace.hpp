#pragma once
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/finding.hpp"
#include "fretish/selection.hpp"

namespace uabt::monitor {

// One value of a recorded trace, as JSON wrote it.
struct TraceValue {
  // `none`: JSON null, the variable has no value at this tick (the run had none to give).
  enum class Kind { boolean, number, text, none } kind = Kind::boolean;
  bool boolean = false;
  double number = 0;
  // JSON writes a whole number within 64 bits (`12`, not `12.0`): what the number is for a
  // name the domain does not declare (fretish::number_is_integer).
  bool integer = false;
  std::string text;
};

// A selection an adaptable node made in a tick ("select" of a trace line).
struct TraceSelection {
  std::string adaptable, alternative, after;
  std::vector<std::pair<std::string, TraceValue>> read;  // its guards' variables, as read
};

// An adaptable node as a "selection" line describes it: its alternatives and its selection
// requirements in priority order, from the next tick on, and those requirements as the run
// stated them (`sentences`; none in a trace written before they were recorded).
struct TraceAdaptable {
  std::string id;
  std::vector<std::string> alternatives, requirements;
  std::vector<fretish::SelectionRequirement> stated;
};

struct TraceTick {
  std::uint64_t tick = 0;
  int line = 0;
  std::vector<std::pair<std::string, TraceValue>> state;  // what this line sets
  std::vector<TraceSelection> selections;                 // what this line's "select" says
  std::vector<TraceAdaptable> adaptables;                 // "selection" lines before this one
};

struct Trace {
  std::vector<TraceTick> ticks;
  std::set<std::string> names;      // every variable the trace sets
  std::set<std::string> strings;    // every string value and alternative: values, not variables
  bool records_selections = false;  // a "selection" or "select" somewhere
};

// A recorded trace (ARCHITECTURE §10): JSON lines {"tick": t, "state": {"name": value, …}}, one a
// tick, ticks consecutive. A line sets the values it lists; the others keep their value. A
// line may also carry "select": {"<adaptable>": [{"alternative": "a", "read": {…}, "after":
// "Req1"}]}, the selections made in that tick; a line {"selection": {"<adaptable>":
// {"alternatives": […], "requirements": […], "sentences": {"<id>": {"text": FRETISH, "file":
// f, "line": l, "column": c}}}}} describes the adaptable nodes from the next tick on
// ("sentences" is optional: each requirement as written, and where). Problems are
// `trace-invalid` findings naming file, line and column.
std::optional<Trace> read_trace(const std::string& content, const std::string& file,
                                std::vector<Finding>& findings);

}  // namespace uabt::monitor
