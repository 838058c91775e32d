#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "prove/model.hpp"

namespace uabt::prove {

// Which states of an assumption's monitor allow more of the environment than others. A state
// `loose` covers a state `tight` when every sequence of the monitor's inputs the assumption
// accepts from `tight`, it accepts from `loose` too: then a run in `tight` is no more than a
// run in `loose` with fewer choices left, and the explorer need not follow it when it follows
// the other (`upon CheckK … always CheckK` before CheckK is seen covers it after).
// The monitor is deterministic, so this is a search over pairs of states for a tick whose
// inputs `tight` accepts and `loose` does not. Every combination of inputs counts, possible or
// not, so the answer errs only towards "does not cover". Answers are cached per property.
class AssumptionOrder {
 public:
  explicit AssumptionOrder(const Model& model) : m_(model) {}

  // `loose` and `tight`: the property's words (Property::layout->words() of them).
  bool covers(std::size_t property, const std::uint64_t* loose, const std::uint64_t* tight);

  // Beyond these the answer is "does not cover" (equal states excepted).
  static constexpr std::size_t kMaxInputs = 10;
  static constexpr std::size_t kMaxPairs = 4096;

 private:
  bool search(const Property& p, const std::vector<std::uint64_t>& loose,
              const std::vector<std::uint64_t>& tight);

  const Model& m_;
  std::unordered_map<std::string, bool> cache_;
  std::string key_;
  std::vector<char> scratch_;
};

}  // namespace uabt::prove
