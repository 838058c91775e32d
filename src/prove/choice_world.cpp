#include "prove/choice_world.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "runtime/scenario_check.hpp"

namespace uabt::prove {

using runtime::NodeStatus;

void Chooser::start(const std::vector<std::uint32_t>& prefix) {
  taken_ = prefix;
  arity_.assign(prefix.size(), 0);
  allowed_.assign(prefix.size(), ~std::uint64_t{0});
  pos_ = 0;
  branchings_ = 0;
  forced_ = prefix.size();
}

void Chooser::resume(const std::vector<std::uint32_t>& prefix, std::size_t at) {
  taken_ = prefix;
  arity_.resize(prefix.size(), 0);
  allowed_.resize(prefix.size(), ~std::uint64_t{0});
  pos_ = at;
  forced_ = prefix.size();
}

std::uint32_t Chooser::choose(std::uint32_t options, std::uint32_t site, std::uint64_t allowed) {
  if (pos_ >= forced_ && seen && seen(site)) {
    taken_.resize(pos_);
    arity_.resize(pos_);
    allowed_.resize(pos_);
    throw ChoicePruned{};
  }
  if (reached) reached(site, pos_);
  const std::uint64_t options_bits =
      options >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << options) - 1;
  branchings_ += options >= 64 || std::popcount(allowed & options_bits) > 1;
  if (pos_ < taken_.size()) {
    arity_[pos_] = options;
    allowed_[pos_] = allowed;
    taken_[pos_] %= options;  // a prefix from elsewhere (a random walk) may exceed it
    return taken_[pos_++];
  }
  const std::uint32_t first =
      allowed == 0 ? 0 : static_cast<std::uint32_t>(std::countr_zero(allowed));
  taken_.push_back(std::min(first, options - 1));
  arity_.push_back(options);
  allowed_.push_back(allowed);
  ++pos_;
  return taken_.back();
}

bool Chooser::advance(std::vector<std::uint32_t>& prefix) const {
  prefix.assign(taken_.begin(), taken_.begin() + static_cast<std::ptrdiff_t>(pos_));
  while (!prefix.empty()) {
    const std::size_t i = prefix.size() - 1;
    std::uint32_t next = prefix[i] + 1;
    while (next < arity_[i] && next < 64 && ((allowed_[i] >> next) & 1) == 0) ++next;
    if (next < arity_[i]) {
      prefix[i] = next;
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

std::string leaf_state_key(const std::string& name, std::span<const runtime::LeafPort> ports) {
  for (const auto& p : ports)
    if (p.from_blackboard()) return name;
  return runtime::qualified_leaf_key(name, ports,
                                     [](const runtime::LeafPort& p) { return p.literal; });
}

std::uint32_t ChoiceWorld::bind_leaf(const runtime::LeafBinding& binding) {
  Leaf leaf;
  leaf.node = binding.node;
  leaf.name = binding.kind;
  const std::string key = leaf_state_key(leaf.name, binding.ports);
  for (const auto& p : binding.ports)
    if (p.reads_entry()) leaf.inputs.push_back(p.slot);
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
    for (const auto& p : binding.ports) {
      if (!p.writes_entry()) continue;
      Leaf::Output out{p.name, p.slot, nullptr};
      if (leaf.contract)
        if (const auto it = leaf.contract->outputs.find(p.name); it != leaf.contract->outputs.end())
          out.fixed = &it->second;
      leaf.outputs.push_back(std::move(out));
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
      elapsed = c == nullptr                                          ? 1
                : static_cast<std::uint64_t>(c->max_ticks) > horizon_ ? std::min(now, c->min_ticks)
                                                                      : now;
      return NodeStatus::running;
    }
    --pick;
  }
  const NodeStatus result = results[pick];
  // While its outputs and its effect run, the action's progress says which result it ends
  // with: a choice made there (a value an output gets, a value the effect reads) is another
  // point of the tick for each result, and the explicit engine's mid-tick memo keys on it.
  elapsed = -1 - static_cast<std::int64_t>(pick);
  struct Ended {
    std::int64_t& elapsed;
    ~Ended() { elapsed = 0; }
  } ended{elapsed};
  // Its output ports first (the node's setOutput before it returns), then the world's effect.
  for (std::size_t k = 0; k < leaf.outputs.size(); ++k) {
    const Leaf::Output& out = leaf.outputs[k];
    runtime::ScriptValue& entry = context.blackboard.value(out.slot);
    if (out.fixed != nullptr) {
      entry = *out.fixed;
      const std::string& name = context.blackboard.key(out.slot);
      if (const fretish::Variable* var = domain_ ? domain_->find(name) : nullptr;
          var != nullptr && context.blackboard.owner(out.slot) == runtime::Blackboard::kRootScope)
        if (const std::string why = runtime::misfit_message(name, entry, *var); !why.empty())
          throw WorldError(leaf.contract->location,
                           "action '" + leaf.label + "' outputs '" + out.port + "': " + why);
      continue;
    }
    const auto values = output_values.find(out.slot);
    if (values == output_values.end() || values->second.empty())
      throw std::runtime_error("internal error: no values for the output port '" + out.port +
                               "' of '" + leaf.label + "'");
    if (forced_) {
      const std::size_t n = forced_next_[context.handle];
      if (forced_outputs_ == nullptr || n == 0 || (*forced_outputs_)[context.handle].size() < n ||
          (*forced_outputs_)[context.handle][n - 1].size() <= k)
        throw std::runtime_error("internal error: the counterexample does not say what '" +
                                 leaf.label + "' writes to '" + out.port + "'");
      entry = (*forced_outputs_)[context.handle][n - 1][k];
      continue;
    }
    const std::uint32_t n = static_cast<std::uint32_t>(values->second.size());
    const std::uint32_t k_value =
        n > 1 ? chooser.choose(n, (1u << 31) + 64 * context.handle + static_cast<std::uint32_t>(k))
              : 0;
    entry = values->second[k_value];
  }
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
