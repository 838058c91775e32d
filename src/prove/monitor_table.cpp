#include "prove/monitor_table.hpp"

namespace uabt::prove {

MonitorTable::MonitorTable(const PastTimeLayout& layout, std::size_t max_states) {
  states_.push_back(layout.initial());
  index_[states_.front()] = 0;
  std::vector<char> scratch;
  for (std::size_t s = 0; s < states_.size(); ++s) {
    std::array<std::uint32_t, 16> next{};
    std::array<bool, 16> now{};
    for (unsigned in = 0; in < 16; ++in) {
      const bool inputs[4] = {(in & 1) != 0, (in & 2) != 0, (in & 4) != 0, (in & 8) != 0};
      std::vector<std::uint64_t> words = states_[s];
      now[in] = layout.step(inputs, words, scratch);
      auto [it, added] = index_.emplace(words, static_cast<std::uint32_t>(states_.size()));
      if (added) {
        if (states_.size() >= max_states) {
          failed_ = true;
          states_.clear();
          next_.clear();
          now_.clear();
          return;
        }
        states_.push_back(std::move(words));
      }
      next[in] = it->second;
    }
    next_.push_back(next);
    now_.push_back(now);
  }
}

std::optional<std::uint32_t> MonitorTable::index_of(const std::vector<std::uint64_t>& words) const {
  const auto it = index_.find(words);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

}  // namespace uabt::prove
