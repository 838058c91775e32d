#include "prove/monitor_table.hpp"

namespace uabt::prove {

MonitorTable::MonitorTable(const monitor::PastTimeLayout& layout, std::size_t max_states,
                           const std::function<bool(const std::vector<char>&)>& triggered)
    : inputs_(layout.inputs()) {
  if (inputs_ > kMaxInputs) {
    failed_ = true;
    return;
  }
  const unsigned combinations = 1u << inputs_;
  states_.push_back(layout.initial());
  index_[states_.front()] = 0;
  std::vector<char> scratch;
  bool inputs[kMaxInputs] = {};
  for (std::size_t s = 0; s < states_.size(); ++s) {
    std::vector<std::uint32_t> next(combinations);
    std::vector<char> now(combinations), fired(triggered ? combinations : 0);
    for (unsigned in = 0; in < combinations; ++in) {
      for (std::size_t k = 0; k < inputs_; ++k) inputs[k] = ((in >> k) & 1u) != 0;
      std::vector<std::uint64_t> words = states_[s];
      now[in] = layout.step(inputs, words, scratch);
      if (triggered) fired[in] = triggered(scratch);
      auto [it, added] = index_.emplace(words, static_cast<std::uint32_t>(states_.size()));
      if (added) {
        if (states_.size() >= max_states) {
          failed_ = true;
          states_.clear();
          next_.clear();
          now_.clear();
          triggered_.clear();
          return;
        }
        states_.push_back(std::move(words));
      }
      next[in] = it->second;
    }
    next_.push_back(std::move(next));
    now_.push_back(std::move(now));
    if (triggered) triggered_.push_back(std::move(fired));
  }
}

std::optional<std::uint32_t> MonitorTable::index_of(const std::vector<std::uint64_t>& words) const {
  const auto it = index_.find(words);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

}  // namespace uabt::prove
