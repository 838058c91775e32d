#include "prove/past_time.hpp"

#include <algorithm>

namespace uabt::prove {

using monitor::Op;

PastTimeLayout::PastTimeLayout(const monitor::Formula& formula, int root)
    : nodes_(formula.nodes()), inputs_(static_cast<std::size_t>(formula.inputs())), root_(root) {
  for (const monitor::Node& n : nodes_) {
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
    const monitor::Node& n = nodes_[i];
    if (n.op == Op::historically || n.op == Op::weak_yesterday) s[offset_[i]] = 1;
    if (n.op == Op::once_within) s[offset_[i]] = n.k + 1;  // never seen: beyond the bound
  }
  return s;
}

bool PastTimeLayout::step(const bool* inputs, std::vector<std::uint64_t>& state,
                          std::vector<char>& value) const {
  value.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const monitor::Node& n = nodes_[i];
    std::uint64_t* w = state.data() + offset_[i];
    bool v = false;
    switch (n.op) {
      case Op::input: v = inputs[n.k]; break;
      case Op::constant: v = n.k != 0; break;
      case Op::negation: v = !value[n.a]; break;
      case Op::conjunction: v = value[n.a] && value[n.b]; break;
      case Op::disjunction: v = value[n.a] || value[n.b]; break;
      case Op::yesterday:
      case Op::weak_yesterday:
        v = w[0] != 0;
        w[0] = value[n.a];
        break;
      case Op::historically: v = (w[0] = w[0] && value[n.a]) != 0; break;
      case Op::once: v = (w[0] = w[0] || value[n.a]) != 0; break;
      case Op::since: v = (w[0] = value[n.b] || (value[n.a] && w[0])) != 0; break;
      case Op::once_within:
        if (value[n.a])
          w[0] = 0;
        else if (w[0] <= n.k)
          ++w[0];
        v = w[0] <= n.k;
        break;
      case Op::since_at_least:
        if (w[0] != 0) {
          if (value[n.a])
            w[1] = std::min(w[1] + 1, n.k);
          else
            w[0] = 0;
        }
        if (w[0] == 0 && value[n.b]) {
          w[0] = 1;
          w[1] = 0;
        }
        v = w[0] != 0 && w[1] >= n.k;
        break;
      case Op::exactly_ago: {
        // w[0]: write index, w[1]: ticks seen before this one (saturates at k), ring after.
        const std::uint64_t size = n.k + 1;
        w[2 + w[0]] = value[n.a];
        w[0] = w[0] + 1 == size ? 0 : w[0] + 1;
        v = w[1] >= n.k && w[2 + w[0]] != 0;
        w[1] = std::min(w[1] + 1, n.k);
        break;
      }
    }
    value[i] = v;
  }
  return value[root_] != 0;
}

}  // namespace uabt::prove
