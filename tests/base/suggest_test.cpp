#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "base/suggest.hpp"

namespace uabt {
namespace {

TEST(Suggest, EditDistanceCountsASwapAsOneEdit) {
  EXPECT_EQ(edit_distance("OnRokcs", "OnRocks"), 1);
  EXPECT_EQ(edit_distance("OnRocks", "OnRocks"), 0);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(edit_distance("OnDust", "OnRocks"), 5);
}

TEST(Suggest, ClosestNamesWithinTwoEditsClosestFirst) {
  const std::vector<std::string> names = {"OnDust", "OnRocks", "OnRock", "OnSand"};
  EXPECT_EQ(closest_names("OnRokcs", names), (std::vector<std::string>{"OnRocks", "OnRock"}));
  EXPECT_TRUE(closest_names("Battery", names).empty());
  EXPECT_TRUE(closest_names("OnDust", {"OnDust"}).empty()) << "a name is not its own typo";
}

TEST(Suggest, ShortNamesDoNotAllLookAlike) {
  EXPECT_TRUE(closest_names("x", {"y", "z"}).empty());
  EXPECT_TRUE(closest_names("ab", {"cd"}).empty());
  EXPECT_EQ(closest_names("abc", {"abd"}), std::vector<std::string>{"abd"});
}

TEST(Suggest, DidYouMean) {
  EXPECT_EQ(did_you_mean("OnRokcs", {"OnDust", "OnRocks"}), "did you mean 'OnRocks'?");
  EXPECT_EQ(did_you_mean("on_dsut", {"on_dust", "on_dusk"}),
            "did you mean 'on_dust' or 'on_dusk'?");
  EXPECT_EQ(did_you_mean("zzz", {"OnDust"}), "");
}

// The optimal string alignment distance written out in full, independent of the one the index
// and edit_distance share.
int reference_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<int>> d(a.size() + 1, std::vector<int>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = static_cast<int>(i);
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// Every query answered from the index is what comparing the query with every name gives: the
// names within two edits and closer than half the shorter length, closest first, then in the
// order given. Names over a small alphabet, so that many are near one another, with shared
// prefixes, swaps, names that are prefixes of others, and bytes of accented letters.
TEST(Suggest, TheIndexAnswersWhatComparingEveryNameAnswers) {
  std::mt19937 random(20261203);
  auto word = [&](std::size_t max_length) {
    std::string w(std::uniform_int_distribution<std::size_t>(0, max_length)(random), 'a');
    // Bytes above 127 too (UTF-8's), which std::string orders as unsigned.
    for (char& c : w) c = "abcd_\xC3\xA9"[std::uniform_int_distribution<int>(0, 6)(random)];
    return w;
  };
  std::size_t suggested = 0;
  for (int round = 0; round < 40; ++round) {
    std::vector<std::string> names;
    for (int k = 0; k < 300; ++k) names.push_back(word(7));
    const NameIndex index(names);
    for (int q = 0; q < 100; ++q) {
      const std::string query = q % 2 == 0 ? word(8) : names[static_cast<std::size_t>(q)] + "x";
      std::vector<std::pair<int, std::size_t>> scored;
      for (std::size_t k = 0; k < names.size(); ++k) {
        const std::string& c = names[k];
        if (c.empty() || c == query ||
            std::find(names.begin(), names.begin() + static_cast<long>(k), c) !=
                names.begin() + static_cast<long>(k))
          continue;
        const int d = reference_distance(query, c);
        if (d <= 2 && static_cast<std::size_t>(2 * d) < std::min(query.size(), c.size()))
          scored.emplace_back(d, k);
      }
      std::stable_sort(scored.begin(), scored.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
      std::vector<std::string> expected;
      for (const auto& [d, k] : scored) expected.push_back(names[k]);
      ASSERT_EQ(index.closest(query), expected) << "query '" << query << "'";
      ASSERT_EQ(edit_distance(query, names[0]), reference_distance(query, names[0]));
      suggested += expected.size();
    }
  }
  EXPECT_GT(suggested, 1000u) << "the names are near enough to one another to test the index";
}

TEST(Suggest, ALongNameIsNoTypo) {
  const std::string long_name(1001, 'a');
  EXPECT_TRUE(closest_names(long_name, {long_name + "b"}).empty());
  EXPECT_EQ(closest_names(long_name.substr(1), {long_name}), std::vector<std::string>{long_name});
}

}  // namespace
}  // namespace uabt
