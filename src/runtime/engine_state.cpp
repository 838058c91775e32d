#include "runtime/engine_state.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "runtime/core.hpp"
#include "runtime/smart_selection.hpp"

namespace uabt::runtime {

EngineState EngineState::save(const Engine& engine) {
  const detail::Core& c = *engine.core_;
  EngineState s;
  s.status.reserve(c.nodes.size());
  s.counters.reserve(3 * c.nodes.size());
  for (const detail::RtNode& n : c.nodes) {
    s.status.push_back(n.status);
    s.counters.insert(s.counters.end(), n.memory.begin(), n.memory.end());
  }
  s.child_done = c.child_done;
  s.values.reserve(c.bb.slot_count());
  for (SlotId slot = 0; slot < c.bb.slot_count(); ++slot) s.values.push_back(c.bb.value(slot));
  s.wake_up = c.wake_up;
  s.wake_up_node = c.wake_up_node;
  s.tick = c.tick;
  s.last_result = c.last_result;
  return s;
}

void EngineState::restore(Engine& engine) const {
  detail::Core& c = *engine.core_;
  for (std::size_t i = 0; i < c.nodes.size() && i < status.size(); ++i) {
    c.nodes[i].status = status[i];
    std::copy_n(counters.begin() + static_cast<std::ptrdiff_t>(3 * i), 3,
                c.nodes[i].memory.begin());
  }
  c.child_done = child_done;
  // Slots created after the save (a script's first write) go back to empty.
  for (SlotId slot = 0; slot < c.bb.slot_count(); ++slot)
    c.bb.value(slot) = slot < values.size() ? values[slot] : ScriptValue{};
  c.wake_up = wake_up;
  c.wake_up_node = wake_up_node;
  c.tick = tick;
  c.last_result = last_result;
}

void Engine::reset(World& world, const EngineState& built) {
  detail::Core& c = *core_;
  built.restore(*this);
  c.errors.clear();
  c.stats = {};
  if (c.options.smart_selection) c.smart = std::make_shared<detail::SmartSelection>();
  c.world = &world;
  for (NodeId id = 0; id < c.nodes.size(); ++id)
    if (c.nodes[id].kind == detail::Kind::robot && c.nodes[id].alive) c.bind_world_leaf(id);
}

namespace {

// Gathers a key in a local buffer and appends it to the string in large pieces (a model
// checker takes one key per state, and per choice point within a tick, so appending it byte by
// byte would dominate).
class KeyWriter {
 public:
  explicit KeyWriter(std::string& out) : out_(out) {}
  ~KeyWriter() { flush(); }
  template <typename T>
  void put(const T& v) {
    if (n_ + sizeof(T) > sizeof buffer_) flush();
    std::memcpy(buffer_ + n_, &v, sizeof(T));
    n_ += sizeof(T);
  }
  void bytes(const char* data, std::size_t n) {
    flush();
    out_.append(data, n);
  }

 private:
  void flush() {
    out_.append(buffer_, n_);
    n_ = 0;
  }
  std::string& out_;
  char buffer_[4096];
  std::size_t n_ = 0;
};

void append_value(KeyWriter& out, const ScriptValue& v) {
  out.put(static_cast<char>(v.kind));
  switch (v.kind) {
    case ScriptValue::Kind::empty: break;
    case ScriptValue::Kind::boolean: out.put(static_cast<char>(v.boolean)); break;
    case ScriptValue::Kind::integer:
      out.put(v.integer);
      out.put(static_cast<char>(v.bool_entry));
      break;
    case ScriptValue::Kind::real: out.put(v.real); break;
    case ScriptValue::Kind::string:
      out.put(static_cast<std::uint32_t>(v.text.size()));
      out.bytes(v.text.data(), v.text.size());
      break;
  }
}

inline void append_node(KeyWriter& out, std::uint32_t i, NodeStatus status, std::int32_t a,
                        std::int32_t b, std::int32_t c) {
  // Sparse: between two ticks almost every node is IDLE with zero counters, and a model
  // checker hashes and stores one key per state.
  if (status == NodeStatus::idle && (a | b | c) == 0) return;
  out.put(i);
  out.put(static_cast<char>(status));
  out.put(a);
  out.put(b);
  out.put(c);
}

// The key of a state whose node `i` has status(i) and counters counter(i, 0..2); `only`, when
// given, lists in ascending order every node that may not be IDLE with zero counters.
template <typename Status, typename Counters, typename Value>
void write_key(std::string& out, std::uint32_t nodes, const std::vector<NodeId>* only,
               Status status, Counters counters, const std::vector<std::uint8_t>& child_done,
               std::size_t slots, Value value, bool wake_up, NodeStatus last_result) {
  KeyWriter w(out);
  auto node = [&](std::uint32_t i) {
    const auto [a, b, c] = counters(i);
    append_node(w, i, status(i), a, b, c);
  };
  if (only != nullptr) {
    for (NodeId i : *only) node(i);
  } else {
    for (std::uint32_t i = 0; i < nodes; ++i) node(i);
  }
  w.put(UINT32_MAX);
  // A flag per child of every node, set only under a Parallel: eight at a time.
  const std::size_t flags = child_done.size();
  std::size_t i = 0;
  for (; i < flags; i += 8) {
    std::uint64_t eight = 0;
    std::memcpy(&eight, child_done.data() + i, std::min<std::size_t>(8, flags - i));
    if (eight == 0) continue;
    for (std::size_t k = i; k < i + 8 && k < flags; ++k)
      if (child_done[k] != 0) w.put(static_cast<std::uint32_t>(k));
  }
  w.put(UINT32_MAX);
  for (std::size_t slot = 0; slot < slots; ++slot) append_value(w, value(slot));
  w.put(static_cast<char>(wake_up));
  w.put(static_cast<char>(last_result));
}

void engine_key(const detail::Core& c, const std::vector<NodeId>* only, std::string& out) {
  write_key(
      out, static_cast<std::uint32_t>(c.nodes.size()), only,
      [&](std::uint32_t i) { return c.nodes[i].status; },
      [&](std::uint32_t i) {
        const detail::RtNode& n = c.nodes[i];
        return n.memory;
      },
      c.child_done, c.bb.slot_count(),
      [&](std::size_t slot) -> const ScriptValue& { return c.bb.value(slot); }, c.wake_up,
      c.last_result);
}

bool busy(const detail::RtNode& n) {
  return n.status != NodeStatus::idle || n.memory != decltype(n.memory){};
}

}  // namespace

void EngineState::append_key(std::string& out) const {
  write_key(
      out, static_cast<std::uint32_t>(status.size()), nullptr,
      [&](std::uint32_t i) { return status[i]; },
      [&](std::uint32_t i) {
        const std::int32_t* c = &counters[3 * static_cast<std::size_t>(i)];
        return std::array<std::int32_t, 3>{c[0], c[1], c[2]};
      },
      child_done, values.size(),
      [&](std::size_t slot) -> const ScriptValue& { return values[slot]; }, wake_up, last_result);
}

void EngineState::append_key(const Engine& engine, std::string& out) {
  engine_key(*engine.core_, nullptr, out);
}

}  // namespace uabt::runtime

namespace uabt::runtime {

TickTrail::TickTrail(Engine& engine) : engine_(engine), trail_(std::make_unique<detail::Trail>()) {
  detail::Core& c = *engine_.core_;
  trail_->stamp.assign(c.nodes.size(), 0);
  c.trail = trail_.get();
}

TickTrail::~TickTrail() {
  engine_.core_->trail = nullptr;
}

void TickTrail::begin() {
  const detail::Core& c = *engine_.core_;
  trail_->stamp.resize(c.nodes.size(), 0);
  // Only a Parallel sets the flags of its children (none: they stay as they are).
  parallel_ = std::any_of(c.nodes.begin(), c.nodes.end(), [](const detail::RtNode& n) {
    return n.kind == detail::Kind::parallel || n.kind == detail::Kind::parallel_all;
  });
  trail_->entries.clear();
  trail_->path.clear();
  ++trail_->epoch;
  count_ = 0;
  busy_.clear();
  for (NodeId id = 0; id < c.nodes.size(); ++id)
    if (busy(c.nodes[id])) busy_.push_back(id);
}

void TickTrail::busy_now(std::vector<NodeId>& out) const {
  const detail::Core& c = *engine_.core_;
  const std::vector<NodeId>& before = count_ > 0 ? stack_[count_ - 1].busy : busy_;
  const std::size_t since = count_ > 0 ? stack_[count_ - 1].entries : 0;
  out.clear();
  for (NodeId id : before)
    if (busy(c.nodes[id])) out.push_back(id);
  for (std::size_t k = since; k < trail_->entries.size(); ++k)
    if (busy(c.nodes[trail_->entries[k].id])) out.push_back(trail_->entries[k].id);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void TickTrail::append_key(std::string& out) const {
  busy_now(scratch_);
  engine_key(*engine_.core_, &scratch_, out);
}

bool TickTrail::resumable() const {
  using detail::Kind;
  const detail::Core& c = *engine_.core_;
  const std::vector<NodeId>& path = trail_->path;
  if (c.in_wake_up_loop || path.empty() || path.front() != c.root) return false;
  const detail::RtNode& leaf = c.nodes[path.back()];
  if (leaf.kind != Kind::robot || leaf.conditions != detail::RtNode::kNoConditions) return false;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const detail::RtNode& n = c.nodes[path[k]];
    if (n.status != NodeStatus::running) return false;
    if (n.conditions != detail::RtNode::kNoConditions &&
        c.conditions[n.conditions].pre[detail::ConditionScripts::while_true] >= 0)
      return false;
    std::uint32_t child = 0;
    switch (n.kind) {
      case Kind::sequence:
      case Kind::fallback:
        if (n.current_child_idx() < 0) return false;
        child = static_cast<std::uint32_t>(n.current_child_idx());
        break;
      case Kind::inverter:
      case Kind::force_success:
      case Kind::force_failure:
      case Kind::keep_running_until_failure:
      case Kind::run_once:
      case Kind::subtree: break;
      default: return false;
    }
    if (child >= n.child_count || c.child(path[k], child) != path[k + 1]) return false;
  }
  return true;
}

void TickTrail::push() {
  detail::Core& c = *engine_.core_;
  detail::Trail& t = *trail_;
  if (count_ == stack_.size()) stack_.emplace_back();
  // Every node that is not IDLE with zero counters now: those that were at the last
  // checkpoint (or at begin()) and those changed since, that still are.
  busy_now(scratch_);
  Checkpoint& cp = stack_[count_++];
  cp.busy.swap(scratch_);
  cp.entries = t.entries.size();
  ++t.epoch;
  // The nodes of the open frames change without being entered again (a Fallback moves on to
  // its next child): they are logged now.
  for (NodeId id : t.path) t.log(c.nodes, id);
  cp.path = t.path;
  if (parallel_) cp.child_done = c.child_done;
  cp.values.resize(c.bb.slot_count());
  for (SlotId slot = 0; slot < c.bb.slot_count(); ++slot) cp.values[slot] = c.bb.value(slot);
  cp.wake_up = c.wake_up;
  cp.wake_up_node = c.wake_up_node;
  cp.tick = c.tick;
  cp.last_result = c.last_result;
}

void TickTrail::restore() {
  detail::Core& c = *engine_.core_;
  detail::Trail& t = *trail_;
  const Checkpoint& cp = stack_[count_ - 1];
  while (t.entries.size() > cp.entries) {
    const detail::Trail::Entry& e = t.entries.back();
    detail::RtNode& n = c.nodes[e.id];
    n.status = e.status;
    n.memory = e.memory;
    t.entries.pop_back();
  }
  ++t.epoch;
  t.path = cp.path;
  if (parallel_) c.child_done = cp.child_done;
  for (SlotId slot = 0; slot < c.bb.slot_count(); ++slot)
    c.bb.value(slot) = slot < cp.values.size() ? cp.values[slot] : ScriptValue{};
  c.wake_up = cp.wake_up;
  c.wake_up_node = cp.wake_up_node;
  c.tick = cp.tick;
  c.last_result = cp.last_result;
}

void TickTrail::pop() {
  --count_;
}

}  // namespace uabt::runtime
