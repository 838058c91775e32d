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

PastTimeLayout::PastTimeLayout(const Formula& formula, int root)
    : nodes_(formula.nodes()), inputs_(static_cast<std::size_t>(formula.inputs())), root_(root) {
  for (const Node& n : nodes_) {
    offset_.push_back(words_);
    switch (n.op) {
      case Op::yesterday:
      case Op::weak_yesterday:
      case Op::historically:
      case Op::once:
      case Op::since:
      case Op::once_within: words_ += 1; break;
      case Op::since_at_least: words_ += 2; break;
      case Op::exactly_ago: words_ += 2 + n.k + 1; break;
      default: break;
    }
  }
}

std::vector<std::uint64_t> PastTimeLayout::initial() const {
  std::vector<std::uint64_t> s(words_, 0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    if (n.op == Op::historically || n.op == Op::weak_yesterday) s[offset_[i]] = 1;
    if (n.op == Op::once_within) s[offset_[i]] = n.k + 1;  // never seen: beyond the bound
  }
  return s;
}

bool PastTimeLayout::step(const bool* inputs, std::vector<std::uint64_t>& state,
                          std::vector<char>& value) const {
  value.resize(nodes_.size());
  // Locals, not members: a store through `char*` may alias anything, and would make the
  // compiler reload every member after each node.
  const Node* const nodes = nodes_.data();
  const std::size_t* const offset = offset_.data();
  const std::size_t count = nodes_.size();
  std::uint64_t* const words = state.data();
  char* const val = value.data();
  for (std::size_t i = 0; i < count; ++i) {
    const Node& n = nodes[i];
    std::uint64_t* w = words + offset[i];
    bool v = false;
    switch (n.op) {
      case Op::input: v = inputs[n.k]; break;
      case Op::constant: v = n.k != 0; break;
      case Op::negation: v = !val[n.a]; break;
      case Op::conjunction: v = val[n.a] && val[n.b]; break;
      case Op::disjunction: v = val[n.a] || val[n.b]; break;
      case Op::yesterday:
      case Op::weak_yesterday:
        v = w[0] != 0;
        w[0] = val[n.a];
        break;
      case Op::historically: v = (w[0] = w[0] && val[n.a]) != 0; break;
      case Op::once: v = (w[0] = w[0] || val[n.a]) != 0; break;
      case Op::since: v = (w[0] = val[n.b] || (val[n.a] && w[0])) != 0; break;
      case Op::once_within:
        if (val[n.a])
          w[0] = 0;
        else if (w[0] <= n.k)
          ++w[0];
        v = w[0] <= n.k;
        break;
      case Op::since_at_least:
        if (w[0] != 0) {
          if (val[n.a])
            w[1] = std::min(w[1] + 1, n.k);
          else
            w[0] = 0;
        }
        if (w[0] == 0 && val[n.b]) {
          w[0] = 1;
          w[1] = 0;
        }
        v = w[0] != 0 && w[1] >= n.k;
        break;
      case Op::exactly_ago: {
        // w[0]: write index, w[1]: ticks seen before this one (saturates at k), ring after.
        const std::uint64_t size = n.k + 1;
        w[2 + w[0]] = val[n.a];
        w[0] = w[0] + 1 == size ? 0 : w[0] + 1;
        v = w[1] >= n.k && w[2 + w[0]] != 0;
        w[1] = std::min(w[1] + 1, n.k);
        break;
      }
    }
    val[i] = v;
  }
  return val[root_] != 0;
}

}  // namespace uabt::monitor
