// Hot swap: replacing one tree's definition in a running engine between two ticks.
// BT.CPP cannot do this (it rebuilds the whole tree); here an instance of the tree is rebuilt
// in place: new nodes are appended, the SubTree node (or the engine's root) is re-pointed at
// them, and the old ones are retired. Nothing outside the instance is halted or reset.
#include "runtime/core.hpp"

namespace uabt::runtime {

namespace {

// Marks a retired instance's nodes (and the instances they call) dead.
void retire(detail::Core& core, NodeId root) {
  std::vector<NodeId> stack{root};
  while (!stack.empty()) {
    const NodeId n = stack.back();
    stack.pop_back();
    core.nodes[n].alive = false;
    core.info[n].alive = false;
    const detail::RtNode& node = core.nodes[n];
    if (node.kind == detail::Kind::subtree)
      core.instances[core.params[node.params].instance].alive = false;
    for (std::uint32_t i = 0; i < node.child_count; ++i) stack.push_back(core.child(n, i));
  }
}

// The trees calling `instance`, outermost first: SubTree cycles through a new definition are
// caught as in a first build.
std::vector<std::string> callers(const detail::Core& core, std::uint32_t instance) {
  std::vector<std::string> chain;
  for (NodeId call = core.instances[instance].call; call != kNoNode;) {
    const std::uint32_t caller = core.info[call].instance;
    chain.insert(chain.begin(), core.instances[caller].tree_id);
    call = core.instances[caller].call;
  }
  return chain;
}

bool is_running(const detail::Core& core, std::uint32_t instance) {
  const detail::Instance& inst = core.instances[instance];
  const NodeId top = inst.call == kNoNode ? inst.root : inst.call;
  return core.nodes[top].status == NodeStatus::running;
}

// Rebuilds one instance from `def` on its own scope. Throws LoadError (nothing changed then).
void rebuild(detail::Core& core, std::uint32_t instance,
             const std::shared_ptr<const bt::TreeDef>& def) {
  const detail::CoreMark before = detail::mark(core);
  detail::Builder builder(core);
  builder.call_stack = callers(core, instance);
  NodeId new_root = kNoNode;
  try {
    new_root = builder.instantiate_tree(def, instance, core.instances[instance].call);
  } catch (...) {
    detail::rollback(core, before);
    throw;
  }
  detail::Instance& inst = core.instances[instance];
  const NodeId old_root = inst.root;
  if (inst.call == kNoNode) {
    core.root = new_root;
  } else {
    core.children[core.nodes[inst.call].first_child] = new_root;
  }
  inst.root = new_root;
  inst.pending.reset();
  retire(core, old_root);
  ++core.stats.swaps;
}

}  // namespace

void Engine::define_tree(bt::TreeDef def) {
  auto& slot = core_->defs[def.id];
  if (slot) core_->retired.push_back(slot);
  slot = std::make_shared<const bt::TreeDef>(std::move(def));
}

bool Engine::has_tree(std::string_view tree_id) const {
  return core_->defs.find(tree_id) != core_->defs.end();
}

SwapResult Engine::replace_tree(const std::string& tree_id, bt::TreeDef def, SwapPolicy policy) {
  detail::Core& core = *core_;
  if (def.id.empty()) def.id = tree_id;
  if (def.id != tree_id)
    throw std::invalid_argument("replace_tree: the new definition is '" + def.id + "', not '" +
                                tree_id + "'");
  auto fresh = std::make_shared<const bt::TreeDef>(std::move(def));

  std::vector<std::uint32_t> targets;
  bool any_running = false;
  for (std::uint32_t i = 0; i < core.instances.size(); ++i) {
    if (!core.instances[i].alive || core.instances[i].tree_id != tree_id) continue;
    targets.push_back(i);
    any_running = any_running || is_running(core, i);
  }
  SwapResult result;
  if (any_running && policy == SwapPolicy::refuse_if_running) {
    result.outcome = SwapResult::Outcome::refused;
    return result;
  }

  // Validate against the definitions it will see (its own id included, for cycles) with a
  // dry run that touches no World, then undo it.
  auto& slot = core.defs[tree_id];
  const std::shared_ptr<const bt::TreeDef> previous = slot;
  slot = fresh;
  {
    const detail::CoreMark before = detail::mark(core);
    detail::Instance probe;
    probe.tree_id = tree_id;
    probe.scope = core.bb.add_scope(Blackboard::kRootScope, true);
    core.instances.push_back(probe);
    detail::Builder dry(core, false);
    if (!targets.empty()) dry.call_stack = callers(core, targets.front());
    try {
      dry.instantiate_tree(fresh, static_cast<std::uint32_t>(core.instances.size() - 1), kNoNode);
    } catch (...) {
      detail::rollback(core, before);
      slot = previous;
      throw;
    }
    detail::rollback(core, before);
  }
  if (previous) core.retired.push_back(previous);

  for (const std::uint32_t i : targets) {
    if (!core.instances[i].alive) continue;  // retired by an earlier rebuild in this loop
    if (is_running(core, i)) {
      if (policy == SwapPolicy::defer_until_idle) {
        core.instances[i].pending = fresh;
        ++result.deferred;
        continue;
      }
      const detail::Instance& inst = core.instances[i];
      core.halt_node(inst.call == kNoNode ? inst.root : inst.call);
      ++result.halted;
    }
    rebuild(core, i, fresh);
    ++result.swapped;
  }
  result.outcome =
      result.deferred > 0 ? SwapResult::Outcome::deferred : SwapResult::Outcome::swapped;
  return result;
}

std::size_t Engine::pending_swaps() const {
  std::size_t n = 0;
  for (const detail::Instance& inst : core_->instances) n += inst.alive && inst.pending ? 1 : 0;
  return n;
}

void Engine::apply_pending_swaps() {
  detail::Core& core = *core_;
  for (std::uint32_t i = 0; i < core.instances.size(); ++i) {
    if (!core.instances[i].alive || !core.instances[i].pending || is_running(core, i)) continue;
    const auto def = core.instances[i].pending;
    rebuild(core, i, def);  // validated when it was queued
  }
}

}  // namespace uabt::runtime
