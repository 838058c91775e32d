#pragma once
// Small missions for --selection optimized: many alternatives over shared variables.
#include <map>
#include <string>

#include "temp_mission.hpp"

namespace uabt::testing {

// K-1 battery bands [10j, 10j+10) in priority order, plus a default: the issue's "16
// alternatives over one battery reading" for K = 16.
inline std::map<std::string, std::string> battery_ladder_files(int k) {
  std::map<std::string, std::string> files;
  files["mission.xml"] = mission_with("    <Adaptable ID=\"power\"/>");
  files["domain.fret"] = "integer battery in [0, " + std::to_string(10 * k) + "]\n";
  std::string reqs;
  for (int j = 0; j < k; ++j) {
    const std::string alt = "band" + std::to_string(j);
    reqs += "B" + std::to_string(j) + ": In power ";
    if (j + 1 < k)
      reqs += "if battery >= " + std::to_string(10 * j) + " & battery < " +
              std::to_string(10 * j + 10) + " ";
    reqs += "Mission shall satisfy selected_alt = " + alt + "\n";
    files["alternatives/power/" + alt + ".xml"] = alternative_tree(alt);
  }
  files["requirements.fret"] = reqs;
  return files;
}

// K terrains of an enum, one alternative each, the last one the default.
inline std::map<std::string, std::string> terrain_enum_files(int k) {
  std::map<std::string, std::string> files;
  files["mission.xml"] = mission_with("    <Adaptable ID=\"drive\"/>");
  std::string literals, reqs;
  for (int j = 0; j < k; ++j) {
    const std::string lit = "t" + std::to_string(j), alt = "on_t" + std::to_string(j);
    literals += (j ? ", " : "") + lit;
    reqs += "T" + std::to_string(j) + ": In drive ";
    if (j + 1 < k) reqs += "if terrain = " + lit + " ";
    reqs += "Mission shall satisfy selected_alt = " + alt + "\n";
    files["alternatives/drive/" + alt + ".xml"] = alternative_tree(alt);
  }
  files["domain.fret"] = "enum terrain in {" + literals + "}\n";
  files["requirements.fret"] = reqs;
  return files;
}

// Two conditions of which the domain says one always holds: the second need not be checked.
inline std::map<std::string, std::string> assumed_cover_files() {
  return {{"mission.xml", mission_with("    <Adaptable ID=\"nav\"/>")},
          {"domain.fret", "boolean OnDust, OnRocks\nassume classified: OnDust | OnRocks\n"},
          {"requirements.fret",
           "Req1: In nav if OnDust Mission shall satisfy selected_alt = on_dust\n"
           "Req2: In nav if OnRocks Mission shall satisfy selected_alt = on_rocks\n"},
          {"alternatives/nav/on_dust.xml", alternative_tree("on_dust")},
          {"alternatives/nav/on_rocks.xml", alternative_tree("on_rocks")}};
}

}  // namespace uabt::testing
