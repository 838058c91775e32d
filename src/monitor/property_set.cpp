#include "monitor/property_set.hpp"

#include <cctype>

#include "fretish/expr.hpp"

namespace uabt::monitor {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::held: return "held";
    case Verdict::violated: return "violated";
    case Verdict::not_monitored: return "not-monitored";
  }
  return "held";
}

std::string held_text(const PropertyResult& r) {
  if (!r.pending_since) return "held";
  return "held (pending at end: " + r.pending + ", triggered at tick " +
         std::to_string(*r.pending_since) + ")";
}

PropertySet::PropertySet(const std::vector<fretish::Requirement>& requirements,
                         const std::vector<fretish::Assumption>& assumptions,
                         const Vocabulary& vocabulary)
    : vocabulary_(vocabulary) {
  add_all(requirements, assumptions, entries_);
}

void PropertySet::add_all(const std::vector<fretish::Requirement>& requirements,
                          const std::vector<fretish::Assumption>& assumptions,
                          std::vector<Entry>& out) const {
  const Resolver resolve = [this](const std::string& name) -> Resolved {
    if (const auto slot = vocabulary_.variables->find(name))
      return {Resolved::Kind::variable, *slot};
    if (vocabulary_.literals.count(name) != 0)
      return {Resolved::Kind::literal, vocabulary_.symbols->id(name)};
    return {};
  };
  const auto add = [&](const fretish::Requirement& r, bool assumption, std::string text) {
    Entry e;
    e.base.id = r.id;
    e.base.assumption = assumption;
    e.base.location = r.location;
    e.text = std::move(text);
    std::string reason;
    e.monitor = RequirementMonitor::compile(r, resolve, reason);
    if (!e.monitor) {
      e.base.verdict = Verdict::not_monitored;
      e.base.reason = reason;
    }
    out.push_back(std::move(e));
  };
  for (const fretish::Requirement& r : requirements) add(r, fretish::is_assumption(r), r.text);
  for (const fretish::Assumption& a : assumptions) {
    fretish::Requirement r;
    r.id = a.name;
    r.location = a.location;
    r.component = "Environment";
    r.timing.keyword = "always";
    r.response = a.expr;
    add(r, true, "assume " + (a.expr ? fretish::to_fretish(*a.expr) : std::string()));
  }
}

std::vector<std::size_t> PropertySet::update(const std::vector<fretish::Requirement>& requirements,
                                             const std::vector<fretish::Assumption>& assumptions,
                                             const std::set<std::string>& literals,
                                             std::uint64_t last_tick) {
  vocabulary_.literals.insert(literals.begin(), literals.end());
  std::vector<Entry> next;
  add_all(requirements, assumptions, next);
  std::vector<std::size_t> ended;
  std::vector<bool> kept(next.size(), false);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    Entry& e = entries_[i];
    if (e.stopped) continue;
    bool same = false;
    for (std::size_t k = 0; k < next.size() && !same; ++k)
      if (!kept[k] && next[k].base.id == e.base.id &&
          next[k].base.assumption == e.base.assumption && next[k].text == e.text)
        same = kept[k] = true;
    if (same) continue;
    e.stopped = true;
    e.base.monitored_until = last_tick;
    if (e.monitor && !e.monitor->failed() && e.started && !e.reported && !e.monitor->holds())
      ended.push_back(i);
  }
  for (std::size_t k = 0; k < next.size(); ++k) {
    if (kept[k]) continue;
    next[k].base.monitored_from = last_tick + 1;
    entries_.push_back(std::move(next[k]));
  }
  return ended;
}

std::vector<std::size_t> PropertySet::step(const std::vector<Val>& frame, std::uint64_t tick) {
  started_ = true;
  std::vector<std::size_t> fresh;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    Entry& e = entries_[i];
    if (e.stopped || !e.monitor || e.monitor->failed()) continue;
    if (!e.started) {
      e.started = true;
      e.first_tick = tick;
    }
    e.monitor->step(frame);
    if (!e.reported && e.monitor->final_violation() && !e.monitor->failed()) {
      e.reported = true;
      fresh.push_back(i);
    }
  }
  return fresh;
}

std::vector<std::size_t> PropertySet::violated_at_end() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (e.monitor && !e.stopped && e.started && !e.monitor->failed() && !e.reported &&
        !e.monitor->holds())
      out.push_back(i);
  }
  return out;
}

PropertyResult PropertySet::result(std::size_t index) const {
  const Entry& e = entries_[index];
  PropertyResult r = e.base;
  if (!e.monitor) return r;
  if (e.monitor->failed()) {
    r.verdict = Verdict::not_monitored;
    r.reason = e.monitor->error();
    return r;
  }
  if (!e.started) {
    r.verdict = Verdict::not_monitored;
    r.reason = started_ ? "no tick after the uplink that added it" : "the trace is empty";
    return r;
  }
  if (e.monitor->holds()) {
    if (const auto since = e.monitor->pending_since()) {
      r.pending = e.monitor->obligation();
      r.pending_since = e.first_tick + *since;
    }
    return r;
  }
  r.verdict = Verdict::violated;
  r.first_violation = e.first_tick + e.monitor->violated_since();
  const auto& slots = e.monitor->variables();
  const auto& values = e.monitor->violation_values();
  for (std::size_t k = 0; k < slots.size() && k < values.size(); ++k)
    r.values.emplace_back(vocabulary_.variables->name(slots[k]),
                          value_of(values[k], *vocabulary_.symbols));
  return r;
}

std::vector<PropertyResult> PropertySet::results() const {
  std::vector<PropertyResult> out;
  for (std::size_t i = 0; i < entries_.size(); ++i) out.push_back(result(i));
  return out;
}

}  // namespace uabt::monitor
