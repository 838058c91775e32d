#include "base/suggest.hpp"

#include <algorithm>

namespace uabt {

int edit_distance(const std::string& a, const std::string& b) {
  // Optimal string alignment: Levenshtein plus adjacent transpositions, three rows.
  const std::size_t n = a.size(), m = b.size();
  std::vector<int> before(m + 1), previous(m + 1), current(m + 1);
  for (std::size_t j = 0; j <= m; ++j) previous[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i) {
    current[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[m];
}

std::vector<std::string> closest_names(const std::string& name,
                                       const std::vector<std::string>& candidates) {
  constexpr int kMaxEdits = 2;
  std::vector<std::pair<int, std::size_t>> scored;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const std::string& c = candidates[k];
    if (c == name || c.empty()) continue;
    if (std::find(candidates.begin(), candidates.begin() + static_cast<long>(k), c) !=
        candidates.begin() + static_cast<long>(k))
      continue;  // listed twice
    const int d = edit_distance(name, c);
    const std::size_t shorter = std::min(name.size(), c.size());
    if (d <= kMaxEdits && static_cast<std::size_t>(2 * d) < shorter) scored.emplace_back(d, k);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (const auto& [d, k] : scored) out.push_back(candidates[k]);
  return out;
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  const std::vector<std::string> close = closest_names(name, candidates);
  if (close.empty()) return {};
  std::string out = "did you mean ";
  for (std::size_t k = 0; k < close.size() && k < 3; ++k) {
    if (k > 0) out += k + 1 == std::min<std::size_t>(close.size(), 3) ? " or " : ", ";
    out += "'" + close[k] + "'";
  }
  return out + "?";
}

}  // namespace uabt
