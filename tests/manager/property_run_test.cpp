// Mission properties monitored on every tick of a run (ARCHITECTURE §10): Curiosity's shipped
// properties hold in its scenarios, and each violation is traced at its tick with the values
// the property read.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "base/diagnostics.hpp"
#include "manager/manager.hpp"
#include "style_missions.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::manager {
namespace {

using namespace uabt::runtime;  // the scenarios and traces the manager runs on

std::filesystem::path curiosity() {
  return uabt::testing::mission_dir("msl_curiosity");
}

ManagerRun run_in(const std::filesystem::path& mission, const std::string& scenario,
                  compile::SelectionStyle style) {
  ManagerOptions options;
  options.gate.compile.selection = style;
  options.gate.compile.selection_forced = true;
  BehaviorTreeManager manager(mission, load_scenario(mission / "scenarios" / scenario), options);
  return manager.run();
}

std::vector<const TraceEvent*> violations(const ManagerRun& run) {
  std::vector<const TraceEvent*> out;
  for (const auto& e : run.trace)
    if (e.event == "violation") out.push_back(&e);
  return out;
}

const monitor::PropertyResult& property(const ManagerRun& run, const std::string& id) {
  for (const auto& p : run.properties)
    if (p.id == id) return p;
  throw std::runtime_error("no property " + id);
}

TEST(MissionProperties, CuriosityHoldsItsPropertiesInItsScenarios) {
  for (const char* scenario : {"dusty_start.json", "rocks_mid_drive.json", "mud_uplink.json"}) {
    const ManagerRun run = run_in(curiosity(), scenario, compile::SelectionStyle::reactive);
    // Three selection requirements, four properties and the domain's assumption; on_mud adds
    // the selection requirement Req3, restates HoldOnUnknown and adds the assumption mud_alone.
    ASSERT_EQ(run.properties.size(), scenario == std::string("mud_uplink.json") ? 11u : 8u);
    for (const auto& p : run.properties)
      EXPECT_EQ(p.verdict, monitor::Verdict::held) << scenario << ": " << p.id << " " << p.reason;
    EXPECT_FALSE(run.guarantees_failed);
    EXPECT_TRUE(violations(run).empty()) << trace_summary(run);
  }
}

// An obligation still open when the run ends (the arm closes in the last tick, so the stop
// it asks for within 3 ticks never comes) holds, as FRET's finite-trace meaning says; the
// summary and the trace say it is pending, what is due and since which tick.
TEST(MissionProperties, AnObligationOpenAtTheEndIsHeldButPending) {
  auto files = uabt::testing::mission_files("msl_curiosity");
  files["requirements.fret"] +=
      "Park: upon CloseToolArm.success the rover shall within 3 ticks satisfy Stop.running\n";
  uabt::testing::TempMission dir(files);
  const ManagerRun run = run_in(dir.dir(), "dusty_start.json", compile::SelectionStyle::reactive);
  ASSERT_EQ(run.verdict, "success");
  const auto& park = property(run, "Park");
  EXPECT_EQ(park.verdict, monitor::Verdict::held);
  EXPECT_EQ(park.pending, "Stop.running within 3 ticks");
  EXPECT_EQ(park.pending_since, run.ticks) << "the arm closes in the last tick";
  EXPECT_FALSE(property(run, "NoDrillAway").pending_since);
  EXPECT_FALSE(run.guarantees_failed);
  const std::string last = std::to_string(run.ticks);
  EXPECT_NE(property_summary(run).find("property Park: held (pending at end: Stop.running within "
                                       "3 ticks, triggered at tick " +
                                       last + ")\n"),
            std::string::npos)
      << property_summary(run);
  EXPECT_NE(trace_json_lines(run.trace).find(
                "{\"tick\":" + last +
                ",\"event\":\"pending\",\"requirement\":\"Park\",\"role\":\"guarantee\","
                "\"obligation\":\"Stop.running within 3 ticks\",\"since\":" +
                last + "}"),
            std::string::npos)
      << trace_json_lines(run.trace);
}

TEST(MissionProperties, ShortDriveDrillsAwayFromTheTarget) {
  const ManagerRun run = run_in(curiosity(), "short_drive.json", compile::SelectionStyle::sequence);
  EXPECT_EQ(run.status, NodeStatus::success) << "the tree itself completes";
  EXPECT_TRUE(run.guarantees_failed);
  const auto found = violations(run);
  ASSERT_EQ(found.size(), 1u) << trace_summary(run);
  EXPECT_EQ(found[0]->requirement, "NoDrillAway");
  EXPECT_EQ(found[0]->role, "guarantee");
  EXPECT_EQ(found[0]->tick, 22u) << "MoveForward ends at tick 21; Drill starts at 22";
  const std::vector<std::pair<std::string, Value>> values = {
      {"Drill.running", Value::of_bool(true)}, {"IsInLocation", Value::of_bool(false)}};
  EXPECT_EQ(found[0]->values, values);
  EXPECT_EQ(property(run, "NoDrillAway").first_violation, 22u);
  const std::string json = trace_json_lines(run.trace);
  EXPECT_NE(json.find("{\"tick\":22,\"event\":\"violation\",\"requirement\":\"NoDrillAway\","
                      "\"role\":\"guarantee\",\"values\":{\"Drill.running\":true,"
                      "\"IsInLocation\":false}}"),
            std::string::npos)
      << json;
}

// The paper's plain Fallback keeps on_rocks running into the mud: hold_position comes only
// with the reactive selection, and the property says so at the tick after the mud appears.
TEST(MissionProperties, UnknownTerrainNeedsTheReactiveSelection) {
  const ManagerRun run = run_in(curiosity(), "mud_uplink.json", compile::SelectionStyle::sequence);
  const auto found = violations(run);
  ASSERT_EQ(found.size(), 1u) << trace_summary(run);
  EXPECT_EQ(found[0]->requirement, "HoldOnUnknown");
  EXPECT_EQ(found[0]->tick, 11u) << "mud from tick 10; within 1 tick ends at 11";
  const std::vector<std::pair<std::string, Value>> values = {
      {"navigation", Value::of_bool(true)},
      {"OnDust", Value::of_bool(false)},
      {"OnRocks", Value::of_bool(false)},
      {"navigation.selected", Value::of_enum("on_rocks")}};
  EXPECT_EQ(found[0]->values, values);
}

// The version an uplink swaps in brings its own properties: the restated HoldOnUnknown
// stops at the swap and its new text is monitored from the next tick on, like the package's
// new assumption, over the trace from there.
TEST(MissionProperties, AnUplinksPropertiesAreMonitoredFromTheSwap) {
  const ManagerRun run = run_in(curiosity(), "mud_uplink.json", compile::SelectionStyle::reactive);
  std::vector<const monitor::PropertyResult*> hold;
  for (const auto& p : run.properties)
    if (p.id == "HoldOnUnknown") hold.push_back(&p);
  ASSERT_EQ(hold.size(), 2u) << property_summary(run);
  EXPECT_EQ(hold[0]->monitored_until, 29u);
  EXPECT_FALSE(hold[0]->monitored_from);
  EXPECT_EQ(hold[1]->monitored_from, 30u);
  EXPECT_FALSE(hold[1]->monitored_until);
  EXPECT_EQ(property(run, "mud_alone").monitored_from, 30u);
  EXPECT_FALSE(property(run, "NoDrillAway").monitored_from) << "kept: monitored throughout";
  EXPECT_FALSE(property(run, "NoDrillAway").monitored_until);
  EXPECT_NE(property_summary(run).find(
                "property HoldOnUnknown: held (added by an uplink: monitored from tick 30)"),
            std::string::npos)
      << property_summary(run);
}

// A guarantee the package adds about a node of its own alternative: the gate proves it in
// world.json's world (a drive takes 1 to 3 ticks), the rehearsal's scenario drives through
// mud for 25 ticks, and the run sees the swapped-in node run too long.
TEST(MissionProperties, ANewGuaranteeReadsTheSwappedInTreesNodes) {
  uabt::testing::TempMission scratch({}, "work");
  const auto dir = scratch.dir() / "msl";
  std::filesystem::copy(curiosity(), dir, std::filesystem::copy_options::recursive);
  const auto package = dir / "uplinks" / "mud_timed";
  std::filesystem::copy(dir / "uplinks" / "on_mud", package,
                        std::filesystem::copy_options::recursive);
  scratch.write(
      "msl/uplinks/mud_timed/alternatives/navigation/on_mud.xml",
      uabt::testing::alternative_tree(
          "on_mud", "<Sequence><IsTowardObject/><MoveForward name=\"crawl\"/></Sequence>"));
  {
    std::ofstream add(package / "requirements.fret", std::ios::app);
    add << "CrawlBrief: upon crawl.running the rover shall within 3 ticks satisfy !crawl.running\n";
  }
  std::ifstream in(dir / "scenarios" / "mud_uplink.json");
  std::string scenario((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "\"uplinks/on_mud\"";
  scenario.replace(scenario.find(from), from.size(), "\"uplinks/mud_timed\"");
  scratch.write("msl/scenarios/mud_timed.json", scenario);

  const ManagerRun run = run_in(dir, "mud_timed.json", compile::SelectionStyle::reactive);
  ASSERT_EQ(run.accepted_uplinks, std::vector<std::string>{"uplinks/mud_timed"})
      << trace_summary(run);
  const monitor::PropertyResult& crawl = property(run, "CrawlBrief");
  EXPECT_EQ(crawl.monitored_from, 30u);
  EXPECT_EQ(crawl.verdict, monitor::Verdict::violated) << property_summary(run);
  EXPECT_EQ(crawl.first_violation, 33u) << "crawl runs from tick 30; within 3 ticks ends at 33";
  EXPECT_TRUE(run.guarantees_failed);
  const auto found = violations(run);
  ASSERT_EQ(found.size(), 1u) << trace_summary(run);
  EXPECT_EQ(found[0]->requirement, "CrawlBrief");
}

// Sequence[Adaptable nav, Drill] with one alternative `go` (MoveForward), the selection
// requirement Go, then `properties` and a scenario s.json.
std::map<std::string, std::string> drill_mission(const std::string& properties,
                                                 const std::string& scenario) {
  return {
      {"mission.xml",
       uabt::testing::mission_with("    <Sequence><Adaptable ID=\"nav\"/><Drill/></Sequence>")},
      {"alternatives/nav/go.xml", uabt::testing::alternative_tree("go", "<MoveForward/>")},
      {"requirements.fret", "Go: In nav Mission shall satisfy selected_alt = go\n" + properties},
      {"scenarios/s.json", scenario}};
}

// An assumption that fails is traced, but only guarantees decide the run.
TEST(MissionProperties, AssumptionsAreTracedGuaranteesDecide) {
  uabt::testing::TempMission m(
      drill_mission("Done: the rover shall eventually satisfy Drill.success\n"
                    "Picked: In nav the rover shall immediately satisfy nav.selected = go\n"
                    "World: the Environment shall always satisfy !Drill.running\n",
                    "{\"max_ticks\": 10, \"actions\": {\"Drill\": {\"ticks\": 2}}}"));
  const ManagerRun run = run_in(m.dir(), "s.json", compile::SelectionStyle::sequence);
  EXPECT_EQ(run.status, NodeStatus::success) << trace_summary(run);
  EXPECT_EQ(property(run, "Done").verdict, monitor::Verdict::held);
  EXPECT_EQ(property(run, "Picked").verdict, monitor::Verdict::held);
  EXPECT_EQ(property(run, "World").verdict, monitor::Verdict::violated);
  EXPECT_TRUE(property(run, "World").assumption);
  const auto found = violations(run);
  ASSERT_EQ(found.size(), 1u) << trace_summary(run);
  EXPECT_EQ(found[0]->role, "assumption");
  EXPECT_EQ(found[0]->tick, 1u) << "MoveForward succeeds in tick 1, so Drill starts in it";
  EXPECT_FALSE(run.guarantees_failed);
}

// FRET's temporal functions on a run: Drill runs in ticks 1 and 2 and succeeds in tick 3, so
// it persisted for one tick more at tick 2, never for three, and its success follows a run.
TEST(MissionProperties, TemporalFunctionsAreMonitoredOnARun) {
  uabt::testing::TempMission m(drill_mission(
      "Long: the rover shall always satisfy !persisted(1, Drill.running)\n"
      "Short: the rover shall always satisfy !persisted(3, Drill.running)\n"
      "Ran: upon Drill.success the rover shall immediately satisfy occurred(2, Drill.running)\n"
      "First: the rover shall always satisfy FTP -> !Drill.success\n",
      "{\"max_ticks\": 10, \"actions\": {\"Drill\": {\"ticks\": 3}}}"));
  const ManagerRun run = run_in(m.dir(), "s.json", compile::SelectionStyle::sequence);
  EXPECT_EQ(property(run, "Long").verdict, monitor::Verdict::violated) << trace_summary(run);
  EXPECT_EQ(property(run, "Short").verdict, monitor::Verdict::held) << trace_summary(run);
  EXPECT_EQ(property(run, "Ran").verdict, monitor::Verdict::held) << trace_summary(run);
  EXPECT_EQ(property(run, "First").verdict, monitor::Verdict::held) << trace_summary(run);
  const auto found = violations(run);
  ASSERT_EQ(found.size(), 1u) << trace_summary(run);
  EXPECT_EQ(found[0]->requirement, "Long");
  EXPECT_EQ(found[0]->tick, 2u);
}

// A property that names what the run cannot observe never reaches a run: the gate refuses it.
TEST(MissionProperties, TheGateRefusesPropertiesWithoutMeaning) {
  uabt::testing::TempMission m(
      drill_mission("Typo: the rover shall always satisfy !Dril.running\n"
                    "Kind: the rover shall always satisfy nav.selected < 3\n"
                    "Secs: the rover shall within 2 seconds satisfy Drill.success\n"
                    "Temp: the rover shall always satisfy occurred(2, nav.selected)\n",
                    "{\"max_ticks\": 10}"));
  try {
    run_in(m.dir(), "s.json", compile::SelectionStyle::sequence);
    FAIL() << "the gate passed";
  } catch (const uabt::manager::NotAdmitted& e) {
    const std::string text = format_text(e.findings);
    EXPECT_NE(text.find("requirements.fret:2:39: error: 'Dril.running' is not an observable of "
                        "the run"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("did you mean 'Drill.running'?"), std::string::npos) << text;
    EXPECT_NE(text.find("requirements.fret:3:38: error: 'nav.selected < 3' needs numbers, got a "
                        "name [property-type]"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("requirements.fret:4:30: error: Secs: timing 'within 2 seconds' is not in "
                        "ticks"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("requirements.fret:5:50: error: 'nav.selected' is a name, but occurred "
                        "needs a boolean there [property-type]"),
              std::string::npos)
        << text;
  }
}

// Two nodes with one ID (sample_drilling's drills without their `name="Drill"`): `Drill.running`
// means any of them, in the run as in the gate and in prove.
TEST(MissionProperties, ALabelTwoNodesShareMeansAnyOfThem) {
  auto files = uabt::testing::unnamed_drills();
  // Soft rock, a hot bit: rotary drills it (CoolBit is violated at once); then hard rock.
  files["scenarios/hot.json"] =
      R"({"max_ticks": 40, "initial": {"HardRock": false, "IsBitCool": false},
          "actions": {"Drill": {"ticks": 2, "effects": {"IsBitCool": false}},
                      "CoolDown": {"ticks": 2, "effects": {"IsBitCool": true}}},
          "events": [{"at": 3, "set": {"HardRock": true}}]})";
  const uabt::testing::TempMission m(files, "sample_drilling");
  const ManagerRun run = run_in(m.dir(), "hot.json", compile::SelectionStyle::sequence);
  EXPECT_EQ(property(run, "CoolBit").verdict, monitor::Verdict::violated) << trace_summary(run);
  EXPECT_EQ(property(run, "CoolBit").first_violation, 1u);
  EXPECT_EQ(property(run, "OneTool").verdict, monitor::Verdict::held)
      << property(run, "OneTool").reason;
}

}  // namespace
}  // namespace uabt::manager
