#pragma once
#include <cstdint>
#include <vector>

#include "monitor/formula.hpp"

namespace uabt::prove {

// The state of a monitor::Formula as plain words, so that a model checker can hash it, copy it
// with the rest of a state and encode it: one word per Y/Z/H/O/S bit or O[<=k] age, two for
// S[>=k] (live, age) and 2 + k + 1 for O[=k] (write index, ticks seen up to k, the ring).
// Same meaning as monitor::FormulaMonitor (tested against it).
class PastTimeLayout {
 public:
  explicit PastTimeLayout(const monitor::Formula& formula, int root);
  std::vector<std::uint64_t> initial() const;
  // One tick: updates `state`, returns the formula's value. `values` is scratch.
  bool step(const bool* inputs, std::vector<std::uint64_t>& state, std::vector<char>& values) const;
  std::size_t words() const { return words_; }
  std::size_t inputs() const { return inputs_; }  // the boolean inputs step reads

 private:
  std::vector<monitor::Node> nodes_;
  std::vector<std::size_t> offset_;
  std::size_t words_ = 0;
  std::size_t inputs_ = 0;
  int root_ = 0;
};

}  // namespace uabt::prove
