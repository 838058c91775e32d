#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace uabt::verify::detail {

// A set of states as one bit per state of an enumerated space.
class Bits {
 public:
  Bits() = default;
  Bits(std::uint64_t size, bool value)
      : size_(size), words_((size + 63) / 64, value ? ~std::uint64_t{0} : 0) {
    clear_tail();
  }
  std::uint64_t size() const { return size_; }
  void set(std::uint64_t i) { words_[i / 64] |= std::uint64_t{1} << (i % 64); }
  bool test(std::uint64_t i) const { return (words_[i / 64] >> (i % 64)) & 1; }
  std::uint64_t count() const {
    std::uint64_t n = 0;
    for (auto w : words_) n += static_cast<std::uint64_t>(std::popcount(w));
    return n;
  }
  // Calls f(i) for each member i, in increasing order: a pass over the words, then over the
  // members only.
  template <typename F>
  void for_each(F&& f) const {
    for (std::size_t w = 0; w < words_.size(); ++w)
      for (std::uint64_t x = words_[w]; x != 0; x &= x - 1)
        f(w * 64 + static_cast<std::uint64_t>(std::countr_zero(x)));
  }
  bool any() const {
    for (auto w : words_)
      if (w != 0) return true;
    return false;
  }
  // Whether the two sets share a member: `(*this & o).any()` without making the intersection.
  bool intersects(const Bits& o) const {
    for (std::size_t i = 0; i < words_.size(); ++i)
      if ((words_[i] & o.words_[i]) != 0) return true;
    return false;
  }
  bool operator==(const Bits& o) const { return size_ == o.size_ && words_ == o.words_; }
  Bits operator&(const Bits& o) const {
    return zip(o, [](auto a, auto b) { return a & b; });
  }
  Bits operator|(const Bits& o) const {
    return zip(o, [](auto a, auto b) { return a | b; });
  }
  Bits operator~() const {
    Bits r = *this;
    for (auto& w : r.words_) w = ~w;
    r.clear_tail();
    return r;
  }

 private:
  std::uint64_t size_ = 0;
  std::vector<std::uint64_t> words_;

  void clear_tail() {
    if (size_ % 64 != 0 && !words_.empty()) words_.back() &= (std::uint64_t{1} << (size_ % 64)) - 1;
  }
  template <typename F>
  Bits zip(const Bits& o, F f) const {
    Bits r = *this;
    for (std::size_t i = 0; i < r.words_.size(); ++i) r.words_[i] = f(r.words_[i], o.words_[i]);
    return r;
  }
};

// A condition over the space in three-valued logic: where it surely holds, where it may hold
// (an atom that cannot be measured exactly is "may" everywhere), and where it has no value (a
// division by zero that reaches it). sure ⊆ maybe; both are empty where `none` is set.
struct Truth {
  Bits sure, maybe, none;

  static Truth exactly(const Bits& holds, const Bits& none) {
    const Bits value = holds & ~none;
    return {value, value, none};
  }
  bool exact() const { return sure == maybe; }
};

inline Truth negation(const Truth& a) {
  return {~a.maybe & ~a.none, ~a.sure & ~a.none, a.none};
}

// A conjunction (or disjunction): a definite false (true) operand decides it even where
// another operand has no value, as in `battery != 0 & 10 / battery > 2`.
inline Truth junction(bool is_and, const std::vector<Truth>& args, std::uint64_t size) {
  Bits decided(size, false), any_none(size, false), sure(size, true), maybe(size, true);
  for (const auto& a : args) {
    const Truth t = is_and ? a : negation(a);
    decided = decided | (~t.maybe & ~t.none);
    any_none = any_none | t.none;
    sure = sure & t.sure;
    maybe = maybe & (t.maybe | t.none);
  }
  const Bits none = any_none & ~decided;
  Truth out{sure & ~none, maybe & ~none & ~decided, none};
  return is_and ? out : negation(out);
}

}  // namespace uabt::verify::detail
