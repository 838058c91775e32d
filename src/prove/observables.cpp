#include "prove/observables.hpp"

#include <algorithm>

#include "runtime/observed_nodes.hpp"
#include "runtime/selection.hpp"

namespace uabt::prove {

using runtime::NodeId;
using runtime::NodeStatus;

std::vector<NodeId> status_nodes(const runtime::Engine& engine, const load::Mission& mission,
                                 const std::string& node) {
  return runtime::observed_nodes(engine, mission, node);
}

std::map<NodeId, std::string> alternative_calls(const runtime::Engine& engine,
                                                const load::Mission& mission,
                                                const std::string& node) {
  std::map<NodeId, std::string> out;
  for (NodeId id = 0; id < engine.node_count(); ++id) {
    const runtime::NodeInfo& info = engine.info(id);
    if (!info.alive || info.tree_id != node) continue;
    // The rule `uabt run` reports its selections by, whatever the selection's style.
    const NodeId selector = runtime::SelectionObserver::selector_of(engine, id);
    if (selector == runtime::kNoNode || engine.info(selector).name != node) continue;
    const std::string* tree = info.element ? info.element->attribute("ID") : nullptr;
    if (tree == nullptr) continue;
    std::string alt = *tree;
    for (const auto& a : mission.alternatives)
      if (a.adaptable == node && a.tree_id == *tree) alt = a.name;
    out[id] = alt;
  }
  return out;
}

Observables::Observables(const runtime::Engine& engine, const load::Mission& mission,
                         std::set<std::string, std::less<>> state, monitor::Variables& variables,
                         monitor::Symbols& symbols)
    : engine_(engine),
      mission_(mission),
      state_(std::move(state)),
      variables_(variables),
      symbols_(symbols) {
  last_.assign(engine.node_count(), NodeStatus::idle);
}

monitor::Val Observables::value_of(const runtime::ScriptValue& v, monitor::Symbols& symbols) {
  using K = runtime::ScriptValue::Kind;
  switch (v.kind) {
    case K::empty: return {};
    case K::boolean: return monitor::Val::of_bool(v.boolean);
    case K::integer: return monitor::Val::of_integer(static_cast<double>(v.integer));
    case K::real: return monitor::Val::of_number(v.real);
    case K::string: return monitor::Val::of_symbol(symbols.id(v.text));
  }
  return {};
}

monitor::Resolved Observables::resolve(const std::string& name) {
  using R = monitor::Resolved;
  if (auto slot = variables_.find(name)) {
    // Registered by another property, or a state variable the caller reads itself.
    bool known = false;
    for (const StateObs& s : states_) known = known || s.slot == *slot;
    if (!known && state_.contains(name)) states_.push_back({name, *slot});
    return {R::Kind::variable, *slot};
  }
  // A state variable: declared in the domain, or a condition.
  if (state_.contains(name)) {
    const int slot = variables_.id(name);
    states_.push_back({name, slot});
    return {R::Kind::variable, slot};
  }
  // <node>.success / .failure / .running
  const auto dot = name.rfind('.');
  if (dot != std::string::npos) {
    const std::string node = name.substr(0, dot), field = name.substr(dot + 1);
    if (field == "success" || field == "failure" || field == "running") {
      std::vector<NodeId> nodes = status_nodes(engine_, mission_, node);
      if (!nodes.empty()) {
        const int slot = variables_.id(name);
        const NodeStatus s = field == "success"   ? NodeStatus::success
                             : field == "failure" ? NodeStatus::failure
                                                  : NodeStatus::running;
        observed_.insert(observed_.end(), nodes.begin(), nodes.end());
        statuses_.push_back({std::move(nodes), s, slot});
        return {R::Kind::variable, slot};
      }
    }
    if (field == "selected") {
      for (const auto& site : mission_.adaptables) {
        if (site.id != node) continue;
        SelectedObs obs{variables_.id(name), std::vector<int>(engine_.node_count(), -1)};
        for (const auto& [call, alt] : alternative_calls(engine_, mission_, node))
          obs.alternative_of_call[call] = symbols_.id(alt);
        selected_.push_back(std::move(obs));
        last_alternative_.push_back(-1);
        return {R::Kind::variable, selected_.back().slot};
      }
    }
  }
  // The mode of an adaptable node.
  for (const auto& site : mission_.adaptables) {
    if (site.id != name) continue;
    ModeObs mode{engine_.subtree_calls(name), variables_.id(name)};
    observed_.insert(observed_.end(), mode.calls.begin(), mode.calls.end());
    modes_.push_back(std::move(mode));
    return {R::Kind::variable, modes_.back().slot};
  }
  // Literals: enum values, alternative names, `none`.
  bool literal = name == "none" || mission_.domain.enum_owning(name) != nullptr;
  for (const auto& a : mission_.alternatives) literal = literal || a.name == name;
  if (literal) return {R::Kind::literal, symbols_.id(name)};
  return {};
}

void Observables::begin_tick() {
  for (NodeId n : touched_) last_[n] = NodeStatus::idle;
  touched_.clear();
  before_.clear();
  open_.clear();
  std::fill(last_alternative_.begin(), last_alternative_.end(), -1);
}

void Observables::mark(Mark& out) const {
  out.touched = touched_.size();
  out.open = open_;
  out.alternatives = last_alternative_;
}

void Observables::undo(const Mark& mark) {
  for (std::size_t k = touched_.size(); k > mark.touched; --k)
    last_[touched_[k - 1]] = before_[k - 1];
  touched_.resize(mark.touched);
  before_.resize(mark.touched);
  open_ = mark.open;
  last_alternative_ = mark.alternatives;
}

void Observables::on_node_ticked(NodeId node, NodeStatus result) {
  if (node >= last_.size()) last_.resize(node + 1, NodeStatus::idle);
  before_.push_back(last_[node]);
  last_[node] = result;
  touched_.push_back(node);
  for (std::size_t i = 0; i < selected_.size(); ++i)
    if (node < selected_[i].alternative_of_call.size() &&
        selected_[i].alternative_of_call[node] >= 0)
      last_alternative_[i] = selected_[i].alternative_of_call[node];
  if (!track_open_) return;
  if (parent_.size() != engine_.node_count()) {
    parent_.resize(engine_.node_count());
    for (NodeId n = 0; n < parent_.size(); ++n) parent_[n] = engine_.info(n).parent;
  }
  std::erase_if(open_, [&](NodeId child) { return parent_[child] == node; });
  if (std::find(open_.begin(), open_.end(), node) == open_.end()) open_.push_back(node);
}

void Observables::append_tick_key(std::string& out) const {
  // Returns a node's parent has not yet consumed (its loop may still look at them), and every
  // return a property reads; a return whose parent has returned since matters to nothing.
  std::vector<std::pair<NodeId, NodeStatus>> record;
  for (NodeId n : open_) record.emplace_back(n, last_[n]);
  for (NodeId n : observed_)
    if (n < last_.size() && last_[n] != NodeStatus::idle) record.emplace_back(n, last_[n]);
  std::sort(record.begin(), record.end());
  record.erase(std::unique(record.begin(), record.end()), record.end());
  for (const auto& [n, status] : record) {
    out.append(reinterpret_cast<const char*>(&n), sizeof n);
    out += static_cast<char>(status);
  }
  out += '|';
  for (int a : last_alternative_) out.append(reinterpret_cast<const char*>(&a), sizeof a);
}

void Observables::fill(std::vector<monitor::Val>& frame) const {
  frame.resize(variables_.size());
  for (const StateObs& s : states_) {
    const runtime::ScriptValue* v = engine_.blackboard().get(s.key);
    frame[s.slot] = v ? value_of(*v, symbols_) : monitor::Val{};
  }
  for (const StatusObs& s : statuses_) {
    bool any = false;
    for (NodeId n : s.nodes) any = any || last_[n] == s.status;
    frame[s.slot] = monitor::Val::of_bool(any);
  }
  for (std::size_t i = 0; i < selected_.size(); ++i)
    frame[selected_[i].slot] = monitor::Val::of_symbol(
        last_alternative_[i] >= 0 ? last_alternative_[i] : symbols_.id("none"));
  for (const ModeObs& m : modes_) {
    bool ticked = false;
    for (NodeId n : m.calls) ticked = ticked || last_[n] != NodeStatus::idle;
    frame[m.slot] = monitor::Val::of_bool(ticked);
  }
}

}  // namespace uabt::prove
