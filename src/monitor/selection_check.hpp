#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fretish/selection.hpp"
#include "monitor/expression.hpp"
#include "monitor/property_set.hpp"

namespace uabt::monitor {

// One selection an adaptable node made in a tick: the alternative it started, the values of
// the variables its guards read as they were at that moment, and, when it follows an earlier
// branch of the same selection that did not go on (it failed, or its guard no longer held),
// that branch's requirement (`after`).
struct SelectionRecord {
  std::string adaptable;
  std::string alternative;
  std::string after;
  std::vector<std::pair<std::string, Val>> read;
};

// Judges selection requirements on the selections a run made, in their priority order: a
// selection must start the alternative of the first requirement (from the one after `after`
// on) whose guard holds in the values it read; that requirement is violated otherwise, and
// when no guard holds, the requirements of the alternative it started are.
// `uabt run` and `uabt monitor` judge with this one class, so both give the same verdicts.
class SelectionJudge {
 public:
  // `symbols` and `literals` are the caller's: enum values and alternatives the guards name.
  SelectionJudge(const std::vector<fretish::SelectionRequirement>& requirements, Symbols& symbols,
                 const std::set<std::string>& literals);

  // Requirements of a new version (an uplink) judged from now on: those with a new id are
  // added; the others keep their verdicts so far.
  void add(const std::vector<fretish::SelectionRequirement>& requirements,
           const std::set<std::string>& literals);
  // After an uplink swapped a new version in after tick `last_tick`: `adaptable`'s selections
  // are judged from the next tick on by `requirements` (its requirements in that version, in
  // priority order). One stated alike (same alternative, same guard) keeps its verdict so far;
  // one the version restates or no longer has stops at `last_tick` (monitored_until), and a
  // restated or new one is judged from the next tick (monitored_from).
  void update(const std::string& adaptable,
              const std::vector<fretish::SelectionRequirement>& requirements,
              const std::set<std::string>& literals, std::uint64_t last_tick);
  // The statement `adaptable`'s selections are judged by for requirement `id` now, or null.
  const fretish::SelectionRequirement* current(const std::string& adaptable,
                                               const std::string& id) const;
  // Whether two statements of a selection requirement judge alike.
  static bool same_meaning(const fretish::SelectionRequirement& a,
                           const fretish::SelectionRequirement& b);
  // The priority order of `adaptable`'s requirements from now on (a trace's or an uplink's):
  // the ids listed, in that order, then the others in their own order.
  void set_order(const std::string& adaptable, const std::vector<std::string>& ids);
  void observe(std::uint64_t tick, const SelectionRecord& record);
  // Verdicts in the requirements' order. `recorded`: the trace records selections at all
  // (otherwise every requirement is not monitored, with why).
  std::vector<PropertyResult> results(bool recorded = true) const;

 private:
  struct Entry {
    fretish::SelectionRequirement requirement;
    std::optional<CompiledExpression> guard;  // none: the default
    PropertyResult result;
  };
  Entry make_entry(const fretish::SelectionRequirement& r, const std::set<std::string>& literals);

  Symbols& symbols_;
  Variables variables_;  // the guards' names
  std::vector<Entry> entries_;
  std::map<std::string, std::vector<std::size_t>> order_;  // per adaptable: entries, by priority
};

}  // namespace uabt::monitor
