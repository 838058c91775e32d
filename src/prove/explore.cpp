#include "prove/explore.hpp"

#include "prove/assumption_order.hpp"
#include "prove/environment.hpp"

#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <unordered_map>
#include <unordered_set>

namespace uabt::prove {

using runtime::EngineState;
using runtime::NodeStatus;

namespace {

// The stored form of a state between two ticks.
struct Node {
  EngineState engine;
  std::vector<std::int64_t> elapsed;
  std::vector<std::uint64_t> monitors;
  std::uint32_t parent = UINT32_MAX;
  Step step;
  std::uint64_t tick = 0;
};

// Mixed-radix enumeration of assignments to a set of variables.
struct Product {
  std::vector<const StateVar*> vars;
  std::vector<std::vector<runtime::ScriptValue>> values;  // per variable
  std::uint64_t size = 1;
  void set(Model& m, std::uint64_t index) const {
    for (std::size_t i = 0; i < vars.size(); ++i) {
      m.engine->blackboard().value(vars[i]->slot) = values[i][index % values[i].size()];
      index /= values[i].size();
    }
  }
};

// The values a conjunction of literals (`!X`, `X`, `x = 3`, `t = rocks`) fixes: the initial
// condition usually fixes most of the state, and need not be enumerated for them.
void fixed_values(const fretish::Expr& e, const Model& m,
                  std::map<std::string, runtime::ScriptValue>& out) {
  using K = fretish::ExprKind;
  if (e.kind == K::logical_and) {
    for (const auto& a : e.args) fixed_values(*a, m, out);
  } else if (e.kind == K::identifier && m.state_names.contains(e.text)) {
    out[e.text] = runtime::ScriptValue::of_bool(true);
  } else if (e.kind == K::logical_not && e.args[0]->kind == K::identifier &&
             m.state_names.contains(e.args[0]->text)) {
    out[e.args[0]->text] = runtime::ScriptValue::of_bool(false);
  }
}

// The mission's own variables (those actions write) at the first tick; the environment's are
// chosen on demand (Environment).
Product initial_product(const Model& m) {
  std::map<std::string, runtime::ScriptValue> fixed;
  if (m.world.initial) fixed_values(*m.world.initial, m, fixed);
  Product p;
  for (const StateVar& v : m.vars) {
    if (!v.relevant || v.env || v.unset_first) continue;
    std::vector<runtime::ScriptValue> values = v.values;
    // Only a boolean literal is fixed here; the initial condition is still checked on each.
    if (const auto it = fixed.find(v.name); it != fixed.end() && values.size() == 2 &&
                                            values[0].kind == runtime::ScriptValue::Kind::boolean)
      values = {it->second};
    p.vars.push_back(&v);
    if (p.size > (std::uint64_t{1} << 40) / values.size())
      throw ProveError(
          "the explicit-state engine cannot enumerate the mission's initial states: more than "
          "2^40 combinations of values");
    p.size *= values.size();
    p.values.push_back(std::move(values));
  }
  return p;
}

// The state after a tick as bytes: the engine's, the actions' progress, the monitors' words.
// The actions' progress as bytes: only the actions that run (index and ticks), as most do not
// between two ticks.
void append_elapsed(std::string& key, const std::vector<std::int64_t>& elapsed) {
  const std::uint32_t n = static_cast<std::uint32_t>(elapsed.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    // Four at a time past the idle ones.
    if (i + 4 <= n && (elapsed[i] | elapsed[i + 1] | elapsed[i + 2] | elapsed[i + 3]) == 0) {
      i += 3;
      continue;
    }
    if (elapsed[i] == 0) continue;
    key.append(reinterpret_cast<const char*>(&i), sizeof i);
    key.append(reinterpret_cast<const char*>(&elapsed[i]), sizeof elapsed[i]);
  }
  const std::uint32_t end = UINT32_MAX;
  key.append(reinterpret_cast<const char*>(&end), sizeof end);
}

void key_of(const runtime::TickTrail& trail, const std::vector<std::int64_t>& elapsed,
            const std::vector<std::uint64_t>& monitors, bool completed, std::string& key) {
  key.clear();
  trail.append_key(key);  // the engine's bytes
  append_elapsed(key, elapsed);
  key.append(reinterpret_cast<const char*>(monitors.data()),
             monitors.size() * sizeof(std::uint64_t));
  key += static_cast<char>(completed);
}

// Two independent 64-bit hashes of the same bytes, in one pass (word by word: a
// multiply-rotate lane and an FNV-style lane, each with a final avalanche), so that two
// different mid-tick states practically never share both.
std::pair<std::uint64_t, std::uint64_t> hash128(const std::string& bytes) {
  std::uint64_t h1 = 0x9e3779b97f4a7c15ull ^ bytes.size();
  std::uint64_t h2 = 0xcbf29ce484222325ull + bytes.size();
  std::size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t w;
    std::memcpy(&w, bytes.data() + i, 8);
    h1 = (h1 ^ (w * 0x87c37b91114253d5ull)) * 0x4cf5ad432745937full;
    h1 = (h1 << 31) | (h1 >> 33);
    h2 = (h2 ^ w) * 0x100000001b3ull;
    h2 ^= h2 >> 29;
  }
  std::uint64_t tail = 0;
  if (i < bytes.size()) std::memcpy(&tail, bytes.data() + i, bytes.size() - i);
  h1 = (h1 ^ (tail * 0x87c37b91114253d5ull)) * 0x4cf5ad432745937full;
  h2 = (h2 ^ tail) * 0x100000001b3ull;
  auto avalanche = [](std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
  };
  return {avalanche(h1), avalanche(h2)};
}

// What a saved engine state holds in memory, for Options::explicit_memory.
std::uint64_t bytes_of(const EngineState& e) {
  return sizeof e + e.status.size() * sizeof e.status[0] +
         e.counters.size() * sizeof e.counters[0] + e.child_done.size() +
         e.values.size() * sizeof e.values[0];
}

// The monitors' reads after tick `tick`, in the one order the search and its replay share: the
// state after the tick into `frame`, then property by property its atoms, each environment value
// still pending chosen when an atom reaches it (so a conjunction of N flags nobody else read
// branches N + 1 ways, not 2^N). `before(i)` is called before property i reads (the search
// may narrow the choices it offers there); `read(i, inputs)` gets its atoms; false stops.
template <typename Before, typename Read>
void read_monitors(Model& m, std::vector<monitor::Val>& frame, std::uint64_t tick, Before&& before,
                   Read&& read) {
  m.observables->fill(frame);
  m.fill_state(frame);
  monitor::Reader& reader = m.environment->monitor_reader(frame);
  for (std::size_t i = 0; i < m.properties.size(); ++i) {
    const Property& p = m.properties[i];
    if (!p.layout) continue;
    before(i);
    bool inputs[Property::kMaxAtoms] = {};
    p.read_atoms(frame, inputs, tick, &reader);
    if (!read(i, inputs)) break;
  }
  m.environment->monitors_read();
}

bool completed(NodeStatus s) {
  return s == NodeStatus::success || s == NodeStatus::failure || s == NodeStatus::skipped;
}

class Search {
 public:
  Search(Model& m, const Options& o) : m_(m), o_(o), order_(m) {
    initial_ = initial_product(m);
    base_.engine = m.fresh;
    base_.elapsed.assign(m.choice->leaves().size(), 0);
    base_.monitors.assign(m.monitor_words, 0);
    for (const Property& p : m.properties)
      if (p.layout) {
        const auto init = p.layout->initial();
        std::copy(init.begin(), init.end(), base_.monitors.begin() + p.offset);
      }
    for (std::size_t i = 0; i < m.vars.size(); ++i)
      if (m.vars[i].env && m.vars[i].relevant) env_vars_.push_back(i);
    result_.violations.resize(m.properties.size());
    result_.first_trigger.assign(m.properties.size(), 0);
  }

  SearchResult run() {
    // Choices within a tick often meet again (a flag read true, or read false and repaired at
    // once, leave the same state): a choice point reached again in the same mid-tick state
    // has nothing new below it.
    m_.choice->chooser.seen = [this](std::uint32_t site) { return seen_mid_tick(site); };
    m_.choice->set_horizon(o_.depth != 0 ? std::min<std::uint64_t>(o_.depth, o_.max_states)
                                         : o_.max_states);
    m_.observables->track_open(true);
    // A tick is resumed at the choice it changes, not ticked again from its start.
    trail_ = std::make_unique<runtime::TickTrail>(*m_.engine);
    m_.choice->chooser.reached = [this](std::uint32_t site, std::size_t at) {
      take_checkpoint(site, at);
    };
    struct Unset {
      Search& s;
      ~Unset() {
        s.m_.choice->chooser.seen = nullptr;
        s.m_.choice->chooser.reached = nullptr;
        s.m_.choice->set_horizon(UINT64_MAX);
        s.m_.observables->track_open(false);
        s.trail_.reset();
      }
    } unset{*this};
    ticks_at_start_ = m_.engine->stats().node_ticks;
    expand(base_, UINT32_MAX, true);
    std::uint64_t depth = 1;
    while (!frontier_.empty() && !all_violated() && !result_.vacuous &&
           !m_.environment->refined() && result_.budget_spent.empty()) {
      if (o_.depth != 0 && depth >= o_.depth) break;
      if (nodes_.size() >= o_.max_states) break;
      std::vector<std::uint32_t> next;
      next.swap(frontier_);
      for (std::uint32_t i : next) {
        expand(nodes_[i], i, false);
        // Only its place in the paths is needed once a state is expanded.
        release(nodes_[i]);
        if (!memo_on_) m_.choice->chooser.seen = nullptr;  // not even asked from now on
        if (nodes_.size() >= o_.max_states || result_.vacuous || spent()) break;
      }
      ++depth;
    }
    result_.complete = frontier_.empty() && !result_.vacuous && result_.budget_spent.empty();
    result_.depth = depth;
    result_.states = nodes_.size();
    return std::move(result_);
  }

 private:
  // Options::explicit_steps and explicit_memory.
  std::uint64_t steps() const {
    return m_.engine->stats().node_ticks - ticks_at_start_ + key_bytes_ + 256 * result_.transitions;
  }
  bool spent() {
    if (!result_.budget_spent.empty()) return true;
    if (steps() > o_.explicit_steps)
      result_.budget_spent = std::to_string(o_.explicit_steps) +
                             " steps: node ticks, the bytes of the states it compared, and 256 "
                             "a transition";
    else if (kept_bytes_ > o_.explicit_memory)
      result_.budget_spent = std::to_string(o_.explicit_memory >> 20) + " MiB of states kept";
    return !result_.budget_spent.empty();
  }
  std::uint64_t ticks_at_start_ = 0, key_bytes_ = 0, kept_bytes_ = 0;

  bool all_violated() const {
    for (std::size_t i = 0; i < m_.properties.size(); ++i)
      if (!m_.properties[i].assumption && m_.properties[i].layout && !result_.violations[i])
        return false;
    return true;
  }

  // The state in the middle of a tick as bytes: the engine's (blackboard included), what is
  // still pending, the actions' progress, what the tick has recorded, the monitors' words it
  // started from, and the choice point.
  bool seen_mid_tick(std::uint32_t site) {
    // Building the key costs a pass over the engine's state: where choices never meet again
    // (each path of the tick ends in a state of its own), stop looking after a while. The
    // monitors' reads after the tick are not looked up: where they stand is not in the key.
    if (!memo_on_ || monitors_reading_) return false;
    if (++memo_checks_ == kMemoTrial && memo_hits_ * 16 < memo_checks_) {
      memo_on_ = false;
      m_.observables->track_open(false);
    }
    std::string& key = mid_key_;
    key.clear();
    append_tick_state(key, [&](std::size_t i) { return m_.environment->live(i); });
    key.append(reinterpret_cast<const char*>(mid_monitors_->data()),
               mid_monitors_->size() * sizeof(std::uint64_t));
    key.append(reinterpret_cast<const char*>(&site), sizeof site);
    key_bytes_ += key.size();
    // Two independent 64-bit hashes: a collision would wrongly skip choices.
    const bool seen = !mid_tick_.insert(hash128(key)).second;
    memo_hits_ += seen;
    return seen;
  }
  // The state in the middle of a tick as bytes: which environment values are still pending, the
  // engine's (blackboard included), the actions' progress, what the tick has recorded. A value
  // chosen that nothing can read again (`matters(var)` false) is left out: put back to its
  // placeholder while the engine's bytes are taken.
  template <typename Matters>
  void append_tick_state(std::string& key, Matters&& matters) {
    runtime::Blackboard& bb = m_.engine->blackboard();
    hidden_.clear();
    for (std::size_t i : env_vars_) {
      const StateVar& v = m_.vars[i];
      const bool pending = bb.pending(v.slot);
      key += static_cast<char>(pending);
      if (!pending && !matters(i)) {
        hidden_.emplace_back(v.slot, v.values.front());
        std::swap(bb.value(v.slot), hidden_.back().second);
      }
    }
    trail_->append_key(key);
    for (auto& [slot, value] : hidden_) std::swap(bb.value(slot), value);
    append_elapsed(key, m_.choice->elapsed());
    m_.observables->append_tick_key(key);
  }

  // Whether the monitors' reads, about to go on at property `pos`, were at this point before in
  // this expansion (the state after the tick, the values the reads from `pos` on may still
  // read, the monitors' words, what failed or triggered so far) with assumption monitors that
  // allowed at least as much (AssumptionOrder). Then everything that can follow was followed.
  bool met_before(std::size_t pos, const std::vector<std::uint64_t>& monitors, bool done) {
    // As for the tick's own choices: where branches never meet, stop looking after a while.
    if (++met_checks_ == kMemoTrial && met_hits_ * 16 < met_checks_) met_on_ = false;
    std::string& key = met_key_;
    key.clear();
    append_tick_state(key, [&](std::size_t i) { return m_.environment->read_from(i, pos); });
    key.append(reinterpret_cast<const char*>(&pos), sizeof pos);
    key += static_cast<char>(done);
    tight_.clear();
    for (std::size_t j = 0; j < m_.properties.size(); ++j) {
      const Property& p = m_.properties[j];
      if (!p.layout) continue;
      const std::uint64_t* words = monitors.data() + p.offset;
      if (p.assumption && j < pos)
        tight_.insert(tight_.end(), words, words + p.layout->words());
      else
        key.append(reinterpret_cast<const char*>(words), p.layout->words() * sizeof *words);
    }
    // What failed or triggered so far; an assumption's trigger is nobody's answer.
    key.append(reinterpret_cast<const char*>(violated_.data()),
               violated_.size() * sizeof(std::size_t));
    key += '|';
    for (std::size_t j : triggered_)
      if (!m_.properties[j].assumption) key.append(reinterpret_cast<const char*>(&j), sizeof j);
    key_bytes_ += key.size();
    std::vector<std::vector<std::uint64_t>>& met = met_[hash128(key)];
    for (const auto& loose : met)
      if (covers(loose, tight_, pos)) {
        ++met_hits_;
        return true;
      }
    if (met.size() < kMetPerPoint) met.push_back(tight_);
    return false;
  }
  // Before assumption `i` reads a value no other property reads in this tick (nor a domain
  // assumption): only the values that leave its monitor loosest are offered. A value is left
  // out when another lets the monitor hold whenever it does and then covers its state
  // (AssumptionOrder); of two that cover each other, the first is kept. The run from the value
  // left out is one the kept value's run allows too, so no verdict or shortest violation
  // changes, and a flag seen once by `upon CheckK … always CheckK` is not a branch per tick.
  void offer_loosest(std::size_t i, const std::vector<std::uint64_t>& monitors,
                     std::uint64_t tick) {
    std::size_t var = SIZE_MAX;
    const std::vector<monitor::Val>* choices = m_.environment->sole_reader_choices(i, var);
    if (choices == nullptr) return;
    const Property& p = m_.properties[i];
    const std::size_t slot = static_cast<std::size_t>(m_.vars[var].frame);
    const monitor::Val placeholder = frame_[slot];
    const std::size_t n = choices->size();
    outcome_words_.assign(n, {});
    outcome_holds_.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
      frame_[slot] = (*choices)[k];
      bool inputs[Property::kMaxAtoms] = {};
      p.read_atoms(frame_, inputs, tick, nullptr);
      outcome_words_[k].assign(monitors.begin() + p.offset,
                               monitors.begin() + p.offset + p.layout->words());
      outcome_holds_[k] = p.layout->step(inputs, outcome_words_[k], scratch_);
    }
    frame_[slot] = placeholder;
    std::uint64_t allowed = 0;
    for (std::size_t k = 0; k < n; ++k) {
      bool left_out = false;
      for (std::size_t j = 0; j < n && !left_out; ++j) {
        if (j == k || (outcome_holds_[k] && !outcome_holds_[j])) continue;
        if (!order_.covers(i, outcome_words_[j].data(), outcome_words_[k].data())) continue;
        // Two that cover each other: the first stays.
        left_out = j < k || !order_.covers(i, outcome_words_[k].data(), outcome_words_[j].data());
      }
      if (!left_out) allowed |= std::uint64_t{1} << k;
    }
    m_.environment->offer_only(var, allowed);
  }
  std::vector<std::vector<std::uint64_t>> outcome_words_;
  std::vector<char> outcome_holds_;

  // Each assumption before `pos` in `loose` covers its words in `tight`.
  bool covers(const std::vector<std::uint64_t>& loose, const std::vector<std::uint64_t>& tight,
              std::size_t pos) {
    std::size_t at = 0;
    for (std::size_t j = 0; j < pos && j < m_.properties.size(); ++j) {
      const Property& p = m_.properties[j];
      if (!p.layout || !p.assumption) continue;
      if (!order_.covers(j, loose.data() + at, tight.data() + at)) return false;
      at += p.layout->words();
    }
    return true;
  }
  // The assumption states kept per meeting point: beyond it, branches are compared with these.
  static constexpr std::size_t kMetPerPoint = 16;
  static constexpr std::uint64_t kMemoTrial = 4096;
  bool memo_on_ = true;
  bool monitors_reading_ = false;  // the monitors' reads after the tick (read_monitors)
  std::uint64_t memo_checks_ = 0, memo_hits_ = 0;

  struct PairHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& p) const {
      return static_cast<std::size_t>(p.first ^ (p.second * 0x9e3779b97f4a7c15ull));
    }
  };

  static void release(Node& n) {
    n.engine = EngineState{};
    n.elapsed = {};
    n.monitors = {};
  }

  void restore(const Node& from) {
    from.engine.restore(*m_.engine);
    m_.choice->set_elapsed(from.elapsed);
  }

  // `from` may be an element of nodes_: a std::deque keeps references valid as it grows.
  void expand(const Node& from, std::uint32_t from_index, bool first) {
    const Product& start = first ? initial_ : next_;
    Outcomes outcomes;
    mid_tick_.clear();
    met_.clear();
    mid_monitors_ = &from.monitors;
    for (std::uint64_t e = 0; e < start.size; ++e) {
      if (!possible_start(from, start, e, first)) continue;
      // The first checkpoint is the state before the tick.
      std::vector<std::uint32_t> prefix;
      checkpoints_in_use_ = 0;
      trail_->begin();
      trail_->push();
      do {
        // A checkpoint taken at or past the choice that changes is of another sequence.
        while (checkpoints_in_use_ > 0 &&
               checkpoints_[checkpoints_in_use_ - 1].at >= prefix.size()) {
          --checkpoints_in_use_;
          trail_->pop();
        }
        const bool resume = checkpoints_in_use_ > 0;
        trail_->restore();
        if (resume) {
          const Checkpoint& c = checkpoints_[checkpoints_in_use_ - 1];
          m_.choice->set_elapsed(c.elapsed);
          m_.environment->undo(c.chosen);
          m_.observables->undo(c.observables);
          m_.choice->chooser.resume(prefix, c.at);
        } else {
          m_.choice->set_elapsed(from.elapsed);
          m_.choice->chooser.start(prefix);
          m_.environment->start_tick(first);
          m_.observables->begin_tick();
        }
        try {
          successor(from, from_index, Step{e, {}, {}, {}, {}}, outcomes, resume);
        } catch (const ChoicePruned&) {
        }
        m_.environment->end_tick();
      } while (!spent() && m_.choice->chooser.advance(prefix));
      if (!result_.budget_spent.empty()) return;
    }
    if (outcomes.kept == 0 && !outcomes.errors) vacuous(from, first, outcomes);
  }

  struct Outcomes {
    std::uint64_t kept = 0;                 // transitions the assumptions allow
    bool errors = false;                    // a tick that stopped with an error
    const Property* excluded_by = nullptr;  // an Environment requirement that pruned one
  };

  // Nothing can follow `from`: the first tick has no initial state, or a reachable state has
  // no allowed tick (a deadlock). Either way every "proof" from here on would be vacuous.
  void vacuous(const Node& from, bool first, const Outcomes& outcomes) {
    const Stuck kind = !first ? Stuck::deadlock
                       : outcomes.excluded_by == nullptr && m_.world.initial && initial_without_it()
                           ? Stuck::initial
                           : Stuck::assumptions;
    result_.vacuous = vacuity_of(
        m_, kind, from.tick, outcomes.excluded_by ? outcomes.excluded_by->requirement : nullptr);
  }

  // Whether the domain's assumptions alone leave some first state (so the initial condition
  // is what rules them all out).
  bool initial_without_it() {
    for (std::uint64_t e = 0; e < initial_.size; ++e)
      if (possible_start(base_, initial_, e, false)) return true;
    return false;
  }

  // Restores `from` with the start's e-th values: can the environment satisfy the assumptions
  // (`with_initial`: and the initial condition) there?
  bool possible_start(const Node& from, const Product& start, std::uint64_t e, bool with_initial) {
    restore(from);
    start.set(m_, e);
    m_.environment->start_tick(with_initial);
    const bool possible = m_.environment->satisfiable();
    m_.environment->end_tick();
    return possible;
  }

  // A checkpoint where the tick can be resumed (an action about to choose its outcome), when
  // none is taken at this choice yet.
  void take_checkpoint(std::uint32_t site, std::size_t at) {
    if (checkpoints_in_use_ > 0 && checkpoints_[checkpoints_in_use_ - 1].at >= at) return;
    if (!Chooser::outcome_site(site) || !trail_->resumable()) return;
    trail_->push();
    if (checkpoints_in_use_ == checkpoints_.size()) checkpoints_.emplace_back();
    Checkpoint& c = checkpoints_[checkpoints_in_use_++];
    c.at = at;
    c.elapsed = m_.choice->elapsed();
    c.chosen = m_.environment->chosen().size();
    m_.observables->mark(c.observables);
  }

  // `resume`: the tick goes on from the last checkpoint (restored), else it starts.
  void successor(const Node& from, std::uint32_t from_index, Step step, Outcomes& outcomes,
                 bool resume) {
    NodeStatus root;
    monitors_reading_ = false;
    try {
      root = resume ? m_.engine->resume_tick() : m_.engine->tick();
      ++result_.transitions;
    } catch (const runtime::TickException& e) {
      ++result_.transitions;
      // As in `uabt run`, the run stops there: the runs that go on are still explored.
      if (!result_.tick_error) result_.tick_error = tick_error_text(from.tick + 1, e.error.message);
      outcomes.errors = true;
      return;
    }
    Node next;
    next.monitors = from.monitors;
    next.tick = from.tick + 1;
    const bool done = completed(root);
    std::vector<std::size_t>& violated = violated_;
    std::vector<std::size_t>& triggered = triggered_;
    violated.clear();
    triggered.clear();
    const Property* excluded = nullptr;
    monitors_reading_ = true;
    std::size_t branchings = m_.choice->chooser.branchings();
    const auto offer = [&](std::size_t i) {
      if (o_.merge_monitor_reads && m_.properties[i].assumption)
        offer_loosest(i, next.monitors, next.tick);
    };
    read_monitors(m_, frame_, next.tick, offer, [&](std::size_t i, const bool* inputs) {
      const Property& p = m_.properties[i];
      std::vector<std::uint64_t>& words = words_;
      words.assign(next.monitors.begin() + p.offset,
                   next.monitors.begin() + p.offset + p.layout->words());
      const bool now = p.layout->step(inputs, words, scratch_);
      std::copy(words.begin(), words.end(), next.monitors.begin() + p.offset);
      if (p.triggered(scratch_)) triggered.push_back(i);
      const bool fails = !now && (monitor::verdict_is_final_once_violated(p.shape) || done);
      if (fails && p.assumption) {  // a world the assumptions exclude: no more need be read
        excluded = &p;
        return false;
      }
      if (fails) violated.push_back(i);
      // This read branched on values nobody had read: where it meets a branch of another
      // choice, the rest of the reads are taken once. (Within the prefix of the choices, the
      // point is where an earlier sequence of the same choices was.)
      const bool branched = m_.choice->chooser.branchings() != branchings;
      branchings = m_.choice->chooser.branchings();
      if (branched && met_on_ && m_.choice->chooser.past_prefix()) {
        if (met_before(i + 1, next.monitors, done)) {
          m_.environment->monitors_read();
          throw ChoicePruned{};
        }
      }
      return true;
    });
    monitors_reading_ = false;
    if (excluded != nullptr) {
      outcomes.excluded_by = excluded;
      return;
    }
    step.inner = m_.choice->chooser.taken();
    ++outcomes.kept;
    for (std::size_t i : triggered)
      if (result_.first_trigger[i] == 0) result_.first_trigger[i] = next.tick;
    for (std::size_t i : violated) {
      if (result_.violations[i]) continue;
      Finding f;
      f.property = i;
      f.tick = next.tick;
      f.path = path_to(from_index);
      f.path.push_back(step);
      result_.violations[i] = std::move(f);
    }
    // The environment's values are chosen afresh in every tick: once the monitors have read
    // them they do not matter, and states that differ only in them are one state.
    m_.environment->end_tick();
    key_of(*trail_, m_.choice->elapsed(), next.monitors, done, key_);
    key_bytes_ += key_.size();
    if (!seen_.insert(key_).second) return;
    next.engine = EngineState::save(*m_.engine);
    kept_bytes_ += key_.size() + bytes_of(next.engine);
    next.elapsed = m_.choice->elapsed();
    next.parent = from_index;
    next.step = std::move(step);
    nodes_.push_back(std::move(next));
    if (!done) frontier_.push_back(static_cast<std::uint32_t>(nodes_.size() - 1));
  }

  std::vector<Step> path_to(std::uint32_t index) const {
    std::vector<Step> path;
    for (std::uint32_t i = index; i != UINT32_MAX; i = nodes_[i].parent)
      path.push_back(nodes_[i].step);
    return {path.rbegin(), path.rend()};
  }

  Model& m_;
  const Options& o_;
  Product initial_, next_;  // next_: nothing to set before a later tick
  Node base_;
  std::deque<Node> nodes_;
  std::unordered_set<std::string> seen_;
  std::unordered_set<std::pair<std::uint64_t, std::uint64_t>, PairHash> mid_tick_;
  // The monitors' reads' meeting points (met_before): per key, the assumption states seen.
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>,
                     std::vector<std::vector<std::uint64_t>>, PairHash>
      met_;
  std::string met_key_;
  bool met_on_ = o_.merge_monitor_reads;
  std::uint64_t met_checks_ = 0, met_hits_ = 0;
  std::vector<std::uint64_t> tight_;
  AssumptionOrder order_;
  const std::vector<std::uint64_t>* mid_monitors_ = nullptr;
  std::string mid_key_;
  std::vector<std::pair<runtime::SlotId, runtime::ScriptValue>> hidden_;
  std::vector<std::size_t> env_vars_;  // the relevant environment variables (Model::vars)
  std::vector<std::size_t> violated_, triggered_;
  std::vector<std::uint64_t> words_;
  std::string key_;
  std::vector<std::uint32_t> frontier_;
  std::vector<monitor::Val> frame_;
  std::vector<char> scratch_;
  SearchResult result_;
  // The checkpoints of the tick being explored, by the choice they were taken at (trail_
  // keeps the engine's part of each); the first checkpoints_in_use_ are.
  struct Checkpoint {
    std::size_t at = 0;
    std::vector<std::int64_t> elapsed;
    std::size_t chosen = 0;  // Environment::chosen()
    runtime::TickObservation::Mark observables;
  };
  std::vector<Checkpoint> checkpoints_;
  std::size_t checkpoints_in_use_ = 0;
  std::unique_ptr<runtime::TickTrail> trail_;
};

}  // namespace

Vacuity vacuity_of(const Model& m, Stuck kind, std::uint64_t tick,
                   const fretish::Requirement* excluded_by) {
  std::string names;
  for (const auto& a : m.mission.domain.assumptions)
    names += (names.empty() ? "" : ", ") + a.name + " (" + a.location.file + ":" +
             std::to_string(a.location.line) + ")";
  Vacuity v;
  if (!m.mission.domain.assumptions.empty())
    v.location = m.mission.domain.assumptions.front().location;
  const std::string stuck = "after tick " + std::to_string(tick) + " of a reachable run, ";
  const std::string cannot = ": the run cannot go on (a deadlock)";
  if (excluded_by != nullptr) {
    v.location = excluded_by->location;
    v.message =
        kind == Stuck::deadlock
            ? stuck + "the Environment requirement '" + excluded_by->id +
                  "' rules out every next tick" + cannot
            : "the Environment requirement '" + excluded_by->id + "' rules out every first tick";
  } else if (kind == Stuck::initial) {
    v.location = {m.world.file, m.world.initial->range.begin_line,
                  m.world.initial->range.begin_column};
    v.message = "no state of the domain satisfies the initial condition `" +
                fretish::to_fretish(*m.world.initial) + "`" +
                (names.empty() ? std::string() : " together with the assumptions " + names);
  } else if (kind == Stuck::assumptions) {
    v.message = "the assumptions " + names + " rule out every state of the domain";
  } else {
    v.message = stuck + "no value of the environment satisfies the assumptions " + names +
                " in the state the mission is in" + cannot;
  }
  return v;
}

SearchResult explore(Model& model, const Options& options) {
  if (!model.explicit_refusal.empty()) throw ProveError(model.explicit_refusal);
  // Cells cut in the state at hand may be refined as the search goes (Environment::refined):
  // then it starts over with them, until a search needs no finer cell.
  for (;;) {
    model.environment->clear_refined();
    SearchResult result = Search(model, options).run();
    if (!model.environment->refined()) return result;
  }
}

std::string tick_error_text(std::uint64_t tick, const std::string& message) {
  return "tick " + std::to_string(tick) + " of a run: " + message;
}

std::string replay_tick_error(Model& model, const std::vector<Step>& path) {
  std::uint64_t at = 0;
  try {
    replay_path(
        model, path, [&](std::uint64_t tick) { at = tick; },
        [](std::uint64_t, NodeStatus, const std::vector<std::size_t>&) {});
  } catch (const runtime::TickException& e) {
    if (at == path.size()) return tick_error_text(at, e.error.message);
    throw ProveError("internal error: a run the symbolic engine stops with an error at tick " +
                     std::to_string(path.size()) + " stops at tick " + std::to_string(at) +
                     " in its replay: " + e.error.message);
  }
  throw ProveError("internal error: a run the symbolic engine stops with an error at tick " +
                   std::to_string(path.size()) + " does not stop in its replay");
}

void replay_path(Model& m, const std::vector<Step>& path,
                 const std::function<void(std::uint64_t)>& before_tick,
                 const std::function<void(std::uint64_t, NodeStatus,
                                          const std::vector<std::size_t>&)>& after_tick) {
  const bool symbolic = !path.empty() && !path.front().values.empty();
  const Product initial = symbolic ? Product{} : initial_product(m);
  // Every variable starts at its first value; the first step sets the relevant ones.
  m.fresh.restore(*m.engine);
  m.choice->set_elapsed(std::vector<std::int64_t>(m.choice->leaves().size(), 0));
  static const std::vector<std::size_t> kNone;
  std::vector<monitor::Val> frame;
  for (std::size_t t = 0; t < path.size(); ++t) {
    if (symbolic) {
      for (std::size_t i = 0; i < m.vars.size(); ++i)
        if (m.vars[i].relevant && ((t == 0 && !m.vars[i].unset_first) || m.vars[i].env))
          m.engine->blackboard().value(m.vars[i].slot) = path[t].values[i];
    } else {
      if (t == 0) initial.set(m, path[t].env);
      m.environment->start_tick(t == 0);
    }
    before_tick(t + 1);
    m.choice->force(symbolic ? &path[t].outcomes : nullptr, symbolic ? &path[t].outputs : nullptr);
    m.choice->chooser.start(path[t].inner);
    m.observables->begin_tick();
    NodeStatus root;
    try {
      root = m.engine->tick();
      // The choices the search made as the monitors read, in its order; the rest with their
      // first allowed value.
      if (!symbolic)
        read_monitors(
            m, frame, t + 1, [](std::size_t) {}, [](std::size_t, const bool*) { return true; });
      m.environment->resolve_monitor_reads();
    } catch (...) {
      m.choice->force(nullptr);
      m.environment->end_tick();
      throw;
    }
    m.choice->force(nullptr);
    after_tick(t + 1, root, symbolic ? kNone : m.environment->chosen());
    if (!symbolic) m.environment->end_tick();
  }
}

}  // namespace uabt::prove
