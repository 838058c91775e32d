#include "runtime/smart_selection.hpp"

namespace uabt::runtime::detail {

namespace {

// A guard node that completes within its tick, writes nothing and answers from its reads.
bool pure_guard(Core& core, NodeId id, std::vector<NodeId>& leaves) {
  const RtNode& n = core.nodes[id];
  if (n.conditions != RtNode::kNoConditions) return false;
  switch (n.kind) {
    case Kind::sequence:
    case Kind::fallback:
    case Kind::inverter:
      if (n.child_count == 0) return false;
      for (std::uint32_t i = 0; i < n.child_count; ++i)
        if (!pure_guard(core, core.child(id, i), leaves)) return false;
      return true;
    case Kind::script_condition:
      if (core.programs[core.params[n.params].program].writes()) return false;
      leaves.push_back(id);
      return true;
    case Kind::robot:
      // The world says which leaves are conditions (it names what they read).
      if (condition_reads(core, id).empty()) return false;
      leaves.push_back(id);
      return true;
    default: return false;
  }
}

bool monitored(Core& core, NodeId fallback, SmartSelector& out) {
  const RtNode& f = core.nodes[fallback];
  if (f.child_count == 0) return false;
  for (std::uint32_t b = 0; b < f.child_count; ++b) {
    const NodeId branch = core.child(fallback, b);
    const RtNode& seq = core.nodes[branch];
    if (seq.kind != Kind::reactive_sequence || seq.conditions != RtNode::kNoConditions ||
        seq.child_count == 0)
      return false;
    for (std::uint32_t g = 0; g + 1 < seq.child_count; ++g)
      if (!pure_guard(core, core.child(branch, g), out.guard_leaves)) return false;
  }
  return true;
}

Reads reads_of(Core& core, const SmartSelector& s) {
  Reads out;
  for (NodeId leaf : s.guard_leaves)
    for (auto& read : condition_reads(core, leaf)) out.push_back(std::move(read));
  return out;
}

}  // namespace

Reads condition_reads(Core& core, NodeId node) {
  const RtNode& n = core.nodes[node];
  Reads out;
  if (n.kind == Kind::robot) return core.world->condition_reads(core.leaf_context(node));
  if (n.kind != Kind::script_condition) return out;
  const script::Program& program = core.programs[core.params[n.params].program];
  const ScopeId scope = core.instances[core.info[node].instance].scope;
  for (const std::string& key : program.names()) {
    const auto slot = core.bb.find(scope, key);
    out.emplace_back(key, slot ? core.bb.value(*slot) : ScriptValue{});
  }
  return out;
}

SmartSelector* smart_selector(Core& core, NodeId fallback) {
  if (!core.smart) return nullptr;
  SmartSelection& smart = *core.smart;
  if (smart.index.size() <= fallback) smart.index.resize(core.nodes.size(), 0);
  std::uint32_t& index = smart.index[fallback];
  if (index == 0) {
    SmartSelector s;
    if (monitored(core, fallback, s)) {
      smart.selectors.push_back(std::move(s));
      index = static_cast<std::uint32_t>(smart.selectors.size());
    } else {
      index = SmartSelection::kNot;
    }
  }
  return index == SmartSelection::kNot ? nullptr : &smart.selectors[index - 1];
}

std::uint32_t smart_start(Core& core, NodeId fallback, SmartSelector& s, bool was_running,
                          Reads& reads_now) {
  reads_now = reads_of(core, s);
  const bool unchanged = was_running && s.valid && reads_now == s.snapshot &&
                         core.nodes[core.child(fallback, s.running)].status == NodeStatus::running;
  s.valid = false;
  if (!unchanged) return 0;
  core.smart->skip_guards_of = core.child(fallback, s.running);
  return s.running;
}

void smart_done(Core& core, SmartSelector& s, NodeStatus result, std::uint32_t branch, bool clean,
                Reads&& reads_before) {
  core.smart->skip_guards_of = kNoNode;
  if (result != NodeStatus::running || !clean) return;
  // The guards of later branches saw the state the earlier bodies left; a body that ran and
  // changed a read makes the snapshot unreliable.
  if (reads_of(core, s) != reads_before) return;
  s.snapshot = std::move(reads_before);
  s.running = branch;
  s.valid = true;
}

std::uint32_t smart_sequence_start(Core& core, NodeId sequence) {
  if (!core.smart || core.smart->skip_guards_of != sequence) return 0;
  core.smart->skip_guards_of = kNoNode;
  return core.nodes[sequence].child_count - 1;
}

}  // namespace uabt::runtime::detail
