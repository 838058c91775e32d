// The scenario-driven simulated world (see SimWorld in world.hpp).
#include "runtime/world.hpp"

#include <algorithm>

namespace uabt::runtime {

const char* leaf_event_name(LeafEvent event) {
  switch (event) {
    case LeafEvent::condition: return "condition";
    case LeafEvent::action_started: return "started";
    case LeafEvent::action_finished: return "finished";
    case LeafEvent::action_halted: return "halted";
  }
  return "?";
}

SimWorld::SimWorld(Scenario scenario, std::vector<bt::NodeModel> robot_nodes)
    : scenario_(std::move(scenario)), robot_nodes_(std::move(robot_nodes)) {}

void SimWorld::apply_initial(Blackboard& blackboard) const {
  for (const auto& [key, value] : scenario_.initial) blackboard.set(key, value);
}

void SimWorld::apply_event(const ScenarioEvent& event, Blackboard& blackboard) const {
  for (const auto& [key, value] : event.set) blackboard.set(key, value);
}

std::string qualified_leaf_key(const std::string& name, std::span<const LeafPort> ports,
                               const std::function<std::string(const LeafPort&)>& value) {
  if (ports.empty()) return name;
  std::vector<const LeafPort*> sorted;
  for (const LeafPort& p : ports) sorted.push_back(&p);
  std::sort(sorted.begin(), sorted.end(),
            [](const LeafPort* a, const LeafPort* b) { return a->name < b->name; });
  std::string key = name + "(";
  for (std::size_t i = 0; i < sorted.size(); ++i)
    key += (i ? "," : "") + sorted[i]->name + "=" + value(*sorted[i]);
  return key + ")";
}

std::string SimWorld::qualified_key(const Leaf& leaf, std::span<const LeafPort> ports,
                                    const Blackboard& blackboard) const {
  return qualified_leaf_key(leaf.name, ports, [&](const LeafPort& p) {
    return p.from_blackboard() ? blackboard.value(p.slot).to_string() : p.literal;
  });
}

std::uint32_t SimWorld::bind_leaf(const LeafBinding& binding) {
  Leaf leaf;
  leaf.node = binding.node;
  leaf.name = binding.kind;
  leaf.dynamic = std::any_of(binding.ports.begin(), binding.ports.end(),
                             [](const LeafPort& p) { return p.from_blackboard(); });
  leaf.label = qualified_key(leaf, binding.ports, binding.blackboard);
  const std::string& qualified = leaf.label;

  auto action_it = scenario_.actions.find(qualified);
  if (action_it == scenario_.actions.end()) action_it = scenario_.actions.find(leaf.name);
  std::string family = binding.declared_family;
  if (family.empty()) {
    for (const bt::NodeModel& model : robot_nodes_)
      if (model.id == leaf.name) family = model.family;
  }
  if (action_it != scenario_.actions.end()) {
    leaf.condition = false;
  } else if (family == "Condition" || family == "Action") {
    leaf.condition = family == "Condition";
  } else {
    leaf.condition = scenario_.mentions_state(leaf.name) || scenario_.mentions_state(qualified);
  }

  Blackboard& bb = binding.blackboard;
  if (leaf.condition) {
    if (!leaf.dynamic && qualified != leaf.name)
      leaf.qualified = bb.resolve(Blackboard::kRootScope, qualified);
    leaf.plain = bb.resolve(Blackboard::kRootScope, leaf.name);
  } else if (action_it != scenario_.actions.end()) {
    leaf.action = &action_it->second;
    leaf.label = action_it->first;
    for (const auto& [key, value] : leaf.action->effects)
      leaf.effects.emplace_back(bb.resolve(Blackboard::kRootScope, key), value);
  } else if (leaf.dynamic) {
    leaf.label = leaf.name;
  }
  leaves_.push_back(std::move(leaf));
  return static_cast<std::uint32_t>(leaves_.size() - 1);
}

const ScriptValue* SimWorld::condition_value(const Leaf& leaf, const LeafContext& context,
                                             std::string& dynamic_key) const {
  const ScriptValue* value = nullptr;
  if (leaf.dynamic) {
    dynamic_key = qualified_key(leaf, context.ports, context.blackboard);
    value = context.blackboard.get(dynamic_key);
  } else if (leaf.qualified != kNoSlot && !context.blackboard.value(leaf.qualified).empty()) {
    value = &context.blackboard.value(leaf.qualified);
  }
  if (value == nullptr && !context.blackboard.value(leaf.plain).empty())
    value = &context.blackboard.value(leaf.plain);
  return value;
}

std::vector<std::pair<std::string, ScriptValue>> SimWorld::condition_reads(
    const LeafContext& context) const {
  const Leaf& leaf = leaves_[context.handle];
  if (!leaf.condition) return {};
  std::string dynamic_key;
  const ScriptValue* value = condition_value(leaf, context, dynamic_key);
  std::string key = leaf.dynamic ? dynamic_key : leaf.label;
  if (value != nullptr && value == &context.blackboard.value(leaf.plain)) key = leaf.name;
  return {{std::move(key), value ? *value : ScriptValue{}}};
}

NodeStatus SimWorld::tick_leaf(const LeafContext& context) {
  Leaf& leaf = leaves_[context.handle];
  if (leaf.condition) {
    std::string dynamic_key;
    const ScriptValue* value = condition_value(leaf, context, dynamic_key);
    const bool truth = value != nullptr && value->is_number() && value->as_double() != 0.0;
    const NodeStatus s = truth ? NodeStatus::success : NodeStatus::failure;
    if (log_conditions_)
      log_.push_back({context.tick, leaf.node, leaf.dynamic ? dynamic_key : leaf.label,
                      LeafEvent::condition, s});
    return s;
  }

  if (leaf.elapsed == 0) {
    log_.push_back(
        {context.tick, leaf.node, leaf.label, LeafEvent::action_started, NodeStatus::running});
    leaf.run = nullptr;
    if (leaf.action && !leaf.action->runs.empty()) {
      const std::size_t n = starts_[leaf.action]++;
      if (n < leaf.action->runs.size()) leaf.run = &leaf.action->runs[n];
    }
  }
  ++leaf.elapsed;
  const std::int64_t needed = leaf.run ? leaf.run->ticks : leaf.action ? leaf.action->ticks : 1;
  if (leaf.elapsed < needed) return NodeStatus::running;
  leaf.elapsed = 0;
  NodeStatus result = leaf.action ? leaf.action->result : NodeStatus::success;
  // The outputs first (the node's setOutput before it returns), then the world's effects.
  const StateAssignment* outputs = leaf.run      ? &leaf.run->outputs
                                   : leaf.action ? &leaf.action->outputs
                                                 : nullptr;
  if (outputs != nullptr)
    for (const auto& [port, value] : *outputs)
      for (const LeafPort& p : context.ports)
        if (p.name == port && p.writes_entry()) context.blackboard.value(p.slot) = value;
  if (leaf.run) {
    for (const auto& [key, value] : leaf.run->effects) context.blackboard.set(key, value);
    result = leaf.run->result;
  } else {
    for (const auto& [slot, value] : leaf.effects) context.blackboard.value(slot) = value;
  }
  log_.push_back({context.tick, leaf.node, leaf.label, LeafEvent::action_finished, result});
  return result;
}

void SimWorld::halt_leaf(const LeafContext& context) {
  Leaf& leaf = leaves_[context.handle];
  if (leaf.condition) return;
  leaf.elapsed = 0;
  log_.push_back({context.tick, leaf.node, leaf.label, LeafEvent::action_halted, NodeStatus::idle});
}

}  // namespace uabt::runtime
