#include "monitor/formula.hpp"

#include <algorithm>

namespace uabt::monitor {

int Formula::add(Node n) {
  const auto key = std::make_tuple(n.op, n.a, n.b, n.k);
  if (const auto it = index_.find(key); it != index_.end()) return it->second;
  nodes_.push_back(n);
  const int id = static_cast<int>(nodes_.size()) - 1;
  index_.emplace(key, id);
  return id;
}

int Formula::input(int slot) {
  inputs_ = std::max(inputs_, slot + 1);
  return add({Op::input, -1, -1, static_cast<std::uint64_t>(slot)});
}

int Formula::constant(bool value) {
  return add({Op::constant, -1, -1, value ? 1u : 0u});
}

int Formula::negation(int a) {
  const Node& n = nodes_[a];
  if (n.op == Op::negation) return n.a;
  if (n.op == Op::constant) return constant(n.k == 0);
  return add({Op::negation, a, -1, 0});
}

int Formula::conjunction(int a, int b) {
  if (a == b) return a;
  if (nodes_[a].op == Op::constant) return nodes_[a].k ? b : a;
  if (nodes_[b].op == Op::constant) return nodes_[b].k ? a : b;
  return add({Op::conjunction, std::min(a, b), std::max(a, b), 0});
}

int Formula::disjunction(int a, int b) {
  if (a == b) return a;
  if (nodes_[a].op == Op::constant) return nodes_[a].k ? a : b;
  if (nodes_[b].op == Op::constant) return nodes_[b].k ? b : a;
  return add({Op::disjunction, std::min(a, b), std::max(a, b), 0});
}

int Formula::yesterday(int a) {
  return add({Op::yesterday, a, -1, 0});
}
int Formula::weak_yesterday(int a) {
  return add({Op::weak_yesterday, a, -1, 0});
}
int Formula::historically(int a) {
  return add({Op::historically, a, -1, 0});
}
int Formula::once(int a) {
  return add({Op::once, a, -1, 0});
}
int Formula::since(int a, int b) {
  return add({Op::since, a, b, 0});
}
int Formula::once_within(int a, std::uint64_t k) {
  return add({Op::once_within, a, -1, k});
}

int Formula::once_below(int a, std::uint64_t k) {
  return k == 0 ? constant(false) : once_within(a, k - 1);
}

int Formula::since_at_least(int a, int b, std::uint64_t k) {
  return add({Op::since_at_least, a, b, k});
}

int Formula::exactly_ago(int a, std::uint64_t k) {
  return add({Op::exactly_ago, a, -1, k});
}

int Formula::first_tick() {
  return negation(yesterday(constant(true)));
}

FormulaMonitor::FormulaMonitor(const Formula& formula, int root)
    : nodes_(formula.nodes()), state_(nodes_.size()), value_(nodes_.size(), 0), root_(root) {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    State& s = state_[i];
    if (n.op == Op::historically || n.op == Op::weak_yesterday) s.bit = true;
    if (n.op == Op::once_within) s.count = n.k + 1;  // "never": beyond the bound
    if (n.op == Op::exactly_ago) s.ring.assign(n.k + 1, false);
  }
}

bool FormulaMonitor::step(const bool* inputs) {
  const std::size_t count = nodes_.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Node& n = nodes_[i];
    State& s = state_[i];
    bool v = false;
    switch (n.op) {
      case Op::input: v = inputs[n.k]; break;
      case Op::constant: v = n.k != 0; break;
      case Op::negation: v = !value_[n.a]; break;
      case Op::conjunction: v = value_[n.a] && value_[n.b]; break;
      case Op::disjunction: v = value_[n.a] || value_[n.b]; break;
      case Op::yesterday:
      case Op::weak_yesterday:
        v = s.bit;
        s.bit = value_[n.a];
        break;
      case Op::historically: v = s.bit = s.bit && value_[n.a]; break;
      case Op::once: v = s.bit = s.bit || value_[n.a]; break;
      case Op::since: v = s.bit = value_[n.b] || (value_[n.a] && s.bit); break;
      case Op::once_within:
        if (value_[n.a])
          s.count = 0;
        else if (s.count <= n.k)
          ++s.count;
        v = s.count <= n.k;
        break;
      case Op::since_at_least:
        if (s.bit) {
          if (value_[n.a])
            s.count = std::min(s.count + 1, n.k);
          else
            s.bit = false;
        }
        if (!s.bit && value_[n.b]) {
          s.bit = true;
          s.count = 0;
        }
        v = s.bit && s.count >= n.k;
        break;
      case Op::exactly_ago: {
        const std::uint64_t size = n.k + 1;
        s.ring[s.count] = value_[n.a];
        s.count = s.count + 1 == size ? 0 : s.count + 1;
        v = tick_ >= n.k && s.ring[s.count];
        break;
      }
    }
    value_[i] = v;
  }
  ++tick_;
  return value_[root_];
}

}  // namespace uabt::monitor
