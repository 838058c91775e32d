#include "runtime/property_monitor.hpp"

#include <algorithm>
#include <set>

#include <nlohmann/json.hpp>

#include "base/number_text.hpp"

#include "runtime/blackboard.hpp"
#include "runtime/observed_nodes.hpp"

namespace uabt::runtime {

namespace {

constexpr std::uint8_t kSuccess = 1, kFailure = 2, kRunning = 4, kTicked = 8;

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void collect(const fretish::ExprPtr& e, std::set<std::string>& names) {
  if (!e) return;
  for (const std::string& n : fretish::identifiers_of(*e)) names.insert(n);
}

}  // namespace

PropertyMonitor::PropertyMonitor(const load::Mission& mission, const Engine& engine)
    : engine_(engine) {
  const std::set<std::string> literals = bind(mission);
  monitor::Vocabulary vocabulary{&variables_, &symbols_, literals};
  properties_.emplace(mission.properties, mission.domain.assumptions, vocabulary);
  bind_selections(mission, literals);
}

void PropertyMonitor::bind_selections(const load::Mission& mission,
                                      const std::set<std::string>& literals,
                                      std::optional<std::uint64_t> swapped_after) {
  if (!judge_) {
    judge_.emplace(mission.selections, symbols_, literals);
  } else {
    // The merged version's requirements, as it states them, from the next tick on.
    std::set<std::string> adaptables;
    for (const load::AdaptableSite& site : mission.adaptables) adaptables.insert(site.id);
    for (const fretish::SelectionRequirement& r : mission.selections)
      adaptables.insert(r.adaptable);
    for (const std::string& id : adaptables)
      judge_->update(id, mission.selections, literals, swapped_after.value_or(0));
  }
  selecting_.clear();
  for (const fretish::SelectionRequirement& r : mission.selections) {
    Selecting& s = selecting_[r.adaptable];
    s.requirements.push_back(r.id);
    for (const fretish::Requirement& written : mission.requirements)
      if (written.id == r.id && written.location.file == r.location.file &&
          written.location.line == r.location.line &&
          written.location.column == r.location.column) {
        fretish::Requirement sentence;
        sentence.id = written.id;
        sentence.text = written.text;
        sentence.location = written.location;
        s.sentences.push_back(std::move(sentence));
        break;
      }
    if (r.guard)
      for (const std::string& name : fretish::identifiers_of(*r.guard))
        if ((literals.count(name) == 0 || mission.domain.find(name) != nullptr) &&
            std::find(s.reads.begin(), s.reads.end(), name) == s.reads.end())
          s.reads.push_back(name);
  }
  for (const load::Alternative& alt : mission.alternatives)
    if (auto it = selecting_.find(alt.adaptable); it != selecting_.end())
      it->second.alternatives.push_back(alt.name);
  for (auto& [id, s] : selecting_) {
    judge_->set_order(id, s.requirements);
    s.calls = engine_.subtree_calls(id);
    for (const std::string& name : s.reads) {
      const fretish::Variable* declared = mission.domain.find(name);
      boolean_variable_.emplace(name,
                                declared == nullptr || declared->type == fretish::VarType::boolean);
    }
  }
  header_due_ = true;
}

std::vector<PropertyViolation> PropertyMonitor::adopt(const load::Mission& mission,
                                                      std::uint64_t last_tick) {
  const std::set<std::string> literals = bind(mission);
  std::vector<PropertyViolation> out;
  for (std::size_t i :
       properties_->update(mission.properties, mission.domain.assumptions, literals, last_tick))
    out.push_back({last_tick, properties_->result(i)});
  bind_selections(mission, literals, last_tick);
  return out;
}

std::set<std::string> PropertyMonitor::bind(const load::Mission& mission) {
  // Every name the properties read.
  std::set<std::string> names;
  for (const fretish::Requirement& r : mission.properties) {
    if (r.scope) {
      if (!r.scope->mode.empty()) names.insert(r.scope->mode);
      collect(r.scope->condition, names);
    }
    for (const auto& c : r.conditions) collect(c.expr, names);
    collect(r.response, names);
    collect(r.timing.stop_condition, names);
  }
  for (const auto& a : mission.domain.assumptions) collect(a.expr, names);

  std::set<std::string> literals{"none"};
  for (const load::Alternative& alt : mission.alternatives) literals.insert(alt.name);
  for (const fretish::Variable& v : mission.domain.variables)
    for (const std::string& literal : v.enum_values) literals.insert(literal);

  std::set<std::string> leaf_kinds;
  for (NodeId id = 0; id < engine_.node_count(); ++id)
    if (engine_.info(id).alive && engine_.children(id).empty())
      leaf_kinds.insert(engine_.info(id).kind);
  std::set<std::string> adaptable_ids;
  for (const load::AdaptableSite& site : mission.adaptables) adaptable_ids.insert(site.id);

  // A selection in progress carries over a swap (the adaptable keeps its id).
  std::vector<Adaptable> before = std::move(adaptables_);
  nodes_.clear();
  adaptables_.clear();
  blackboard_.clear();
  boolean_variable_.clear();
  for (const std::string& name : names) {
    if (literals.count(name) != 0 && mission.domain.find(name) == nullptr) continue;
    bool node_observable = false;
    for (const char* suffix : {".success", ".failure", ".running"}) {
      if (!ends_with(name, suffix)) continue;
      const std::string label = name.substr(0, name.size() - std::string(suffix).size());
      std::vector<NodeId> nodes = observed_nodes(engine_, mission, label);
      if (nodes.empty()) break;
      auto it = std::find_if(nodes_.begin(), nodes_.end(),
                             [&](const NodeObservable& o) { return o.nodes == nodes; });
      if (it == nodes_.end()) it = nodes_.insert(nodes_.end(), make_node_observable(nodes));
      const int slot = variables_.id(name);
      (suffix[1] == 's' ? it->success : suffix[1] == 'f' ? it->failure : it->running) = slot;
      node_observable = true;
    }
    if (node_observable) continue;
    std::string adaptable = name;
    const bool selected = ends_with(name, ".selected");
    if (selected) adaptable = name.substr(0, name.size() - 9);
    if (adaptable_ids.count(adaptable) != 0) {
      auto it = std::find_if(adaptables_.begin(), adaptables_.end(),
                             [&](const Adaptable& a) { return a.id == adaptable; });
      if (it == adaptables_.end()) {
        it = adaptables_.insert(adaptables_.end(), make_adaptable(adaptable));
        it->calls = engine_.subtree_calls(adaptable);
        for (const Adaptable& old : before)
          if (old.id == adaptable) {
            it->chosen = old.chosen;
            it->running = old.running;
          }
      }
      (selected ? it->selected : it->mode) = variables_.id(name);
      continue;
    }
    // A variable of the world: declared, a robot leaf, or set on the blackboard.
    const fretish::Variable* declared = mission.domain.find(name);
    if (declared != nullptr || leaf_kinds.count(name) != 0 ||
        engine_.blackboard().get(name) != nullptr) {
      blackboard_.emplace_back(variables_.id(name), name);
      boolean_variable_[name] = declared == nullptr || declared->type == fretish::VarType::boolean;
    }
  }
  // Every bound slot is written before each step; a name the new version no longer shows
  // reads as unknown rather than its last value.
  frame_.assign(variables_.size(), monitor::Val{});
  seen_.resize(engine_.node_count(), 0);
  return literals;
}

void PropertyMonitor::on_node_ticked(NodeId node, NodeStatus result) {
  if (node >= seen_.size()) seen_.resize(node + 1, 0);
  // What the node returned last in the tick (a wake-up re-tick returns again); a node halted
  // or reset without a tick returned nothing.
  seen_[node] = kTicked | (result == NodeStatus::success   ? kSuccess
                           : result == NodeStatus::failure ? kFailure
                           : result == NodeStatus::running ? kRunning
                                                           : 0);
}

void PropertyMonitor::select(const std::string& adaptable, const std::string& alternative,
                             const std::string& requirement) {
  for (Adaptable& a : adaptables_) {
    if (a.id != adaptable) continue;
    a.chosen = alternative;
    a.running = alternative;
  }
  const auto it = selecting_.find(adaptable);
  if (it == selecting_.end()) return;
  Selecting& s = it->second;
  monitor::SelectionRecord record{adaptable, alternative, "", {}};
  // A later branch than the one still running: the selection went on past that branch.
  const auto rank = [&](const std::string& id) {
    return std::find(s.requirements.begin(), s.requirements.end(), id) - s.requirements.begin();
  };
  if (!s.running.empty() && rank(s.running) < rank(requirement)) record.after = s.running;
  s.running = requirement;
  for (const std::string& name : s.reads) record.read.emplace_back(name, read(name));
  selected_.push_back(std::move(record));
}

monitor::Val PropertyMonitor::read(const std::string& key) {
  const ScriptValue* v = engine_.blackboard().get(key);
  if (v == nullptr || v->empty()) {
    const auto it = boolean_variable_.find(key);
    return it == boolean_variable_.end() || it->second ? monitor::Val::of_bool(false)
                                                       : monitor::Val{};
  }
  if (v->kind == ScriptValue::Kind::boolean) return monitor::Val::of_bool(v->boolean);
  if (v->is_number())
    return v->kind == ScriptValue::Kind::integer ? monitor::Val::of_integer(v->as_double())
                                                 : monitor::Val::of_number(v->as_double());
  return monitor::Val::of_symbol(symbols_.id(v->text));
}

std::vector<PropertyViolation> PropertyMonitor::after_tick(std::uint64_t tick) {
  const auto bits = [&](NodeId n) -> std::uint8_t { return n < seen_.size() ? seen_[n] : 0; };
  for (const NodeObservable& o : nodes_) {
    std::uint8_t any = 0;
    for (NodeId n : o.nodes) any |= bits(n);
    if (o.success >= 0)
      frame_[static_cast<std::size_t>(o.success)] = monitor::Val::of_bool(any & kSuccess);
    if (o.failure >= 0)
      frame_[static_cast<std::size_t>(o.failure)] = monitor::Val::of_bool(any & kFailure);
    if (o.running >= 0)
      frame_[static_cast<std::size_t>(o.running)] = monitor::Val::of_bool(any & kRunning);
  }
  for (Adaptable& a : adaptables_) {
    bool ticked = false, still_running = false;
    for (NodeId n : a.calls) {
      ticked = ticked || (bits(n) & kTicked);
      still_running = still_running || engine_.status(n) == NodeStatus::running;
    }
    if (a.mode >= 0) frame_[static_cast<std::size_t>(a.mode)] = monitor::Val::of_bool(ticked);
    const std::string selected = !a.chosen.empty()              ? a.chosen
                                 : ticked && !a.running.empty() ? a.running
                                                                : std::string("none");
    if (a.selected >= 0)
      frame_[static_cast<std::size_t>(a.selected)] = monitor::Val::of_symbol(symbols_.id(selected));
    a.chosen.clear();
    if (!still_running) a.running.clear();
  }
  for (const auto& [slot, key] : blackboard_) frame_[static_cast<std::size_t>(slot)] = read(key);
  std::fill(seen_.begin(), seen_.end(), 0);
  for (const monitor::SelectionRecord& record : selected_) judge_->observe(tick, record);
  traced_ = std::move(selected_);
  selected_.clear();
  for (auto& [id, s] : selecting_)
    if (std::none_of(s.calls.begin(), s.calls.end(),
                     [&](NodeId n) { return engine_.status(n) == NodeStatus::running; }))
      s.running.clear();
  std::vector<PropertyViolation> out;
  for (std::size_t i : properties_->step(frame_, tick))
    out.push_back({tick, properties_->result(i)});
  return out;
}

std::string PropertyMonitor::monitor_trace_line(std::uint64_t tick) {
  using Json = nlohmann::ordered_json;
  std::string out;
  if (header_due_ && !selecting_.empty()) {
    Json nodes = Json::object();
    for (const auto& [id, s] : selecting_) {
      Json sentences = Json::object();
      for (const fretish::Requirement& r : s.sentences)
        sentences[r.id] = {{"text", r.text},
                           {"file", r.location.file},
                           {"line", r.location.line},
                           {"column", r.location.column}};
      nodes[id] = {{"alternatives", s.alternatives},
                   {"requirements", s.requirements},
                   {"sentences", std::move(sentences)}};
    }
    out += Json{{"selection", std::move(nodes)}}.dump() + "\n";
  }
  header_due_ = false;
  Json state = Json::object();
  for (std::size_t slot = 0; slot < frame_.size(); ++slot) {
    if (frame_[slot].kind == monitor::Val::Kind::missing) continue;
    state[variables_.name(static_cast<int>(slot))] =
        value_json(monitor::value_of(frame_[slot], symbols_));
  }
  Json line = {{"tick", tick}, {"state", std::move(state)}};
  if (!traced_.empty()) {
    Json select = Json::object();
    for (const monitor::SelectionRecord& r : traced_) {
      Json read = Json::object();
      for (const auto& [name, value] : r.read)
        if (value.kind != monitor::Val::Kind::missing)
          read[name] = value_json(monitor::value_of(value, symbols_));
      Json one = {{"alternative", r.alternative}, {"read", std::move(read)}};
      if (!r.after.empty()) one["after"] = r.after;
      if (!select.contains(r.adaptable)) select[r.adaptable] = Json::array();
      select[r.adaptable].push_back(std::move(one));
    }
    line["select"] = std::move(select);
  }
  return out + line.dump() + "\n";
}

std::vector<monitor::PropertyResult> PropertyMonitor::results() const {
  std::vector<monitor::PropertyResult> out = judge_->results();
  for (monitor::PropertyResult& r : properties_->results()) out.push_back(std::move(r));
  return out;
}

std::vector<PropertyViolation> PropertyMonitor::at_end(std::uint64_t last_tick) const {
  std::vector<PropertyViolation> out;
  for (std::size_t i : properties_->violated_at_end())
    out.push_back({last_tick, properties_->result(i)});
  return out;
}

bool PropertyMonitor::guarantees_failed() const {
  for (const monitor::PropertyResult& r : results())
    if (!r.assumption && r.verdict != monitor::Verdict::held) return true;
  return false;
}

}  // namespace uabt::runtime
