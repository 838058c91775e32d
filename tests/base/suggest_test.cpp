#include <gtest/gtest.h>

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

}  // namespace
}  // namespace uabt
