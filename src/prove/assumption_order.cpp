#include "prove/assumption_order.hpp"

#include <algorithm>
#include <deque>
#include <unordered_set>

#include "monitor/templates.hpp"

namespace uabt::prove {

namespace {

void append_words(std::string& key, const std::vector<std::uint64_t>& words) {
  key.append(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(std::uint64_t));
}

}  // namespace

bool AssumptionOrder::covers(std::size_t property, const std::uint64_t* loose,
                             const std::uint64_t* tight) {
  const Property& p = m_.properties[property];
  const std::size_t n = p.layout->words();
  if (std::equal(loose, loose + n, tight)) return true;
  if (p.layout->inputs() > kMaxInputs) return false;
  key_.assign(reinterpret_cast<const char*>(&property), sizeof property);
  key_.append(reinterpret_cast<const char*>(loose), n * sizeof(std::uint64_t));
  key_.append(reinterpret_cast<const char*>(tight), n * sizeof(std::uint64_t));
  if (const auto it = cache_.find(key_); it != cache_.end()) return it->second;
  const bool answer = search(p, {loose, loose + n}, {tight, tight + n});
  cache_.emplace(key_, answer);
  return answer;
}

bool AssumptionOrder::search(const Property& p, const std::vector<std::uint64_t>& loose,
                             const std::vector<std::uint64_t>& tight) {
  const std::size_t inputs = p.layout->inputs();
  // A failure that is final ends the run in `tight`: nothing after it need be matched.
  const bool final_failure = monitor::verdict_is_final_once_violated(p.shape);
  std::deque<std::pair<std::vector<std::uint64_t>, std::vector<std::uint64_t>>> pending;
  std::unordered_set<std::string> seen;
  auto visit = [&](std::vector<std::uint64_t> l, std::vector<std::uint64_t> t) {
    if (l == t) return true;  // the same state accepts the same inputs
    std::string key;
    append_words(key, l);
    append_words(key, t);
    if (!seen.insert(std::move(key)).second) return true;
    if (seen.size() > kMaxPairs) return false;
    pending.emplace_back(std::move(l), std::move(t));
    return true;
  };
  if (!visit(loose, tight)) return false;
  bool bits[Property::kMaxAtoms] = {};
  while (!pending.empty()) {
    auto [l, t] = std::move(pending.front());
    pending.pop_front();
    for (std::uint64_t x = 0; x < (std::uint64_t{1} << inputs); ++x) {
      for (std::size_t b = 0; b < inputs; ++b) bits[b] = (x >> b) & 1;
      std::vector<std::uint64_t> l2 = l, t2 = t;
      const bool tight_holds = p.layout->step(bits, t2, scratch_);
      const bool loose_holds = p.layout->step(bits, l2, scratch_);
      // Compared at every tick, as any tick may be the last one (where any failure counts).
      if (tight_holds && !loose_holds) return false;
      if (!tight_holds && final_failure) continue;
      if (!visit(std::move(l2), std::move(t2))) return false;
    }
  }
  return true;
}

}  // namespace uabt::prove
