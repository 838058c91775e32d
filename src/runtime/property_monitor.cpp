#include "runtime/property_monitor.hpp"

#include <algorithm>
#include <set>

#include <nlohmann/json.hpp>

#include "base/number_text.hpp"

#include "runtime/blackboard.hpp"

namespace uabt::runtime {

namespace {

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
  boolean_variable_.clear();
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

  // The state variables: declared, a robot leaf, or set on the blackboard.
  std::set<std::string, std::less<>> state;
  for (const fretish::Variable& v : mission.domain.variables) state.insert(v.name);
  for (NodeId id = 0; id < engine_.node_count(); ++id)
    if (engine_.info(id).alive && engine_.children(id).empty()) state.insert(engine_.info(id).kind);
  for (const std::string& name : names)
    if (engine_.blackboard().get(name) != nullptr) state.insert(name);

  observation_.emplace(engine_, mission, std::move(state), variables_, symbols_);
  for (const std::string& name : names)
    if (literals.count(name) == 0 || mission.domain.find(name) != nullptr)
      observation_->resolve(name);
  // Every bound slot is written before each step; a name the new version no longer shows
  // reads as unknown rather than its last value.
  frame_.assign(variables_.size(), monitor::Val{});
  return literals;
}

void PropertyMonitor::on_node_ticked(NodeId node, NodeStatus result) {
  observation_->on_node_ticked(node, result);
}

void PropertyMonitor::select(const std::string& adaptable, const std::string& alternative,
                             const std::string& requirement) {
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
  const auto it = boolean_variable_.find(key);
  return state_value(engine_.blackboard().get(key), it == boolean_variable_.end() || it->second,
                     symbols_);
}

std::vector<PropertyViolation> PropertyMonitor::after_tick(std::uint64_t tick) {
  observation_->fill(frame_);
  observation_->begin_tick();
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
  // A variable without a value is written as null, so that `uabt monitor` reads the same
  // frame the run judged: a property decided where the value does not matter stays decided.
  Json state = Json::object();
  for (std::size_t slot = 0; slot < frame_.size(); ++slot)
    state[variables_.name(static_cast<int>(slot))] =
        frame_[slot].kind == monitor::Val::Kind::missing
            ? Json(nullptr)
            : value_json(monitor::value_of(frame_[slot], symbols_));
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
