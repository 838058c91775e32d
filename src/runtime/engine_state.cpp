#include "runtime/engine_state.hpp"

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
    s.counters.insert(s.counters.end(), {n.a, n.b, n.c});
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
    c.nodes[i].a = counters[3 * i];
    c.nodes[i].b = counters[3 * i + 1];
    c.nodes[i].c = counters[3 * i + 2];
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
    if (c.nodes[id].kind == detail::Kind::world_leaf && c.nodes[id].alive) c.bind_world_leaf(id);
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

// The key of a state whose node `i` has status(i) and counters counter(i, 0..2).
template <typename Status, typename Counters, typename Value>
void write_key(std::string& out, std::uint32_t nodes, Status status, Counters counters,
               const std::vector<std::uint8_t>& child_done, std::size_t slots, Value value,
               bool wake_up, NodeStatus last_result) {
  KeyWriter w(out);
  for (std::uint32_t i = 0; i < nodes; ++i) {
    const auto [a, b, c] = counters(i);
    append_node(w, i, status(i), a, b, c);
  }
  w.put(UINT32_MAX);
  for (std::uint32_t i = 0; i < child_done.size(); ++i)
    if (child_done[i] != 0) w.put(i);
  w.put(UINT32_MAX);
  for (std::size_t slot = 0; slot < slots; ++slot) append_value(w, value(slot));
  w.put(static_cast<char>(wake_up));
  w.put(static_cast<char>(last_result));
}

}  // namespace

void EngineState::append_key(std::string& out) const {
  write_key(
      out, static_cast<std::uint32_t>(status.size()), [&](std::uint32_t i) { return status[i]; },
      [&](std::uint32_t i) {
        const std::int32_t* c = &counters[3 * static_cast<std::size_t>(i)];
        return std::array<std::int32_t, 3>{c[0], c[1], c[2]};
      },
      child_done, values.size(),
      [&](std::size_t slot) -> const ScriptValue& { return values[slot]; }, wake_up, last_result);
}

void EngineState::append_key(const Engine& engine, std::string& out) {
  const detail::Core& c = *engine.core_;
  write_key(
      out, static_cast<std::uint32_t>(c.nodes.size()),
      [&](std::uint32_t i) { return c.nodes[i].status; },
      [&](std::uint32_t i) {
        const detail::RtNode& n = c.nodes[i];
        return std::array<std::int32_t, 3>{n.a, n.b, n.c};
      },
      c.child_done, c.bb.slot_count(),
      [&](std::size_t slot) -> const ScriptValue& { return c.bb.value(slot); }, c.wake_up,
      c.last_result);
}

}  // namespace uabt::runtime
