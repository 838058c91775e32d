#include "runtime/tick_observation.hpp"

#include <algorithm>

#include "runtime/observed_nodes.hpp"
#include "runtime/selection.hpp"

namespace uabt::runtime {

namespace {

// The SubTree calls of the alternatives of `adaptable` in its selection tree, in any selection
// style, with the alternative each one calls.
std::map<NodeId, std::string> alternative_calls(const Engine& engine, const load::Mission& mission,
                                                const std::string& adaptable) {
  std::map<NodeId, std::string> out;
  for (NodeId id = 0; id < engine.node_count(); ++id) {
    const NodeInfo& info = engine.info(id);
    if (!info.alive || info.tree_id != adaptable) continue;
    // The rule `uabt run` reports its selections by, whatever the selection's style.
    const NodeId selector = SelectionObserver::selector_of(engine, id);
    if (selector == kNoNode || engine.info(selector).name != adaptable) continue;
    const std::string* tree = info.element ? info.element->attribute("ID") : nullptr;
    if (tree == nullptr) continue;
    std::string alt = *tree;
    for (const auto& a : mission.alternatives)
      if (a.adaptable == adaptable && a.tree_id == *tree) alt = a.name;
    out[id] = alt;
  }
  return out;
}

}  // namespace

Observable observable_of(const Engine& engine, const load::Mission& mission,
                         const std::set<std::string, std::less<>>& state, const std::string& name) {
  Observable o;
  if (state.contains(name)) {
    o.kind = Observable::Kind::state;
    const fretish::Variable* declared = mission.domain.find(name);
    o.boolean = declared == nullptr || declared->type == fretish::VarType::boolean;
    return o;
  }
  const auto dot = name.rfind('.');
  if (dot != std::string::npos) {
    const std::string node = name.substr(0, dot), field = name.substr(dot + 1);
    if (field == "success" || field == "failure" || field == "running") {
      o.nodes = observed_nodes(engine, mission, node);
      if (!o.nodes.empty()) {
        o.kind = Observable::Kind::status;
        o.status = field == "success"   ? NodeStatus::success
                   : field == "failure" ? NodeStatus::failure
                                        : NodeStatus::running;
        return o;
      }
    }
    if (field == "selected")
      for (const load::AdaptableSite& site : mission.adaptables)
        if (site.id == node) {
          o.kind = Observable::Kind::selected;
          o.alternatives = alternative_calls(engine, mission, node);
          return o;
        }
  }
  for (const load::AdaptableSite& site : mission.adaptables)
    if (site.id == name) {
      o.kind = Observable::Kind::mode;
      o.nodes = engine.subtree_calls(name);
      return o;
    }
  bool literal = name == "none" || mission.domain.enum_owning(name) != nullptr;
  for (const load::Alternative& a : mission.alternatives) literal = literal || a.name == name;
  if (literal) o.kind = Observable::Kind::literal;
  return o;
}

monitor::Val TickObservation::value_of(const ScriptValue& v, monitor::Symbols& symbols) {
  using K = ScriptValue::Kind;
  switch (v.kind) {
    case K::empty: return {};
    case K::boolean: return monitor::Val::of_bool(v.boolean);
    case K::integer: return monitor::Val::of_whole(v.integer);
    case K::real: return monitor::Val::of_number(v.real);
    case K::string: return monitor::Val::of_symbol(symbols.id(v.text));
  }
  return {};
}

monitor::Val state_value(const ScriptValue* value, bool boolean, monitor::Symbols& symbols) {
  if (value == nullptr || value->empty())
    return boolean ? monitor::Val::of_bool(false) : monitor::Val{};
  return TickObservation::value_of(*value, symbols);
}

TickObservation::TickObservation(const Engine& engine, const load::Mission& mission,
                                 std::set<std::string, std::less<>> state,
                                 monitor::Variables& variables, monitor::Symbols& symbols)
    : engine_(engine),
      mission_(mission),
      state_(std::move(state)),
      variables_(variables),
      symbols_(symbols) {
  last_.assign(engine.node_count(), NodeStatus::idle);
}

monitor::Resolved TickObservation::resolve(const std::string& name) {
  using R = monitor::Resolved;
  if (const auto known = resolved_.find(name); known != resolved_.end()) return known->second;
  Observable o = observable_of(engine_, mission_, state_, name);
  R out;
  switch (o.kind) {
    case Observable::Kind::state:
      out = {R::Kind::variable, variables_.id(name)};
      states_.push_back({name, out.id, o.boolean});
      break;
    case Observable::Kind::status:
      out = {R::Kind::variable, variables_.id(name)};
      observed_.insert(observed_.end(), o.nodes.begin(), o.nodes.end());
      statuses_.push_back({std::move(o.nodes), o.status, out.id});
      break;
    case Observable::Kind::selected: {
      out = {R::Kind::variable, variables_.id(name)};
      SelectedObs obs{out.id, std::vector<int>(engine_.node_count(), -1)};
      for (const auto& [call, alt] : o.alternatives)
        obs.alternative_of_call[call] = symbols_.id(alt);
      selected_.push_back(std::move(obs));
      last_alternative_.push_back(-1);
      break;
    }
    case Observable::Kind::mode:
      out = {R::Kind::variable, variables_.id(name)};
      observed_.insert(observed_.end(), o.nodes.begin(), o.nodes.end());
      modes_.push_back({std::move(o.nodes), out.id});
      break;
    case Observable::Kind::literal: out = {R::Kind::literal, symbols_.id(name)}; break;
    case Observable::Kind::unknown:
      // A slot the caller reads itself.
      if (auto slot = variables_.find(name)) out = {R::Kind::variable, *slot};
      break;
  }
  resolved_.emplace(name, out);
  return out;
}

void TickObservation::begin_tick() {
  for (NodeId n : touched_) last_[n] = NodeStatus::idle;
  touched_.clear();
  before_.clear();
  set_open({});
  std::fill(last_alternative_.begin(), last_alternative_.end(), -1);
}

void TickObservation::mark(Mark& out) const {
  out.touched = touched_.size();
  out.open = open_;
  out.alternatives = last_alternative_;
}

void TickObservation::undo(const Mark& mark) {
  for (std::size_t k = touched_.size(); k > mark.touched; --k)
    last_[touched_[k - 1]] = before_[k - 1];
  touched_.resize(mark.touched);
  before_.resize(mark.touched);
  set_open(mark.open);
  last_alternative_ = mark.alternatives;
}

void TickObservation::on_node_ticked(NodeId node, NodeStatus result) {
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
    is_open_.assign(parent_.size(), 0);
    open_children_.assign(parent_.size(), 0);
    for (NodeId n : open_) count_open(n, true);
  }
  // Counted per parent, so that a Fallback of 60,000 children costs one pass when it returns,
  // not one per child.
  if (open_children_[node] > 0) {
    std::erase_if(open_, [&](NodeId child) {
      if (parent_[child] != node) return false;
      is_open_[child] = 0;
      return true;
    });
    open_children_[node] = 0;
  }
  if (!is_open_[node]) {
    open_.push_back(node);
    count_open(node, true);
  }
}

void TickObservation::count_open(NodeId node, bool open) {
  is_open_[node] = open ? 1 : 0;
  if (parent_[node] == kNoNode) return;
  if (open)
    ++open_children_[parent_[node]];
  else
    --open_children_[parent_[node]];
}

void TickObservation::set_open(const std::vector<NodeId>& open) {
  if (!is_open_.empty())
    for (NodeId n : open_) count_open(n, false);
  open_ = open;
  if (!is_open_.empty())
    for (NodeId n : open_) count_open(n, true);
}

void TickObservation::append_tick_key(std::string& out) const {
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

void TickObservation::fill(std::vector<monitor::Val>& frame) const {
  frame.resize(variables_.size());
  const auto returned = [&](NodeId n) { return n < last_.size() ? last_[n] : NodeStatus::idle; };
  for (const StateObs& s : states_)
    frame[s.slot] = state_value(engine_.blackboard().get(s.key), s.boolean, symbols_);
  for (const StatusObs& s : statuses_) {
    bool any = false;
    for (NodeId n : s.nodes) any = any || returned(n) == s.status;
    frame[s.slot] = monitor::Val::of_bool(any);
  }
  for (std::size_t i = 0; i < selected_.size(); ++i)
    frame[selected_[i].slot] = monitor::Val::of_symbol(
        last_alternative_[i] >= 0 ? last_alternative_[i] : symbols_.id("none"));
  for (const ModeObs& m : modes_) {
    bool ticked = false;
    for (NodeId n : m.calls) ticked = ticked || returned(n) != NodeStatus::idle;
    frame[m.slot] = monitor::Val::of_bool(ticked);
  }
}

}  // namespace uabt::runtime
