#include "prove/explore.hpp"

#include <deque>
#include <functional>
#include <map>
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

Product product(const Model& m, bool initial) {
  std::map<std::string, runtime::ScriptValue> fixed;
  if (initial && m.world.initial) fixed_values(*m.world.initial, m, fixed);
  Product p;
  for (const StateVar& v : m.vars) {
    if (!v.relevant || (!initial && !v.env)) continue;
    std::vector<runtime::ScriptValue> values = v.values;
    // Only a boolean literal is fixed here; the initial condition is still checked on each.
    if (const auto it = fixed.find(v.name); it != fixed.end() && values.size() == 2 &&
                                            values[0].kind == runtime::ScriptValue::Kind::boolean)
      values = {it->second};
    p.vars.push_back(&v);
    if (p.size > (std::uint64_t{1} << 40) / values.size())
      throw ProveError(
          "the explicit-state engine cannot enumerate the environment: more than 2^40 "
          "combinations of values per tick");
    p.size *= values.size();
    p.values.push_back(std::move(values));
  }
  return p;
}

std::string key_of(const Node& n, bool completed) {
  std::string key;
  n.engine.append_key(key);
  for (std::int64_t e : n.elapsed) key.append(reinterpret_cast<const char*>(&e), sizeof e);
  for (std::uint64_t w : n.monitors) key.append(reinterpret_cast<const char*>(&w), sizeof w);
  key += static_cast<char>(completed);
  return key;
}

bool completed(NodeStatus s) {
  return s == NodeStatus::success || s == NodeStatus::failure || s == NodeStatus::skipped;
}

class Search {
 public:
  Search(Model& m, const Options& o) : m_(m), o_(o) {
    initial_ = product(m, true);
    env_ = product(m, false);
    base_.engine = m.fresh;
    base_.elapsed.assign(m.choice->leaves().size(), 0);
    base_.monitors.assign(m.monitor_words, 0);
    for (const Property& p : m.properties)
      if (p.layout) {
        const auto init = p.layout->initial();
        std::copy(init.begin(), init.end(), base_.monitors.begin() + p.offset);
      }
    result_.violations.resize(m.properties.size());
  }

  SearchResult run() {
    expand(base_, UINT32_MAX, true);
    std::uint64_t depth = 1;
    while (!frontier_.empty() && !all_violated()) {
      if (o_.depth != 0 && depth >= o_.depth) break;
      if (nodes_.size() >= o_.max_states) break;
      std::vector<std::uint32_t> next;
      next.swap(frontier_);
      for (std::uint32_t i : next) {
        expand(nodes_[i], i, false);
        if (nodes_.size() >= o_.max_states) break;
      }
      ++depth;
    }
    result_.complete = frontier_.empty();
    result_.depth = depth;
    result_.states = nodes_.size();
    return std::move(result_);
  }

 private:
  bool all_violated() const {
    for (std::size_t i = 0; i < m_.properties.size(); ++i)
      if (!m_.properties[i].assumption && m_.properties[i].layout && !result_.violations[i])
        return false;
    return true;
  }

  void restore(const Node& from) {
    from.engine.restore(*m_.engine);
    m_.choice->set_elapsed(from.elapsed);
  }

  // `from` may be an element of nodes_: a std::deque keeps references valid as it grows.
  void expand(const Node& from, std::uint32_t from_index, bool first) {
    const Product& env = first ? initial_ : env_;
    for (std::uint64_t e = 0; e < env.size; ++e) {
      restore(from);
      env.set(m_, e);
      if (first && m_.initial && !m_.holds(*m_.initial, frame_)) continue;
      bool assumed = true;
      for (auto& a : m_.assumptions) assumed = assumed && m_.holds(*a, frame_);
      if (!assumed) continue;
      const EngineState before = EngineState::save(*m_.engine);
      std::vector<std::uint32_t> prefix;
      do {
        before.restore(*m_.engine);
        m_.choice->set_elapsed(from.elapsed);
        m_.choice->chooser.start(prefix);
        successor(from, from_index, Step{e, {}, {}, {}});
      } while (m_.choice->chooser.advance(prefix));
    }
  }

  void successor(const Node& from, std::uint32_t from_index, Step step) {
    ++result_.transitions;
    m_.observables->begin_tick();
    NodeStatus root;
    try {
      root = m_.engine->tick();
    } catch (const runtime::TickException& e) {
      if (!result_.tick_error) result_.tick_error = e.error.message;
      return;
    }
    step.inner = m_.choice->chooser.taken();
    Node next;
    next.monitors = from.monitors;
    next.tick = from.tick + 1;
    const bool done = completed(root);
    m_.observables->fill(frame_);
    m_.fill_state(frame_);
    std::vector<std::size_t> violated;
    for (std::size_t i = 0; i < m_.properties.size(); ++i) {
      const Property& p = m_.properties[i];
      if (!p.layout) continue;
      bool inputs[4] = {false, false, false, false};
      for (std::size_t k = 0; k < 4; ++k) {
        if (!p.parts[k]) continue;
        std::string error;
        inputs[k] = p.parts[k]->evaluate_bool(frame_, error);
        if (!error.empty())
          throw ProveError(p.requirement->id + ": at tick " + std::to_string(next.tick) + ": " +
                           error);
      }
      std::vector<std::uint64_t> words(next.monitors.begin() + p.offset,
                                       next.monitors.begin() + p.offset + p.layout->words());
      const bool now = p.layout->step(inputs, words, scratch_);
      std::copy(words.begin(), words.end(), next.monitors.begin() + p.offset);
      const bool fails = !now && (monitor::verdict_is_final_once_violated(p.shape) || done);
      if (!fails) continue;
      if (p.assumption) return;  // a world the assumptions exclude
      violated.push_back(i);
    }
    for (std::size_t i : violated) {
      if (result_.violations[i]) continue;
      Finding f;
      f.property = i;
      f.tick = next.tick;
      f.path = path_to(from_index);
      f.path.push_back(step);
      result_.violations[i] = std::move(f);
    }
    // The environment's values are chosen afresh before every tick: once the monitors have
    // read them they do not matter, and states that differ only in them are one state.
    for (const StateVar* v : env_.vars) m_.engine->blackboard().value(v->slot) = v->values.front();
    next.engine = EngineState::save(*m_.engine);
    next.elapsed = m_.choice->elapsed();
    std::string key = key_of(next, done);
    if (!seen_.insert(std::move(key)).second) return;
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
  Product initial_, env_;
  Node base_;
  std::deque<Node> nodes_;
  std::unordered_set<std::string> seen_;
  std::vector<std::uint32_t> frontier_;
  std::vector<monitor::Val> frame_;
  std::vector<char> scratch_;
  SearchResult result_;
};

}  // namespace

SearchResult explore(Model& model, const Options& options) {
  if (!model.explicit_refusal.empty()) throw ProveError(model.explicit_refusal);
  return Search(model, options).run();
}

void replay_path(Model& m, const std::vector<Step>& path,
                 const std::function<void(std::uint64_t)>& before_tick,
                 const std::function<void(std::uint64_t, NodeStatus)>& after_tick) {
  const bool symbolic = !path.empty() && !path.front().values.empty();
  const Product initial = symbolic ? Product{} : product(m, true);
  const Product env = symbolic ? Product{} : product(m, false);
  // Every variable starts at its first value; the first step sets the relevant ones.
  m.fresh.restore(*m.engine);
  m.choice->set_elapsed(std::vector<std::int64_t>(m.choice->leaves().size(), 0));
  for (std::size_t t = 0; t < path.size(); ++t) {
    if (symbolic) {
      for (std::size_t i = 0; i < m.vars.size(); ++i)
        if (m.vars[i].relevant && (t == 0 || m.vars[i].env))
          m.engine->blackboard().value(m.vars[i].slot) = path[t].values[i];
    } else {
      (t == 0 ? initial : env).set(m, path[t].env);
    }
    before_tick(t + 1);
    m.choice->force(symbolic ? &path[t].outcomes : nullptr);
    m.choice->chooser.start(path[t].inner);
    m.observables->begin_tick();
    NodeStatus root;
    try {
      root = m.engine->tick();
    } catch (...) {
      m.choice->force(nullptr);
      throw;
    }
    m.choice->force(nullptr);
    after_tick(t + 1, root);
  }
}

std::uint64_t environment_product(const Model& m) {
  if (!m.explicit_refusal.empty()) return 0;
  std::uint64_t size = 1;
  for (const StateVar& v : m.vars) {
    if (!v.relevant || !v.env) continue;
    if (size > UINT64_MAX / v.values.size()) return UINT64_MAX;
    size *= v.values.size();
  }
  return size;
}

}  // namespace uabt::prove
