// Missions for the tests that every observable means the same whatever the selection style
// and however many nodes share a label (tests/cli, tests/gate, tests/manager, tests/prove).
#pragma once
#include <map>
#include <regex>
#include <string>

#include "temp_mission.hpp"

namespace uabt::testing {

// A decision structure is cheaper than Fig. 4 here (an enum and thresholds), so `optimized`
// compiles `traverse` into IfThenElse (WhileDoElse when reactive) with named leaves.
inline std::map<std::string, std::string> lunar_traverse() {
  auto alternative = [](const std::string& id) {
    return alternative_tree(id, "<Sequence name=\"" + id + "\"><Move_" + id + "/></Sequence>");
  };
  return {
      {"mission.xml",
       mission_with("<KeepRunningUntilFailure><Adaptable ID=\"traverse\" policy=\"first\"/>"
                    "</KeepRunningUntilFailure>")},
      {"domain.fret",
       "enum illumination in {sun, shadow, dusk, night}\n"
       "integer slope in [0, 30]\n"},
      {"requirements.fret",
       "Night: In traverse if illumination = night Mission shall satisfy selected_alt = "
       "wait_for_light\n"
       "Dark: In traverse if illumination = shadow & slope >= 15 Mission shall satisfy "
       "selected_alt = wait_for_light\n"
       "Steep: In traverse if slope >= 20 Mission shall satisfy selected_alt = crawl\n"
       "Dusk: In traverse if illumination = dusk & slope >= 10 Mission shall satisfy "
       "selected_alt = crawl\n"
       "Go: In traverse Mission shall satisfy selected_alt = drive_fast\n"
       "WaitInShadow: In traverse upon illumination = shadow & slope >= 15 the rover shall "
       "within 3 ticks satisfy traverse.selected = wait_for_light\n"
       "CrawlSelected: the rover shall always satisfy Move_crawl.running -> traverse.selected = "
       "crawl\n"},
      {"alternatives/traverse/wait_for_light.xml", alternative("wait_for_light")},
      {"alternatives/traverse/crawl.xml", alternative("crawl")},
      {"alternatives/traverse/drive_fast.xml", alternative("drive_fast")},
      {"world.json",
       R"({"actions": {"Move_wait_for_light": {"ticks": 1, "results": ["success"]},
                       "Move_crawl": {"ticks": [1, 2], "results": ["success"]},
                       "Move_drive_fast": {"ticks": 1, "results": ["success"]}}})"},
      {"scenarios/shadow.json",
       R"({"max_ticks": 12, "initial": {"illumination": "sun", "slope": 22},
           "actions": {"Move_crawl": {"ticks": 3}},
           "events": [{"at": 2, "set": {"illumination": "shadow", "slope": 16}},
                      {"at": 6, "set": {"illumination": "sun", "slope": 0}}]})"},
  };
}

// Every <Adaptable> of mission.xml declared `reactive`, or declaring no selection style.
inline std::string with_reactivity(const std::string& xml, bool reactive) {
  const std::string plain =
      std::regex_replace(xml, std::regex(R"((<Adaptable\b[^>]*?) selection="[a-z]*")"), "$1");
  return reactive ? std::regex_replace(plain, std::regex("<Adaptable\\b"),
                                       "<Adaptable selection=\"reactive\"")
                  : plain;
}

// sample_drilling with its drills unnamed: both alternatives' <Drill> share the label `Drill`
// (the shipped files name them "Drill" only to make it unique).
inline std::map<std::string, std::string> unnamed_drills() {
  auto files = mission_files("sample_drilling");
  for (const char* alt :
       {"alternatives/drilling/percussive.xml", "alternatives/drilling/rotary.xml"}) {
    std::string& xml = files[alt];
    const std::string named = " name=\"Drill\"";
    if (const auto at = xml.find(named); at != std::string::npos) xml.erase(at, named.size());
  }
  return files;
}

}  // namespace uabt::testing
