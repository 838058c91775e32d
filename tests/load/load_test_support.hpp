#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "base/diagnostics.hpp"
#include "load/mission.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {

inline load::Mission load_dir(const std::filesystem::path& dir) {
  std::string error;
  auto m = load::load_mission(dir, {}, error);
  EXPECT_TRUE(m.has_value()) << error;
  return m ? std::move(*m) : load::Mission{};
}

inline std::vector<const Finding*> with_check(const load::Mission& m, const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : m.findings)
    if (f.check == check) out.push_back(&f);
  return out;
}

// The navigation mission of msl_curiosity in miniature: one adaptable node, two terrains.
inline std::map<std::string, std::string> navigation_files(const std::string& requirements,
                                                           const std::string& domain = "") {
  std::map<std::string, std::string> files = {
      {"mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                   "      <Stop/>\n    </Sequence>")},
      {"requirements.fret", requirements},
      {"alternatives/navigation/on_dust.xml", alternative_tree("on_dust")},
      {"alternatives/navigation/on_rocks.xml", alternative_tree("on_rocks")},
  };
  if (!domain.empty()) files["domain.fret"] = domain;
  return files;
}

inline const std::string kTwoTerrains =
    "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
    "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n";

}  // namespace uabt::testing
