#include "monitor/selection_check.hpp"

#include <algorithm>

namespace uabt::monitor {

SelectionJudge::SelectionJudge(const std::vector<fretish::SelectionRequirement>& requirements,
                               Symbols& symbols, const std::set<std::string>& literals)
    : symbols_(symbols) {
  add(requirements, literals);
}

SelectionJudge::Entry SelectionJudge::make_entry(const fretish::SelectionRequirement& r,
                                                 const std::set<std::string>& literals) {
  const Resolver resolve = [&](const std::string& name) -> Resolved {
    if (literals.count(name) != 0) return {Resolved::Kind::literal, symbols_.id(name)};
    return {Resolved::Kind::variable, variables_.id(name)};
  };
  Entry e;
  e.requirement = r;
  e.result.id = r.id;
  e.result.location = r.location;
  e.result.selection = true;
  if (r.guard) {
    std::string error;
    e.guard = CompiledExpression::compile(*r.guard, resolve, error);
    if (!e.guard) {
      e.result.verdict = Verdict::not_monitored;
      e.result.reason = "guard: " + error;
    }
  }
  return e;
}

void SelectionJudge::add(const std::vector<fretish::SelectionRequirement>& requirements,
                         const std::set<std::string>& literals) {
  for (const fretish::SelectionRequirement& r : requirements) {
    if (std::any_of(entries_.begin(), entries_.end(),
                    [&](const Entry& e) { return e.requirement.id == r.id; }))
      continue;
    order_[r.adaptable].push_back(entries_.size());
    entries_.push_back(make_entry(r, literals));
  }
}

bool SelectionJudge::same_meaning(const fretish::SelectionRequirement& a,
                                  const fretish::SelectionRequirement& b) {
  if (a.id != b.id || a.adaptable != b.adaptable || a.alternative != b.alternative) return false;
  if (!a.guard || !b.guard) return !a.guard && !b.guard;
  return fretish::same_expr(*a.guard, *b.guard);
}

const fretish::SelectionRequirement* SelectionJudge::current(const std::string& adaptable,
                                                             const std::string& id) const {
  const auto it = order_.find(adaptable);
  if (it == order_.end()) return nullptr;
  for (std::size_t i : it->second)
    if (entries_[i].requirement.id == id) return &entries_[i].requirement;
  return nullptr;
}

void SelectionJudge::update(const std::string& adaptable,
                            const std::vector<fretish::SelectionRequirement>& requirements,
                            const std::set<std::string>& literals, std::uint64_t last_tick) {
  std::vector<std::size_t>& order = order_[adaptable];
  std::vector<std::size_t> next;
  for (const fretish::SelectionRequirement& r : requirements) {
    if (r.adaptable != adaptable) continue;
    const auto kept = std::find_if(order.begin(), order.end(), [&](std::size_t i) {
      return same_meaning(entries_[i].requirement, r);
    });
    if (kept != order.end()) {
      next.push_back(*kept);
      continue;
    }
    Entry e = make_entry(r, literals);
    e.result.monitored_from = last_tick + 1;
    next.push_back(entries_.size());
    entries_.push_back(std::move(e));
  }
  for (std::size_t i : order) {
    if (std::find(next.begin(), next.end(), i) == next.end())
      entries_[i].result.monitored_until = last_tick;
  }
  order = std::move(next);
}

void SelectionJudge::set_order(const std::string& adaptable, const std::vector<std::string>& ids) {
  std::vector<std::size_t>& order = order_[adaptable];
  std::vector<std::size_t> ordered;
  for (const std::string& id : ids)
    for (std::size_t i : order)
      if (entries_[i].requirement.id == id) ordered.push_back(i);
  for (std::size_t i : order)
    if (std::find(ordered.begin(), ordered.end(), i) == ordered.end()) ordered.push_back(i);
  order = std::move(ordered);
  // A requirement the run judged by that these requirements do not state (an uplink's): the
  // node's selections cannot be judged from here on.
  for (const std::string& id : ids) {
    if (std::any_of(order.begin(), order.end(),
                    [&](std::size_t i) { return entries_[i].requirement.id == id; }))
      continue;
    for (std::size_t i : order) {
      PropertyResult& r = entries_[i].result;
      if (r.verdict != Verdict::held) continue;
      r.verdict = Verdict::not_monitored;
      r.reason = "the run selected by requirement '" + id + "' of '" + adaptable +
                 "', which these requirements do not state (give those of the version that ran)";
    }
    break;
  }
}

void SelectionJudge::observe(std::uint64_t tick, const SelectionRecord& record) {
  const auto it = order_.find(record.adaptable);
  if (it == order_.end()) return;
  std::vector<Val> frame(variables_.size());
  for (const auto& [name, value] : record.read)
    if (const auto slot = variables_.find(name)) frame[static_cast<std::size_t>(*slot)] = value;
  const auto violate = [&](Entry& e) {
    if (e.result.verdict != Verdict::held) return;
    e.result.verdict = Verdict::violated;
    e.result.first_violation = tick;
    e.result.values.clear();
    if (e.guard)
      for (int slot : e.guard->variables())
        e.result.values.emplace_back(variables_.name(slot),
                                     value_of(frame[static_cast<std::size_t>(slot)], symbols_));
    e.result.values.emplace_back(record.adaptable + ".selected",
                                 Value::of_enum(record.alternative));
  };
  // The branches this selection tried: after `after`, in priority order.
  bool tried = record.after.empty() ||
               std::none_of(it->second.begin(), it->second.end(), [&](std::size_t i) {
                 return entries_[i].requirement.id == record.after;
               });
  for (std::size_t i : it->second) {
    Entry& e = entries_[i];
    if (!tried) {
      tried = e.requirement.id == record.after;
      continue;
    }
    if (e.result.verdict == Verdict::not_monitored) return;
    bool holds = true;
    if (e.guard) {
      std::string error;
      holds = e.guard->evaluate_bool(frame, error);
      if (!error.empty()) {
        e.result.verdict = Verdict::not_monitored;
        e.result.reason = "guard at tick " + std::to_string(tick) + ": " + error;
        return;
      }
    }
    if (!holds) continue;
    if (e.requirement.alternative != record.alternative) violate(e);
    return;
  }
  // No guard holds: the alternative started without one.
  for (std::size_t i : it->second)
    if (entries_[i].requirement.alternative == record.alternative) violate(entries_[i]);
}

std::vector<PropertyResult> SelectionJudge::results(bool recorded) const {
  std::vector<PropertyResult> out;
  for (const Entry& e : entries_) {
    PropertyResult r = e.result;
    if (!recorded && r.verdict == Verdict::held) {
      r.verdict = Verdict::not_monitored;
      r.reason = "the trace records no selection of '" + e.requirement.adaptable +
                 "' (the selections `uabt run --monitor-trace` records)";
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace uabt::monitor
