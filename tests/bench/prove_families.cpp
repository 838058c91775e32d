#include "prove_families.hpp"
#include "family_files.hpp"

#include <fstream>
#include <stdexcept>
#include <string>

namespace uabt::bench {

namespace {

std::string mission_xml(const std::string& body) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
         "  <BehaviorTree ID=\"MainTree\">\n    <KeepRunningUntilFailure>\n" +
         body + "    </KeepRunningUntilFailure>\n  </BehaviorTree>\n</root>\n";
}

// The robot's registered nodes. Without it the compiler tells conditions from actions by their
// names (Is…, Has…), and would take Ok_1 or AtSite for an action.
std::string nodes_xml(const std::string& models) {
  return "<root BTCPP_format=\"4\">\n  <TreeNodesModel>\n" + models +
         "  </TreeNodesModel>\n</root>\n";
}

std::string indent(int depth) {
  return std::string(static_cast<std::size_t>(2 * depth), ' ');
}

// The heap-shaped tree: node k has children 2k+1 and 2k+2 when they exist; leaves are
// numbered left to right.
struct BinaryTreeWriter {
  int nodes;
  int counters;
  int leaf = 0;
  std::string xml;

  void node(int k, int depth) {
    if (2 * k + 2 < nodes) {
      xml += indent(depth) + "<Fallback>\n";
      node(2 * k + 1, depth + 1);
      node(2 * k + 2, depth + 1);
      xml += indent(depth) + "</Fallback>\n";
      return;
    }
    const int i = leaf++;
    if (i % 2 == 0) {
      static constexpr int kThreshold[] = {8, 6, 4, 7, 5};
      const int check = i / 2;
      xml += indent(depth) + "<ScriptCondition code=\"vv_" + std::to_string(check % counters) +
             " &gt;= " + std::to_string(kThreshold[check % 5]) + "\"/>\n";
    } else {
      const int action = i / 2;
      const bool inc = (action / counters) % 2 == 0;
      xml +=
          indent(depth) + "<" + (inc ? "Inc" : "Dec") + std::to_string(action % counters) + "/>\n";
    }
  }
};

}  // namespace

FamilyMission generate_binary_tree(const std::filesystem::path& dir, int fallback_nodes,
                                   int counters) {
  if (fallback_nodes < 3 || fallback_nodes % 2 == 0)
    throw std::invalid_argument("a complete binary tree has an odd number of nodes, >= 3");
  if (counters < 1) throw std::invalid_argument("the binary tree needs at least one counter");
  BinaryTreeWriter tree{fallback_nodes, counters, 0, {}};
  tree.node(0, 3);
  write_file(dir / "mission.xml", mission_xml(tree.xml));
  std::string domain = "# Counters the checks read and the actions change.\n";
  std::string initial, actions;
  for (int j = 0; j < counters; ++j) {
    const std::string v = "vv_" + std::to_string(j);
    domain += "integer " + v + " in [0, 8]\n";
    initial += (j ? " & " : "") + v + " = 0";
    actions += std::string(j ? ",\n" : "") + "    \"Inc" + std::to_string(j) +
               "\": {\"ticks\": 1, \"results\": [\"success\", \"failure\"], \"on_success\": \"" +
               v + " = " + v + " < 8 ? " + v + " + 1 : " + v + "\"},\n    \"Dec" +
               std::to_string(j) +
               "\": {\"ticks\": 1, \"results\": [\"success\", \"failure\"], \"on_success\": \"" +
               v + " = " + v + " > 0 ? " + v + " - 1 : " + v + "\"}";
  }
  write_file(dir / "domain.fret", domain);
  write_file(dir / "world.json",
             "{\n  \"initial\": \"" + initial + "\",\n  \"actions\": {\n" + actions + "\n  }\n}\n");
  write_file(dir / "requirements.fret",
             "Bounded: Mission shall always satisfy vv_0 <= 8\n"
             "BelowMax: Mission shall always satisfy vv_0 < 8\n");
  FamilyMission m;
  m.dir = dir;
  m.tree_nodes = fallback_nodes + 1;
  m.verdicts = {{"Bounded", "proved"}, {"BelowMax", "violated"}};
  m.violation_ticks = {{"BelowMax", 8}};
  return m;
}

FamilyMission generate_checklist(const std::filesystem::path& dir, int checks) {
  if (checks < 1) throw std::invalid_argument("a checklist has at least one check");
  std::string body = "      <ForceSuccess>\n        <Sequence>\n";
  std::string domain = "# Whether each item of the checklist is in order.\n";
  std::string initial, actions, all_ok;
  for (int i = 0; i < checks; ++i) {
    const std::string ok = "IsOk_" + std::to_string(i), repair = "Repair" + std::to_string(i);
    body += "          <Fallback>\n            <" + ok + "/>\n            <" + repair +
            "/>\n          </Fallback>\n";
    domain += "boolean " + ok + "\n";
    initial += (i ? " & !" : "!") + ok;
    all_ok += (i ? " & " : "") + ok;
    actions += "    \"" + repair +
               "\": {\"ticks\": [2, 3], \"results\": [\"success\", \"failure\"], "
               "\"on_success\": \"" +
               ok + " = true\"},\n";
  }
  body += "          <Work/>\n        </Sequence>\n      </ForceSuccess>\n";
  write_file(dir / "mission.xml", mission_xml(body));
  write_file(dir / "domain.fret", domain);
  write_file(dir / "world.json",
             "{\n  \"initial\": \"" + initial + "\",\n  \"actions\": {\n" + actions +
                 "    \"Work\": {\"ticks\": 2, \"results\": [\"success\"]}\n  }\n}\n");
  write_file(dir / "requirements.fret",
             "Ready: Mission shall always satisfy Work.running -> (" + all_ok +
                 ")\nNeverWorks: Mission shall always satisfy !Work.running\n");
  FamilyMission m;
  m.dir = dir;
  m.tree_nodes = 3 * checks + 4;
  m.verdicts = {{"Ready", "proved"}, {"NeverWorks", "violated"}};
  m.violation_ticks = {{"NeverWorks", static_cast<std::uint64_t>(checks) + 1}};
  return m;
}

FamilyMission generate_preflight(const std::filesystem::path& dir, int flags) {
  if (flags < 1) throw std::invalid_argument("a pre-flight checklist has at least one flag");
  std::string body = "      <ForceSuccess>\n        <Sequence name=\"preflight\">\n";
  std::string domain =
      "# Sensor flags the vehicle reports. No action writes them, so the environment may set\n"
      "# each of them anew before every tick.\n";
  std::string actions, conditions, nodes;
  for (int i = 1; i <= flags; ++i) {
    const std::string ok = "Ok_" + std::to_string(i), repair = "Repair_" + std::to_string(i);
    body += "          <Fallback>\n            <" + ok + "/>\n            <" + repair +
            "/>\n          </Fallback>\n";
    conditions += "    <Condition ID=\"" + ok + "\"/>\n";
    nodes += "    <Action ID=\"" + repair + "\"/>\n";
    domain += "boolean " + ok + "\n";
    actions += "    \"" + repair + "\": {\"ticks\": [1, 2], \"results\": [\"success\"]},\n";
  }
  body += "          <Launch/>\n        </Sequence>\n      </ForceSuccess>\n";
  write_file(dir / "mission.xml", mission_xml(body));
  write_file(dir / "domain.fret", domain);
  write_file(dir / "nodes.xml", nodes_xml(conditions + nodes + "    <Action ID=\"Launch\"/>\n"));
  write_file(
      dir / "world.json",
      "{\n  \"description\": \"A repair takes one or two ticks and succeeds without setting its "
      "flag; the launch takes two ticks.\",\n  \"actions\": {\n" +
          actions + "    \"Launch\": {\"ticks\": 2, \"results\": [\"success\"]}\n  }\n}\n");
  const std::string last = std::to_string(flags);
  write_file(
      dir / "requirements.fret",
      "# A repair runs only for a flag that was found failed (proved).\n"
      "RepairOnlyWhenNeeded: Mission shall always satisfy Repair_" +
          last + ".running -> !Ok_" + last +
          "\n"
          "# The launch runs only while the first sensor is ok (violated: a repair does not set\n"
          "# the flag and nothing checks it again).\n"
          "LaunchOnlyWhenOk: Mission shall always satisfy Launch.running -> Ok_1\n");
  FamilyMission m;
  m.dir = dir;
  m.tree_nodes = 3 * flags + 4;
  m.verdicts = {{"RepairOnlyWhenNeeded", "proved"}, {"LaunchOnlyWhenOk", "violated"}};
  m.violation_ticks = {{"LaunchOnlyWhenOk", 1}};
  return m;
}

FamilyMission generate_recheck(const std::filesystem::path& dir, int flags, bool kept) {
  if (flags < 2) throw std::invalid_argument("a re-checked checklist has at least two flags");
  std::string body = "      <Sequence>\n";
  std::string domain =
      "# Sensor flags the vehicle reports. No action writes them, so the environment may set\n"
      "# each of them anew before every tick.\n";
  std::string actions, models, all_ok, assumptions;
  for (int i = 1; i <= flags; ++i) {
    const std::string check = "Check" + std::to_string(i), fix = "Fix" + std::to_string(i);
    body += "        <Fallback>\n          <" + check + "/>\n          <Sequence>\n            <" +
            fix + "/>\n            <" + check + "/>\n          </Sequence>\n        </Fallback>\n";
    domain += "boolean " + check + "\n";
    models += "    <Condition ID=\"" + check + "\"/>\n    <Action ID=\"" + fix + "\"/>\n";
    actions +=
        "    \"" + fix + "\": {\"ticks\": [1, 2], \"results\": [\"success\", \"failure\"]},\n";
    all_ok += (i > 1 ? " & " : "") + check;
    assumptions += "Keep" + std::to_string(i) + ": upon " + check +
                   " Environment shall always satisfy " + check + "\n";
  }
  body += "        <Launch/>\n      </Sequence>\n";
  write_file(dir / "mission.xml", mission_xml(body));
  write_file(dir / "domain.fret", domain);
  write_file(dir / "nodes.xml", nodes_xml(models + "    <Action ID=\"Launch\"/>\n"));
  write_file(
      dir / "world.json",
      "{\n  \"description\": \"A fix takes one or two ticks, succeeds or fails, and does not set "
      "its flag; the launch takes three ticks.\",\n  \"actions\": {\n" +
          actions + "    \"Launch\": {\"ticks\": 3, \"results\": [\"success\"]}\n  }\n}\n");
  write_file(dir / "requirements.fret",
             "# The launch runs only while every flag is set.\n"
             "Ready: Mission shall always satisfy (Launch.running | Launch.success) -> (" +
                 all_ok + ")\n" +
                 (kept ? "# A flag once set stays set.\n" + assumptions : std::string()));
  FamilyMission m;
  m.dir = dir;
  m.tree_nodes = 5 * flags + 3;
  m.verdicts = {{"Ready", kept ? "proved" : "violated"}};
  if (!kept) m.violation_ticks = {{"Ready", 2}};
  return m;
}

namespace {

std::string alternative(const std::string& id, const std::string& body) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"" + id + "\">\n  <BehaviorTree ID=\"" +
         id + "\">\n" + body + "  </BehaviorTree>\n</root>\n";
}

}  // namespace

namespace {

// The lunar sortie; with `reserve`, its battery thresholds stand above a reserve the samples
// raise (lunar_reserve).
FamilyMission lunar(const std::filesystem::path& dir, bool reserve) {
  // The charge a guard asks for: `k` percent, or the reserve (20 at first) plus k - 20.
  const auto charge = [&](int k) {
    return reserve ? "reserve + " + std::to_string(k - 20) : std::to_string(k);
  };
  write_file(
      dir / "mission.xml",
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!-- A lunar sampling sortie, over and over: reach the site, take a sample, stow it.\n"
      "     How to drive depends on the slope, the battery and the light (re-checked every\n"
      "     tick); how to sample depends on the battery and the light (chosen once). -->\n" +
          mission_xml("      <ForceSuccess>\n"
                      "        <Sequence name=\"sortie\">\n"
                      "          <Fallback name=\"reach_site\">\n"
                      "            <AtSite/>\n"
                      "            <Adaptable ID=\"traverse\" selection=\"reactive\"/>\n"
                      "          </Fallback>\n"
                      "          <Fallback name=\"collect\">\n"
                      "            <HasSample/>\n"
                      "            <Adaptable ID=\"sample\"/>\n"
                      "          </Fallback>\n"
                      "          <StowSample/>\n"
                      "        </Sequence>\n"
                      "      </ForceSuccess>\n"));
  write_file(dir / "alternatives/traverse/drive_direct.xml",
             alternative("drive_direct", "    <DriveDirect/>\n"));
  write_file(
      dir / "alternatives/traverse/drive_cautious.xml",
      alternative("drive_cautious",
                  "    <Sequence>\n      <ScanHazards/>\n      <DriveSlow/>\n    </Sequence>\n"));
  write_file(dir / "alternatives/traverse/hold_position.xml",
             alternative("hold_position", "    <HoldPosition/>\n"));
  write_file(
      dir / "alternatives/sample/drill_core.xml",
      alternative("drill_core",
                  "    <Sequence>\n      <DeployArm/>\n      <DrillCore/>\n    </Sequence>\n"));
  write_file(
      dir / "alternatives/sample/scoop_regolith.xml",
      alternative("scoop_regolith",
                  "    <Sequence>\n      <DeployArm/>\n      <ScoopRegolith/>\n    </Sequence>\n"));
  write_file(dir / "nodes.xml", nodes_xml("    <Condition ID=\"AtSite\"/>\n"
                                          "    <Condition ID=\"HasSample\"/>\n"
                                          "    <Action ID=\"DriveDirect\"/>\n"
                                          "    <Action ID=\"ScanHazards\"/>\n"
                                          "    <Action ID=\"DriveSlow\"/>\n"
                                          "    <Action ID=\"HoldPosition\"/>\n"
                                          "    <Action ID=\"DeployArm\"/>\n"
                                          "    <Action ID=\"DrillCore\"/>\n"
                                          "    <Action ID=\"ScoopRegolith\"/>\n"
                                          "    <Action ID=\"StowSample\"/>\n"));
  write_file(dir / "domain.fret",
             "# The terrain's slope under the rover (degrees) and the battery's charge (percent).\n"
             "real slope in [0, 30]\n"
             "real battery in [0, 100]\n"
             "# The light at the rover: full sun, a crater's shadow, or lunar night.\n"
             "enum illumination in {sun, shadow, night}\n"
             "# The mission's own state, written by its actions.\n"
             "boolean AtSite, HasSample\n" +
                 std::string(reserve ? "# The charge kept for the way back (percent): each sample "
                                       "raises it.\ninteger reserve in [20, 60]\n"
                                     : ""));
  write_file(
      dir / "requirements.fret",
      "# How to reach the site, in priority order; together the guards cover every state once.\n"
      "Direct: In traverse if battery >= " +
          charge(40) +
          " & slope < 10 & illumination = sun Mission shall satisfy selected_alt = "
          "drive_direct\n"
          "Cautious: In traverse if battery >= " +
          charge(40) +
          " & slope < 25 & (slope >= 10 | illumination != sun) Mission shall satisfy "
          "selected_alt = drive_cautious\n"
          "Hold: In traverse if battery < " +
          charge(40) +
          " | slope >= 25 Mission shall satisfy selected_alt = hold_position\n"
          "# How to take the sample: a core needs charge and light; otherwise scoop.\n"
          "Core: In sample if battery >= " +
          charge(60) +
          " & illumination != night Mission shall satisfy selected_alt = drill_core\n"
          "Scoop: In sample if battery < " +
          charge(60) +
          " | illumination = night Mission shall satisfy selected_alt = scoop_regolith\n"
          "\n"
          "# Guarantees. The direct drive runs only on flat, sunlit ground (proved: the traverse\n"
          "# guards are re-checked every tick).\n"
          "DirectOnFlat: Mission shall always satisfy traverse.selected = drive_direct -> slope < "
          "10 "
          "& illumination = sun\n"
          "# On a steep slope the rover holds its position (proved).\n"
          "HoldWhenSteep: Mission shall always satisfy traverse & slope >= 25 -> traverse.selected "
          "= "
          "hold_position\n"
          "# Samples are taken at the site only (proved).\n"
          "SampleAtSite: Mission shall always satisfy DrillCore.running | ScoopRegolith.running -> "
          "AtSite\n"
          "# The drill runs only on a charged battery (violated at tick 2: the sample selection "
          "is\n"
          "# made once, and the battery may drop while the drill runs).\n"
          "DrillOnCharge: Mission shall always satisfy DrillCore.running -> battery >= " +
          charge(60) + "\n");
  // A sample raises the reserve by 10, up to 60.
  const std::string sampled =
      reserve ? "HasSample = true; reserve = reserve < 60 ? reserve + 10 : 60" : "HasSample = true";
  std::string world = R"({
  "description": "Drives reach the site; holding fails so that the sortie starts over; the drill may fail; stowing the sample sends the rover on to the next site.",
  "initial": "!AtSite & !HasSample",
  "actions": {
    "DriveDirect": {"ticks": [1, 2], "results": ["success"], "on_success": "AtSite = true"},
    "ScanHazards": {"ticks": 1, "results": ["success"]},
    "DriveSlow": {"ticks": [2, 3], "results": ["success"], "on_success": "AtSite = true"},
    "HoldPosition": {"ticks": [1, 2], "results": ["failure"]},
    "DeployArm": {"ticks": 1, "results": ["success"]},
    "DrillCore": {"ticks": [2, 3], "results": ["success", "failure"], "on_success": "HasSample = true"},
    "ScoopRegolith": {"ticks": [1, 2], "results": ["success"], "on_success": "HasSample = true"},
    "StowSample": {"ticks": 1, "results": ["success"], "on_success": "AtSite = false; HasSample = false"}
  }
}
)";
  for (std::size_t at = 0; (at = world.find("\"HasSample = true\"", at)) != std::string::npos;
       at += sampled.size() + 2)
    world.replace(at, 18, "\"" + sampled + "\"");
  if (reserve) world.replace(world.find("!HasSample\""), 11, "!HasSample & reserve = 20\"");
  write_file(dir / "world.json", world);
  FamilyMission m;
  m.dir = dir;
  // MainTree 10, the selection trees 20 (traverse) and 11 (sample), the alternatives 11.
  m.tree_nodes = 52;
  m.verdicts = {{"DirectOnFlat", "proved"},
                {"HoldWhenSteep", "proved"},
                {"SampleAtSite", "proved"},
                {"DrillOnCharge", "violated"}};
  m.violation_ticks = {{"DrillOnCharge", 2}};
  return m;
}

}  // namespace

FamilyMission generate_lunar(const std::filesystem::path& dir) {
  return lunar(dir, false);
}

FamilyMission generate_lunar_reserve(const std::filesystem::path& dir) {
  return lunar(dir, true);
}

namespace {

// `where` says what `guard` says, shortly.
FamilyMission site(const std::filesystem::path& dir, const std::string& domain,
                   const std::string& guard, const std::string& where) {
  write_file(dir / "mission.xml",
             mission_xml("      <Adaptable ID=\"site\" selection=\"reactive\"/>\n"));
  write_file(dir / "alternatives/site/dig.xml", alternative("dig", "    <Dig/>\n"));
  write_file(dir / "alternatives/site/hold.xml", alternative("hold", "    <Hold/>\n"));
  write_file(dir / "nodes.xml", nodes_xml("    <Action ID=\"Dig\"/>\n    <Action ID=\"Hold\"/>\n"));
  write_file(dir / "domain.fret", domain);
  write_file(dir / "world.json",
             "{\n  \"actions\": {\n"
             "    \"Dig\": {\"ticks\": [1, 2], \"results\": [\"success\"]},\n"
             "    \"Hold\": {\"ticks\": 1, \"results\": [\"success\"]}\n  }\n}\n");
  write_file(dir / "requirements.fret",
             "Dig: In site if " + guard +
                 " Mission shall satisfy selected_alt = dig\n"
                 "Hold: In site Mission shall satisfy selected_alt = hold\n"
                 "DigOnlyWhereSelected: the rover shall always satisfy Dig.running -> " +
                 where + "\n");
  FamilyMission m;
  m.dir = dir;
  m.verdicts = {{"DigOnlyWhereSelected", "proved"}};
  return m;
}

}  // namespace

FamilyMission generate_disjunct_site(const std::filesystem::path& dir, int disjuncts) {
  if (disjuncts < 1) throw std::invalid_argument("a guard has at least one disjunct");
  std::string guard = "depth = 0";
  for (int k = 1; k < disjuncts; ++k) guard += " | depth = " + std::to_string(k);
  return site(dir, "integer depth in [0, 100000]\n", guard, "depth < " + std::to_string(disjuncts));
}

FamilyMission generate_enum_site(const std::filesystem::path& dir, int values) {
  if (values < 3) throw std::invalid_argument("the terrain has sand, rocks and unknown at least");
  std::string domain = "enum terrain in {sand, rocks, unknown";
  for (int k = 0; k + 3 < values; ++k) domain += ", v" + std::to_string(k);
  return site(dir, domain + "}\n", "terrain = sand", "terrain = sand");
}

}  // namespace uabt::bench
