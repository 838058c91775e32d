#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "prove/past_time.hpp"

namespace uabt::prove {

// A property's monitor as a finite automaton: every state PastTimeLayout::step reaches from
// its initial state over the four boolean inputs (mode, condition, response, stop), numbered
// in breadth-first order (0 is the initial state). Built by running step itself, so it means
// exactly what the explicit engine's monitor means.
class MonitorTable {
 public:
  // Empty (failed()) when there are more than `max_states` states.
  MonitorTable(const PastTimeLayout& layout, std::size_t max_states);
  bool failed() const { return failed_; }
  std::size_t size() const { return states_.size(); }
  // Inputs as bits: mode 1, condition 2, response 4, stop 8.
  std::uint32_t next(std::uint32_t state, unsigned inputs) const { return next_[state][inputs]; }
  bool now(std::uint32_t state, unsigned inputs) const { return now_[state][inputs]; }
  std::optional<std::uint32_t> index_of(const std::vector<std::uint64_t>& words) const;

 private:
  std::vector<std::vector<std::uint64_t>> states_;
  std::map<std::vector<std::uint64_t>, std::uint32_t> index_;
  std::vector<std::array<std::uint32_t, 16>> next_;
  std::vector<std::array<bool, 16>> now_;
  bool failed_ = false;
};

}  // namespace uabt::prove
