#include "prove/environment.hpp"

#include <algorithm>
#include <cstring>

#include "prove/cells.hpp"
#include "prove/model.hpp"
#include "prove/prove.hpp"

namespace uabt::prove {

namespace {

// Beyond this many combinations of unchosen values, deciding an assumption by enumeration is
// too slow for the explicit engine (a mission whose assumptions relate so many variables).
constexpr std::uint64_t kMaxCompletions = std::uint64_t{1} << 20;

void append_val(std::string& key, const monitor::Val& v) {
  key += static_cast<char>(v.kind);
  key.append(reinterpret_cast<const char*>(&v.number), sizeof v.number);
  key.append(reinterpret_cast<const char*>(&v.symbol), sizeof v.symbol);
}

using verify::detail::Fraction;

// A number of the mission's state as the atoms read it (reals by their shortest text, as
// written); nullopt when it is no number (an entry not written yet) or does not fit.
std::optional<Fraction> fraction_of(const runtime::ScriptValue& v) {
  if (v.kind == runtime::ScriptValue::Kind::integer)
    return Fraction(static_cast<long long>(v.integer));
  if (v.kind != runtime::ScriptValue::Kind::real) return std::nullopt;
  try {
    return Fraction::parse(v.to_string());
  } catch (const verify::detail::FractionOverflow&) {
    return std::nullopt;
  }
}

}  // namespace

Environment::Environment(Model& m) : m_(m) {
  for (std::size_t i = 0; i < m.vars.size(); ++i) {
    const StateVar& v = m.vars[i];
    if (v.frame >= 0) {
      if (var_of_frame_.size() <= static_cast<std::size_t>(v.frame))
        var_of_frame_.resize(static_cast<std::size_t>(v.frame) + 1, SIZE_MAX);
      var_of_frame_[static_cast<std::size_t>(v.frame)] = i;
    }
    if (v.slot != runtime::kNoSlot) {
      if (var_of_slot_.size() <= v.slot) var_of_slot_.resize(v.slot + 1, SIZE_MAX);
      var_of_slot_[v.slot] = i;
    }
    std::vector<monitor::Val> vals;
    for (const auto& value : v.values)
      vals.push_back(runtime::TickObservation::value_of(value, m.symbols));
    choices_.push_back(std::move(vals));
    if (v.relevant && v.env) {
      env_.push_back(i);
    } else if (v.frame >= 0) {
      mission_vars_.push_back(i);
    }
  }
  auto vars_of = [&](const monitor::CompiledExpression& e) {
    std::vector<std::size_t> out;
    for (int slot : e.variables())
      if (const std::size_t i = var_of_frame(slot); i != SIZE_MAX) out.push_back(i);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  for (const auto& a : m.assumptions) constraints_.push_back({a, vars_of(*a), false});
  if (m.initial) constraints_.push_back({m.initial, vars_of(*m.initial), true});
  constraints_of_.resize(m.vars.size());
  for (std::size_t c = 0; c < constraints_.size(); ++c)
    for (std::size_t v : constraints_[c].vars) constraints_of_[v].push_back(c);
  read_until_.assign(m.vars.size(), 0);
  reads_of_.resize(m.properties.size());
  for (std::size_t j = 0; j < m.properties.size(); ++j) {
    for (const auto& atom : m.properties[j].atoms)
      for (std::size_t v : vars_of(*atom)) {
        monitor_reads_.push_back(v);
        reads_of_[j].push_back(v);
        read_until_[v] = j + 1;
      }
    std::sort(reads_of_[j].begin(), reads_of_[j].end());
    reads_of_[j].erase(std::unique(reads_of_[j].begin(), reads_of_[j].end()), reads_of_[j].end());
  }
  for (std::size_t v = 0; v < m.vars.size(); ++v)
    if (!constraints_of_[v].empty()) read_until_[v] = SIZE_MAX;
  std::sort(monitor_reads_.begin(), monitor_reads_.end());
  monitor_reads_.erase(std::unique(monitor_reads_.begin(), monitor_reads_.end()),
                       monitor_reads_.end());
  assigned_.assign(m.vars.size(), 1);
  live_.assign(m.vars.size(), 1);
  for (std::size_t i = 0; i < m.vars.size(); ++i)
    live_[i] = !m.vars[i].read_once || !constraints_of_[i].empty() ||
               std::binary_search(monitor_reads_.begin(), monitor_reads_.end(), i);
  frame_.resize(m.variables.size());
  for (const auto& [var, cut] : m.state_cuts)
    for (const StateCut::Atom& atom : cut.atoms)
      if (atom.at_tick_start)
        for (const auto& term : atom.terms) start_reads_.push_back(term.first);
  std::sort(start_reads_.begin(), start_reads_.end());
  start_reads_.erase(std::unique(start_reads_.begin(), start_reads_.end()), start_reads_.end());
  m.engine->blackboard().set_resolver(this);
}

std::optional<Fraction> Environment::breakpoint(const StateCut::Atom& atom, bool start) const {
  try {
    Fraction sum = atom.b;
    for (const auto& [var, factor] : atom.terms) {
      std::optional<Fraction> value;
      if (start) {
        const auto it = start_.find(var);
        if (it != start_.end()) value = fraction_of(it->second);
      } else {
        value = fraction_of(m_.engine->blackboard().value(m_.vars[var].slot));
      }
      if (!value) return std::nullopt;
      sum += factor * *value;
    }
    return -sum;
  } catch (const verify::detail::FractionOverflow&) {
    return std::nullopt;  // no cut this precise: its evaluation is what it is
  }
}

void Environment::fill(std::size_t var, Cells& c) {
  c.values = cell_values(*m_.state_cuts.at(var).declaration, c.breaks);
  if (c.values.empty()) c.values.push_back(runtime::ScriptValue{});
  c.vals.clear();
  for (const auto& value : c.values)
    c.vals.push_back(runtime::TickObservation::value_of(value, m_.symbols));
}

Environment::Cells& Environment::cells(std::size_t var, bool completion, std::string& key) {
  const StateCut& cut = m_.state_cuts.at(var);
  key.assign(reinterpret_cast<const char*>(&var), sizeof var);
  key += completion ? 'c' : 'x';
  std::vector<std::optional<Fraction>> points;
  for (const StateCut::Atom& atom : cut.atoms) {
    if (completion && !atom.at_tick_start) continue;
    points.push_back(breakpoint(atom, atom.at_tick_start));
    key += points.back() ? points.back()->text() : std::string("-");
    key += ',';
  }
  const auto [it, fresh] = cells_.try_emplace(key);
  if (fresh) {
    it->second.breaks = cut.breaks;
    for (const auto& p : points)
      if (p) it->second.breaks.insert(*p);
    fill(var, it->second);
  }
  return it->second;
}

void Environment::check(std::size_t k) {
  const Watch& w = watches_[k];
  Cells& c = cells_.at(w.key);
  const std::optional<Fraction> value = fraction_of(w.value);
  if (!value || c.breaks.contains(*value)) return;  // a breakpoint: a cell of its own
  const StateCut& cut = m_.state_cuts.at(w.var);
  std::optional<Fraction> lo, hi;  // the chosen cell
  if (!cut.declaration->lower.empty()) lo = Fraction::parse(cut.declaration->lower);
  if (!cut.declaration->upper.empty()) hi = Fraction::parse(cut.declaration->upper);
  if ((lo && *lo == *value) || (hi && *hi == *value)) return;
  if (auto above = c.breaks.upper_bound(*value); above != c.breaks.end() && (!hi || *above < *hi))
    hi = *above;
  if (auto below = c.breaks.lower_bound(*value); below != c.breaks.begin())
    if (--below; !lo || *below > *lo) lo = *below;
  bool split = false;
  for (const StateCut::Atom& atom : cut.atoms) {
    if (atom.at_tick_start) continue;  // read with the values the cells were cut with
    const auto p = breakpoint(atom, false);
    if (p && (!lo || *lo < *p) && (!hi || *p < *hi) && c.breaks.insert(*p).second) split = true;
  }
  if (!split) return;
  fill(w.var, c);
  refined_ = true;
}

void Environment::watched(runtime::SlotId slot) {
  const std::size_t i = slot < var_of_slot_.size() ? var_of_slot_[slot] : SIZE_MAX;
  for (std::size_t k = 0; k < watches_.size(); ++k)
    if (watches_[k].var == i) check(k);
}

void Environment::start_tick(bool first) {
  first_ = first;
  offer_var_ = SIZE_MAX;
  chosen_.clear();
  runtime::Blackboard& bb = m_.engine->blackboard();
  // The environment's own entries get their values as they are chosen.
  for (std::size_t i : mission_vars_) {
    const StateVar& v = m_.vars[i];
    frame_[static_cast<std::size_t>(v.frame)] =
        runtime::TickObservation::value_of(bb.value(v.slot), m_.symbols);
  }
  for (std::size_t i : env_) {
    assigned_[i] = 0;
    bb.set_pending(m_.vars[i].slot, true);
  }
  watches_.clear();
  for (std::size_t i : start_reads_) start_[i] = bb.value(m_.vars[i].slot);
}

bool Environment::satisfiable() {
  std::vector<std::size_t> seeds;
  for (std::size_t c = 0; c < constraints_.size(); ++c)
    if (active(constraints_[c])) seeds.push_back(c);
  // Each connected group separately: one unsatisfiable group is enough.
  std::vector<char> done(constraints_.size(), 0);
  for (std::size_t c : seeds) {
    if (done[c]) continue;
    std::vector<std::size_t> group = {c};
    for (std::size_t k = 0; k < group.size(); ++k) {
      done[group[k]] = 1;
      for (std::size_t v : constraints_[group[k]].vars)
        if (!assigned_[v])
          for (std::size_t other : constraints_of_[v])
            if (!done[other] && active(constraints_[other]) &&
                std::find(group.begin(), group.end(), other) == group.end())
              group.push_back(other);
    }
    if (!component_satisfiable(group)) return false;
  }
  return true;
}

bool Environment::holds(Constraint& c) {
  std::string error;
  const bool v = c.expr->evaluate_bool(frame_, error);
  if (!error.empty()) throw ProveError(error);
  return v;
}

bool Environment::component_satisfiable(std::vector<std::size_t> group) {
  // Close the group over unassigned variables.
  for (std::size_t k = 0; k < group.size(); ++k)
    for (std::size_t v : constraints_[group[k]].vars)
      if (!assigned_[v])
        for (std::size_t other : constraints_of_[v])
          if (active(constraints_[other]) &&
              std::find(group.begin(), group.end(), other) == group.end())
            group.push_back(other);
  std::sort(group.begin(), group.end());
  std::vector<std::size_t> free, read;
  for (std::size_t c : group)
    for (std::size_t v : constraints_[c].vars) read.push_back(v);
  std::sort(read.begin(), read.end());
  read.erase(std::unique(read.begin(), read.end()), read.end());
  std::string key;
  for (std::size_t c : group) key.append(reinterpret_cast<const char*>(&c), sizeof c);
  key += '|';
  for (std::size_t v : read) {
    key.append(reinterpret_cast<const char*>(&v), sizeof v);
    if (assigned_[v]) {
      append_val(key, frame_[static_cast<std::size_t>(m_.vars[v].frame)]);
    } else {
      key += '*';
      free.push_back(v);
    }
  }
  if (const auto it = cache_.find(key); it != cache_.end()) return it->second;

  // A variable cut in the state at hand: its cells in this tick's starting state.
  std::vector<const std::vector<monitor::Val>*> choices;
  for (std::size_t v : free) {
    std::string cells_key;
    choices.push_back(m_.state_cuts.contains(v) ? &cells(v, true, cells_key).vals : &choices_[v]);
  }
  std::uint64_t combinations = 1;
  for (const auto* values : choices) {
    if (values->empty()) return cache_[key] = false;
    if (combinations > kMaxCompletions / values->size())
      throw ProveError(
          "the explicit-state engine cannot decide the assumptions: they relate "
          "more than 2^20 combinations of environment values");
    combinations *= values->size();
  }
  std::vector<monitor::Val> saved;
  for (std::size_t v : free) saved.push_back(frame_[static_cast<std::size_t>(m_.vars[v].frame)]);
  bool any = false;
  for (std::uint64_t n = 0; n < combinations && !any; ++n) {
    std::uint64_t index = n;
    for (std::size_t k = 0; k < free.size(); ++k) {
      const std::vector<monitor::Val>& values = *choices[k];
      frame_[static_cast<std::size_t>(m_.vars[free[k]].frame)] = values[index % values.size()];
      index /= values.size();
    }
    any = std::all_of(group.begin(), group.end(),
                      [&](std::size_t c) { return holds(constraints_[c]); });
  }
  for (std::size_t k = 0; k < free.size(); ++k)
    frame_[static_cast<std::size_t>(m_.vars[free[k]].frame)] = saved[k];
  return cache_[key] = any;
}

void Environment::resolve(runtime::SlotId slot) {
  const std::size_t i = slot < var_of_slot_.size() ? var_of_slot_[slot] : SIZE_MAX;
  if (i == SIZE_MAX) return;
  const StateVar& v = m_.vars[i];
  const std::size_t frame = static_cast<std::size_t>(v.frame);
  // The values that keep the assumptions satisfiable by what is still unchosen.
  std::vector<std::uint32_t>& options = options_;
  options.clear();
  assigned_[i] = 1;
  seeds_.clear();
  for (std::size_t c : constraints_of_[i])
    if (active(constraints_[c])) seeds_.push_back(c);
  // A variable cut in the state at hand: its cells now.
  std::string key;
  Cells* cut = m_.state_cuts.contains(i) ? &cells(i, false, key) : nullptr;
  const std::vector<monitor::Val>& choices = cut ? cut->vals : choices_[i];
  for (std::uint32_t k = 0; k < choices.size(); ++k) {
    frame_[frame] = choices[k];
    if (seeds_.empty() || component_satisfiable(seeds_)) options.push_back(k);
  }
  if (options.empty())
    throw ProveError("internal error: no value of '" + v.name +
                     "' keeps the assumptions satisfiable, although the tick started with one");
  std::uint64_t allowed = ~std::uint64_t{0};
  if (i == offer_var_ && options.size() == choices.size()) allowed = offer_allowed_;
  offer_var_ = SIZE_MAX;
  const std::uint32_t pick =
      options.size() == 1 ? options[0]
                          : options[m_.choice->chooser.choose(
                                static_cast<std::uint32_t>(options.size()), 2 * slot + 1, allowed)];
  frame_[frame] = choices[pick];
  m_.engine->blackboard().value(slot) = cut ? cut->values[pick] : v.values[pick];
  chosen_.push_back(i);
  if (cut) {
    // Read again after an effect changed the mission's state, its cell may need cutting.
    watches_.push_back({i, std::move(key), cut->values[pick]});
    m_.engine->blackboard().set_watched(slot);
  }
}

const std::vector<monitor::Val>* Environment::sole_reader_choices(std::size_t property,
                                                                  std::size_t& var) {
  var = SIZE_MAX;
  const runtime::Blackboard& bb = m_.engine->blackboard();
  for (std::size_t v : reads_of_[property]) {
    if (!m_.vars[v].env || !bb.pending(m_.vars[v].slot)) continue;
    if (var != SIZE_MAX) return nullptr;  // two still to choose
    var = v;
  }
  if (var == SIZE_MAX || read_until_[var] != property + 1 || !constraints_of_[var].empty() ||
      m_.state_cuts.contains(var) || choices_[var].size() < 2 || choices_[var].size() > 64)
    return nullptr;
  return &choices_[var];
}

void Environment::undo(std::size_t count) {
  offer_var_ = SIZE_MAX;  // an offer the monitors' reads did not take is not the tick's
  chosen_.resize(count);
  for (std::size_t i : env_) assigned_[i] = 0;
  for (std::size_t i : chosen_) assigned_[i] = 1;
  // The watches of choices made after the checkpoint go with them; those made before it are
  // watched again, as they were when the checkpoint was taken.
  std::erase_if(watches_, [&](const Watch& w) { return !assigned_[w.var]; });
  runtime::Blackboard& bb = m_.engine->blackboard();
  for (std::size_t i : env_) bb.set_pending(m_.vars[i].slot, !assigned_[i]);
  for (const Watch& w : watches_) bb.set_watched(m_.vars[w.var].slot);
}

void Environment::reach(int slot) {
  const std::size_t i = var_of_frame(slot);
  if (i == SIZE_MAX) return;
  const runtime::Blackboard& bb = m_.engine->blackboard();
  const runtime::SlotId s = m_.vars[i].slot;
  if (!bb.pending(s)) return;
  (*monitor_frame_)[static_cast<std::size_t>(slot)] =
      runtime::TickObservation::value_of(bb.read(s), m_.symbols);
}

bool Environment::boolean(int slot) const {
  const std::size_t i = var_of_frame(slot);
  const auto is_boolean = [](const monitor::Val& v) {
    return !v.known() || v.kind == monitor::Val::Kind::boolean;
  };
  if (i != SIZE_MAX && m_.engine->blackboard().pending(m_.vars[i].slot))
    return !m_.state_cuts.contains(i) &&
           std::all_of(choices_[i].begin(), choices_[i].end(), is_boolean);
  return is_boolean((*monitor_frame_)[static_cast<std::size_t>(slot)]);
}

void Environment::monitors_read() {
  // The monitors read every value as it is after the tick.
  for (std::size_t k = 0; k < watches_.size(); ++k) check(k);
}

void Environment::resolve_monitor_reads() {
  const runtime::Blackboard& bb = m_.engine->blackboard();
  for (std::size_t v : monitor_reads_) bb.read(m_.vars[v].slot);
  monitors_read();
}

void Environment::end_tick() {
  offer_var_ = SIZE_MAX;
  runtime::Blackboard& bb = m_.engine->blackboard();
  bb.clear_pending();
  // watches_ stay until the next tick starts: a tick resumed at a checkpoint (undo) watches
  // again the choices made before it.
  for (std::size_t i : env_) {
    bb.value(m_.vars[i].slot) = m_.vars[i].values.front();
    assigned_[i] = 1;
  }
}

}  // namespace uabt::prove
