#include "runtime/engine_state.hpp"

#include <cstring>

#include "runtime/core.hpp"

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

namespace {

template <typename T>
void put(std::string& out, const T& v) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

namespace {

void append_value(std::string& out, const ScriptValue& v) {
  out += static_cast<char>(v.kind);
  switch (v.kind) {
    case ScriptValue::Kind::empty: break;
    case ScriptValue::Kind::boolean: out += static_cast<char>(v.boolean); break;
    case ScriptValue::Kind::integer: put(out, v.integer); break;
    case ScriptValue::Kind::real: put(out, v.real); break;
    case ScriptValue::Kind::string:
      put(out, static_cast<std::uint32_t>(v.text.size()));
      out += v.text;
      break;
  }
}

void append_node(std::string& out, std::uint32_t i, NodeStatus status, std::int32_t a,
                 std::int32_t b, std::int32_t c) {
  // Sparse: between two ticks almost every node is IDLE with zero counters, and a model
  // checker hashes and stores one key per state.
  if (status == NodeStatus::idle && a == 0 && b == 0 && c == 0) return;
  put(out, i);
  out += static_cast<char>(status);
  put(out, a);
  put(out, b);
  put(out, c);
}

}  // namespace

void EngineState::append_key(std::string& out) const {
  for (std::uint32_t i = 0; i < status.size(); ++i) {
    const std::int32_t* c = &counters[3 * static_cast<std::size_t>(i)];
    append_node(out, i, status[i], c[0], c[1], c[2]);
  }
  put(out, UINT32_MAX);
  for (std::uint32_t i = 0; i < child_done.size(); ++i)
    if (child_done[i] != 0) put(out, i);
  put(out, UINT32_MAX);
  for (const ScriptValue& v : values) append_value(out, v);
  out += static_cast<char>(wake_up);
  out += static_cast<char>(last_result);
}

void EngineState::append_key(const Engine& engine, std::string& out) {
  const detail::Core& c = *engine.core_;
  for (std::uint32_t i = 0; i < c.nodes.size(); ++i) {
    const detail::RtNode& n = c.nodes[i];
    append_node(out, i, n.status, n.a, n.b, n.c);
  }
  put(out, UINT32_MAX);
  for (std::uint32_t i = 0; i < c.child_done.size(); ++i)
    if (c.child_done[i] != 0) put(out, i);
  put(out, UINT32_MAX);
  for (SlotId slot = 0; slot < c.bb.slot_count(); ++slot) append_value(out, c.bb.value(slot));
  out += static_cast<char>(c.wake_up);
  out += static_cast<char>(c.last_result);
}

}  // namespace uabt::runtime
