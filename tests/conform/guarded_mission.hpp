#pragma once
#include <map>
#include <string>

namespace uabt::testing {

// A mission whose guards use every connective Algorithm 1 emits (negation, disjunction,
// implication, relational and enum atoms), two requirements selecting one alternative, a
// second tree in mission.xml and an alternative with a helper tree: the shipped missions'
// guards are single atoms or conjunctions and leave these paths of the checker untried.
inline std::map<std::string, std::string> guarded_mission_files() {
  return {
      {"mission.xml",
       "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
       "  <BehaviorTree ID=\"MainTree\">\n"
       "    <Sequence name=\"main\">\n"
       "      <Inverter><IsDone/></Inverter>\n"
       "      <Adaptable ID=\"navigation\"/>\n"
       "      <SubTree ID=\"report\" _autoremap=\"true\"/>\n"
       "    </Sequence>\n"
       "  </BehaviorTree>\n"
       "  <BehaviorTree ID=\"report\">\n"
       "    <Fallback><ScriptCondition code=\"battery &lt; 5\"/><SendReport channel=\"uhf\"/>"
       "</Fallback>\n"
       "  </BehaviorTree>\n"
       "</root>\n"},
      {"domain.fret",
       "boolean OnDust, OnRocks, OnSand, Dark\n"
       "integer battery in [0, 100]\n"
       "real slope in [-30, 30]\n"
       "enum terrain in {dust, rocks, sand}\n"
       "assume one_terrain: !(OnDust & OnRocks)\n"},
      {"requirements.fret",
       "Low: In navigation if (battery < 20) & !Dark Mission shall satisfy selected_alt = hold\n"
       "Dust: In navigation if OnDust & !(OnRocks | Dark) Mission shall satisfy selected_alt = "
       "on_dust\n"
       "Rocks: In navigation if OnRocks | ((terrain = rocks) & !OnSand) Mission shall satisfy "
       "selected_alt = on_rocks\n"
       "Sand: In navigation if !(OnSand -> (slope <= 10)) Mission shall satisfy selected_alt = "
       "on_sand\n"
       "Safe: In navigation Mission shall satisfy selected_alt = hold\n"},
      {"alternatives/navigation/hold.xml",
       "<root BTCPP_format=\"4\" main_tree_to_execute=\"hold\">\n"
       "  <BehaviorTree ID=\"hold\">\n"
       "    <Sequence><Stop/><SubTree ID=\"hold_wait\" _autoremap=\"true\"/></Sequence>\n"
       "  </BehaviorTree>\n"
       "  <BehaviorTree ID=\"hold_wait\">\n"
       "    <Sleep msec=\"500\"/>\n"
       "  </BehaviorTree>\n"
       "</root>\n"},
      {"alternatives/navigation/on_dust.xml",
       "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"on_dust\">\n"
       "    <MoveForward speed=\"1.0\"/>\n  </BehaviorTree>\n</root>\n"},
      {"alternatives/navigation/on_rocks.xml",
       "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"on_rocks\">\n"
       "    <Sequence><ForceSuccess><IsRockAtLeft/></ForceSuccess>"
       "<MoveBackward speed=\"0.4\"/></Sequence>\n  </BehaviorTree>\n</root>\n"},
      {"alternatives/navigation/on_sand.xml",
       "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"on_sand\">\n"
       "    <MoveForward speed=\"0.5\"/>\n  </BehaviorTree>\n</root>\n"},
  };
}

}  // namespace uabt::testing
