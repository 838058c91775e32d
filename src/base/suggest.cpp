#include "base/suggest.hpp"

#include <algorithm>
#include <span>

namespace uabt {

namespace {

constexpr int kMaxEdits = 2;

// Whether `d` edits between names of these lengths make a likely typo (see NameIndex::closest).
bool close_enough(int d, std::size_t a, std::size_t b) {
  return d <= kMaxEdits && static_cast<std::size_t>(2 * d) < std::min(a, b);
}

// The next row of the optimal-string-alignment table: `row` is the distance of the query's
// prefixes to the current prefix plus `c`; `previous` and `before` are the rows of the prefix
// and of the prefix without its last character `last` (empty when the prefix is empty).
void next_row(const std::string& query, char c, char last, std::span<const int> before,
              std::span<const int> previous, std::span<int> row) {
  row[0] = previous[0] + 1;
  for (std::size_t j = 1; j <= query.size(); ++j) {
    const int cost = query[j - 1] == c ? 0 : 1;
    row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
    if (!before.empty() && j > 1 && query[j - 2] == c && query[j - 1] == last)
      row[j] = std::min(row[j], before[j - 2] + 1);
  }
}

// A depth-first walk of the sorted names as a trie, pruned where every prefix of the query is
// more than kMaxEdits away: a row whose minimum exceeds it only grows (a swap's entry is never
// below the row before it), so nothing below it can come back within reach.
class TrieWalk {
 public:
  // A walk goes at most kMaxEdits + 1 characters deeper than the query before every entry of
  // its row exceeds kMaxEdits, so its rows are allocated once.
  explicit TrieWalk(const std::string& query)
      : query_(query), width_(query.size() + 1), rows_(width_ * (query.size() + kMaxEdits + 3)) {
    for (std::size_t j = 0; j < width_; ++j) rows_[j] = static_cast<int>(j);
  }

  // Names [lo, hi) of `sorted` share their first `depth` characters, whose row is the
  // depth-th; `found` gets (distance, index into sorted) of each name within reach.
  template <typename Entries>
  void walk(const Entries& sorted, std::size_t lo, std::size_t hi, std::size_t depth,
            std::vector<std::pair<int, std::size_t>>& found) {
    const std::span<const int> row = this->row(depth);
    if (sorted[lo].name.size() == depth) {  // the prefix is itself a name (sorted first)
      if (row[width_ - 1] <= kMaxEdits) found.emplace_back(row[width_ - 1], lo);
      ++lo;
    }
    while (lo < hi) {
      const char c = sorted[lo].name[depth];
      // The names after the prefix are sorted by their next character: a binary search finds
      // where this child's ends, so a visit costs its children, not its names.
      const auto after = std::partition_point(
          sorted.begin() + static_cast<long>(lo), sorted.begin() + static_cast<long>(hi),
          [&](const auto& entry) {  // as std::string orders them: bytes unsigned
            return static_cast<unsigned char>(entry.name[depth]) <= static_cast<unsigned char>(c);
          });
      const auto end = static_cast<std::size_t>(after - sorted.begin());
      const std::span<int> next = this->row(depth + 1);
      next_row(query_, c, depth == 0 ? '\0' : sorted[lo].name[depth - 1],
               depth == 0 ? std::span<const int>() : this->row(depth - 1), row, next);
      if (*std::min_element(next.begin(), next.end()) <= kMaxEdits)
        walk(sorted, lo, end, depth + 1, found);
      lo = end;
    }
  }

 private:
  std::span<int> row(std::size_t depth) { return {rows_.data() + width_ * depth, width_}; }

  const std::string& query_;
  std::size_t width_;
  std::vector<int> rows_;  // row k: the distances of the query's prefixes to a k-long prefix
};

}  // namespace

int edit_distance(const std::string& a, const std::string& b) {
  // Optimal string alignment: Levenshtein plus adjacent transpositions, three rows.
  const std::size_t m = b.size();
  std::vector<int> before, previous(m + 1), current(m + 1);
  for (std::size_t j = 0; j <= m; ++j) previous[j] = static_cast<int>(j);
  char last = '\0';
  for (const char c : a) {
    next_row(b, c, last, before, previous, current);
    before = previous;
    std::swap(previous, current);
    last = c;
  }
  return previous[m];
}

NameIndex::NameIndex(const std::vector<std::string>& names) {
  sorted_.reserve(names.size());
  for (std::size_t k = 0; k < names.size(); ++k)
    if (!names[k].empty()) sorted_.push_back({names[k], static_cast<std::uint32_t>(k)});
  std::stable_sort(sorted_.begin(), sorted_.end(),
                   [](const Entry& a, const Entry& b) { return a.name < b.name; });
  // Each name once, at its first place.
  sorted_.erase(std::unique(sorted_.begin(), sorted_.end(),
                            [](const Entry& a, const Entry& b) { return a.name == b.name; }),
                sorted_.end());
}

namespace {

// A name this long is no typo of a name a person types (and its table would be large).
constexpr std::size_t kLongestQuery = 1000;

}  // namespace

std::vector<std::pair<int, std::string>> NameIndex::within_two_edits(
    const std::string& name) const {
  std::vector<std::pair<int, std::size_t>> found;
  if (!sorted_.empty() && name.size() <= kLongestQuery)
    TrieWalk(name).walk(sorted_, 0, sorted_.size(), 0, found);
  std::erase_if(found, [&](const auto& f) { return sorted_[f.second].name == name; });
  std::sort(found.begin(), found.end(), [&](const auto& x, const auto& y) {
    return sorted_[x.second].order < sorted_[y.second].order;
  });
  std::vector<std::pair<int, std::string>> out;
  for (const auto& [d, k] : found) out.emplace_back(d, sorted_[k].name);
  return out;
}

std::vector<std::string> NameIndex::closest(const std::string& name) const {
  std::vector<std::pair<int, std::string>> found = within_two_edits(name);
  std::erase_if(
      found, [&](const auto& f) { return !close_enough(f.first, name.size(), f.second.size()); });
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (auto& [d, n] : found) out.push_back(std::move(n));
  return out;
}

std::string NameIndex::did_you_mean(const std::string& name) const {
  const std::vector<std::string> close = closest(name);
  if (close.empty()) return {};
  std::string out = "did you mean ";
  for (std::size_t k = 0; k < close.size() && k < 3; ++k) {
    if (k > 0) out += k + 1 == std::min<std::size_t>(close.size(), 3) ? " or " : ", ";
    out += "'" + close[k] + "'";
  }
  return out + "?";
}

std::vector<std::string> closest_names(const std::string& name,
                                       const std::vector<std::string>& candidates) {
  return NameIndex(candidates).closest(name);
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  return NameIndex(candidates).did_you_mean(name);
}

}  // namespace uabt
