#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "load/mission.hpp"

namespace uabt::testing {

// Loads a mission with the given uplink packages merged (the merge `gate --uplink`, `diff
// --uplink` and `run` share); a directory that is not a mission fails the test.
inline load::Mission load_merged(const std::filesystem::path& dir,
                                 std::vector<std::filesystem::path> uplinks = {}) {
  std::string error;
  load::LoadOptions options;
  options.uplinks = std::move(uplinks);
  auto m = load::load_mission(dir, options, error);
  EXPECT_TRUE(m.has_value()) << error;
  return m ? std::move(*m) : load::Mission{};
}

}  // namespace uabt::testing
