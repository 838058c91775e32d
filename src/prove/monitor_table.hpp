#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "monitor/formula.hpp"

namespace uabt::prove {

// A property's monitor as a finite automaton: every state PastTimeLayout::step reaches from
// its initial state over its boolean inputs (at most kMaxInputs), numbered in breadth-first
// order (0 is the initial state). Built by running step itself, so it means exactly what the
// explicit engine's monitor means.
class MonitorTable {
 public:
  static constexpr std::size_t kMaxInputs = 10;
  // Empty (failed()) when there are more than `max_states` states or kMaxInputs inputs.
  // `triggered` reads a step's node values (Property::triggered): whether the property's
  // mode and condition hold at that step.
  MonitorTable(const monitor::PastTimeLayout& layout, std::size_t max_states,
               const std::function<bool(const std::vector<char>&)>& triggered = nullptr);
  bool failed() const { return failed_; }
  std::size_t size() const { return states_.size(); }
  std::size_t inputs() const { return inputs_; }
  // Inputs as bits: input k is bit k.
  std::uint32_t next(std::uint32_t state, unsigned inputs) const { return next_[state][inputs]; }
  bool now(std::uint32_t state, unsigned inputs) const { return now_[state][inputs] != 0; }
  // Whether the step from `state` on `inputs` triggers the property (false without a
  // `triggered` reader).
  bool triggered(std::uint32_t state, unsigned inputs) const {
    return !triggered_.empty() && triggered_[state][inputs] != 0;
  }
  std::optional<std::uint32_t> index_of(const std::vector<std::uint64_t>& words) const;

 private:
  std::vector<std::vector<std::uint64_t>> states_;
  std::map<std::vector<std::uint64_t>, std::uint32_t> index_;
  std::vector<std::vector<std::uint32_t>> next_;
  std::vector<std::vector<char>> now_, triggered_;
  std::size_t inputs_ = 0;
  bool failed_ = false;
};

}  // namespace uabt::prove
