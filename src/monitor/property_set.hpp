#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/location.hpp"
#include "fretish/domain.hpp"
#include "fretish/requirement.hpp"
#include "monitor/monitor.hpp"

namespace uabt::monitor {

enum class Verdict { held, violated, not_monitored };
const char* verdict_name(Verdict v);  // "held", "violated", "not-monitored"

struct PropertyResult {
  std::string id;
  bool assumption = false;
  bool selection = false;  // a selection requirement (selection_check.hpp), not a property
  SourceLocation location;
  Verdict verdict = Verdict::held;
  std::optional<std::uint64_t> first_violation;       // tick (as numbered by the caller)
  std::vector<std::pair<std::string, Value>> values;  // read at first_violation
  std::string reason;                                 // not-monitored: why
  // Held only because the trace ended before a deadline: what is still due ("stopped within
  // 2 ticks") and the tick that triggered it.
  std::string pending;
  std::optional<std::uint64_t> pending_since;
  // A property an uplink added or restated mid-run is monitored from the tick after the swap;
  // one it removed or restated stops at the swap (both unset: the whole trace).
  std::optional<std::uint64_t> monitored_from, monitored_until;
};

// "held", or "held (pending at end: stopped within 2 ticks, triggered at tick 7)".
std::string held_text(const PropertyResult& r);

// What the properties may read: the trace's (or the run's) variables and the names that are
// values rather than variables (enum literals, alternatives, string values of the trace).
struct Vocabulary {
  Variables* variables = nullptr;
  Symbols* symbols = nullptr;
  std::set<std::string> literals;
};

// Every property of a requirement set, monitored together over one trace.
class PropertySet {
 public:
  // Domain assumptions (`assume NAME: E`, FRET "assumption" requirements) are monitored as
  // "always E" assumptions. The requirements are lowered (fretish/durations.hpp).
  PropertySet(const std::vector<fretish::Requirement>& requirements,
              const std::vector<fretish::Assumption>& assumptions, const Vocabulary& vocabulary);

  // One tick. `tick` is the caller's number for it. Returns the indices of the properties whose
  // violation became final at this tick (safety properties, at the tick it happens).
  std::vector<std::size_t> step(const std::vector<Val>& frame, std::uint64_t tick);

  // A new version of the requirements from the next tick on (an uplink swapped in after tick
  // `last_tick`): a property with the same id and text keeps its monitor; the others stop at
  // `last_tick`, and the new version's new or restated properties start on the next tick, each
  // read over the trace from there. `literals` joins the vocabulary's (the new alternatives and
  // enum values); the variables must already hold every name they read. Returns the stopped
  // properties violated at their last tick that step() did not report (as violated_at_end).
  std::vector<std::size_t> update(const std::vector<fretish::Requirement>& requirements,
                                  const std::vector<fretish::Assumption>& assumptions,
                                  const std::set<std::string>& literals, std::uint64_t last_tick);

  // Verdicts of the trace so far, read as a whole finite trace.
  std::vector<PropertyResult> results() const;
  std::size_t size() const { return entries_.size(); }
  // Properties violated at the last tick whose violation was not final when it began
  // (eventually, finally, …): reported when the trace ends.
  std::vector<std::size_t> violated_at_end() const;
  PropertyResult result(std::size_t index) const;

 private:
  struct Entry {
    PropertyResult base;
    std::string text;                             // what identifies it across versions
    std::unique_ptr<RequirementMonitor> monitor;  // null: not monitored (base.reason)
    bool reported = false;                        // a final violation was returned by step()
    bool started = false;                         // stepped at least once, from first_tick
    std::uint64_t first_tick = 0;
    bool stopped = false;  // an uplink removed or restated it (base.monitored_until)
  };
  // Every requirement, then every assumption as "always E", as one list.
  void add_all(const std::vector<fretish::Requirement>& requirements,
               const std::vector<fretish::Assumption>& assumptions, std::vector<Entry>& out) const;
  std::vector<Entry> entries_;
  Vocabulary vocabulary_;
  bool started_ = false;  // step() was called: the trace is not empty
};

}  // namespace uabt::monitor
