#include "prove/choice_world.hpp"

#include <algorithm>
#include <stdexcept>

#include "runtime/scenario_check.hpp"

namespace uabt::prove {

using runtime::NodeStatus;

void Chooser::start(const std::vector<std::uint32_t>& prefix) {
  taken_ = prefix;
  arity_.assign(prefix.size(), 0);
  pos_ = 0;
  forced_ = prefix.size();
}

std::uint32_t Chooser::choose(std::uint32_t options, std::uint32_t site) {
  if (pos_ >= forced_ && seen && seen(site)) {
    taken_.resize(pos_);
    arity_.resize(pos_);
    throw ChoicePruned{};
  }
  if (pos_ < taken_.size()) {
    arity_[pos_] = options;
    taken_[pos_] %= options;  // a prefix from elsewhere (a random walk) may exceed it
    return taken_[pos_++];
  }
  taken_.push_back(0);
  arity_.push_back(options);
  ++pos_;
  return 0;
}

bool Chooser::advance(std::vector<std::uint32_t>& prefix) const {
  prefix.assign(taken_.begin(), taken_.begin() + static_cast<std::ptrdiff_t>(pos_));
  while (!prefix.empty()) {
    const std::size_t i = prefix.size() - 1;
    if (prefix[i] + 1 < arity_[i]) {
      ++prefix[i];
      return true;
    }
    prefix.pop_back();
  }
  return false;
}

ChoiceWorld::ChoiceWorld(const WorldModel& model, std::vector<bt::NodeModel> node_models,
                         std::set<std::string, std::less<>> state_names,
                         const fretish::Domain* domain)
    : model_(model),
      models_(std::move(node_models)),
      state_names_(std::move(state_names)),
      domain_(domain) {}

namespace {

std::string qualified(const std::string& name, std::span<const runtime::LeafPort> ports) {
  if (ports.empty()) return name;
  std::vector<const runtime::LeafPort*> sorted;
  for (const auto& p : ports) sorted.push_back(&p);
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->name < b->name; });
  std::string key = name + "(";
  for (std::size_t i = 0; i < sorted.size(); ++i)
    key += (i ? "," : "") + sorted[i]->name + "=" + sorted[i]->literal;
  return key + ")";
}

}  // namespace

std::uint32_t ChoiceWorld::bind_leaf(const runtime::LeafBinding& binding) {
  Leaf leaf;
  leaf.node = binding.node;
  leaf.name = binding.kind;
  for (const auto& p : binding.ports)
    if (p.from_blackboard())
      throw std::runtime_error("leaf '" + leaf.name + "' reads port '" + p.name +
                               "' from the blackboard; prove models literal ports only");
  const std::string key = qualified(leaf.name, binding.ports);
  std::string family = binding.declared_family;
  if (family.empty())
    for (const auto& m : models_)
      if (m.id == leaf.name) family = m.family;
  leaf.contract = model_.find(key, leaf.name);
  if (leaf.contract) {
    leaf.condition = false;
  } else if (family == "Condition" || family == "Action") {
    leaf.condition = family == "Condition";
  } else {
    leaf.condition = state_names_.contains(key) || state_names_.contains(leaf.name);
  }
  if (leaf.condition) {
    leaf.label = state_names_.contains(key) ? key : leaf.name;
    leaf.key = binding.blackboard.resolve(runtime::Blackboard::kRootScope, leaf.label);
  } else {
    leaf.label = leaf.contract ? leaf.contract->name : leaf.name;
    auto compile = [&](const std::string& code, std::optional<runtime::script::Program>& out) {
      if (code.empty()) return;
      out = runtime::script::Program::parse(code);
      out->bind(binding.blackboard, runtime::Blackboard::kRootScope);
      for (auto& n : assigned_names(code)) leaf.writes.push_back(n);
    };
    if (leaf.contract) {
      compile(leaf.contract->on_success, leaf.on_success);
      compile(leaf.contract->on_failure, leaf.on_failure);
    }
  }
  leaves_.push_back(std::move(leaf));
  elapsed_.push_back(0);
  return static_cast<std::uint32_t>(leaves_.size() - 1);
}

NodeStatus ChoiceWorld::tick_leaf(const runtime::LeafContext& context) {
  Leaf& leaf = leaves_[context.handle];
  if (leaf.condition) {
    const runtime::ScriptValue& v = context.blackboard.read(leaf.key);
    return v.is_number() && v.as_double() != 0.0 ? NodeStatus::success : NodeStatus::failure;
  }
  std::int64_t& elapsed = elapsed_[context.handle];
  if (recorder) recorder->ticked(context.handle, elapsed == 0);
  const std::int64_t now = elapsed + 1;
  // Options: keep running (when the contract allows more ticks), or end with each result.
  const ActionContract* c = leaf.contract;
  static const std::vector<NodeStatus> kFree = {NodeStatus::success, NodeStatus::failure};
  const std::vector<NodeStatus>& results = c ? c->results : kFree;
  const bool may_run = c ? now < c->max_ticks : true;
  const bool may_end = c ? now >= c->min_ticks : true;
  const std::uint32_t options =
      (may_run ? 1u : 0u) + (may_end ? static_cast<std::uint32_t>(results.size()) : 0u);
  std::uint32_t pick = 0;
  if (forced_) {
    const auto& list = (*forced_)[context.handle];
    std::size_t& next = forced_next_[context.handle];
    if (next >= list.size())
      throw std::runtime_error("internal error: action '" + leaf.label +
                               "' is ticked more often than the counterexample says");
    const std::int32_t outcome = list[next++];
    if ((outcome < 0 && !may_run) ||
        (outcome >= 0 && (!may_end || static_cast<std::size_t>(outcome) >= results.size())))
      throw std::runtime_error("internal error: action '" + leaf.label + "' cannot have outcome " +
                               std::to_string(outcome) + " here");
    pick = outcome < 0 ? 0 : static_cast<std::uint32_t>(outcome) + (may_run ? 1u : 0u);
  } else if (options > 1) {
    pick = chooser.choose(options, 2 * context.handle);
  }
  if (may_run) {
    if (pick == 0) {
      elapsed = c ? now : 1;
      return NodeStatus::running;
    }
    --pick;
  }
  const NodeStatus result = results[pick];
  elapsed = 0;
  auto& effect = result == NodeStatus::success ? leaf.on_success : leaf.on_failure;
  if (effect) {
    try {
      effect->run(context.blackboard);
    } catch (const std::exception& e) {
      throw std::runtime_error(model_.file + ": action '" + leaf.label + "' " +
                               (result == NodeStatus::success ? "on_success" : "on_failure") +
                               ": " + e.what());
    }
    // An effect that leaves a variable outside its declaration (`HardRock = ~HardRock` makes
    // a boolean -2, as BehaviorTree.CPP computes it) describes a world the domain rules out:
    // the proof and its counterexample would be about states no run of the mission has.
    if (domain_ != nullptr)
      for (const std::string& name : leaf.writes) {
        const fretish::Variable* var = domain_->find(name);
        const runtime::ScriptValue* value = context.blackboard.get(name);
        if (var == nullptr || value == nullptr) continue;
        if (const std::string why = runtime::misfit_message(name, *value, *var); !why.empty())
          throw WorldError(leaf.contract->location,
                           "action '" + leaf.label + "' " +
                               (result == NodeStatus::success ? "on_success" : "on_failure") +
                               ": " + why);
      }
  }
  if (recorder) recorder->ended(context.handle, result);
  return result;
}

void ChoiceWorld::halt_leaf(const runtime::LeafContext& context) {
  if (leaves_[context.handle].condition) return;
  if (recorder) recorder->halted(context.handle);
  elapsed_[context.handle] = 0;
}

}  // namespace uabt::prove
