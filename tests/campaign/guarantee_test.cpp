// Guarantee targets of the test campaign (FRET's FLIP obligations, solved by the prove engines
// over world.json) and campaign scenarios that play in world.json's world.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "base/diagnostics.hpp"
#include "campaign/campaign.hpp"
#include "campaign/guarantee.hpp"
#include "cli/cli_support.hpp"
#include "load/load_test_support.hpp"
#include "prove/reach.hpp"
#include "prove/world_model.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

using campaign::Criterion;

load::Mission load(const std::filesystem::path& dir) {
  return load_dir(dir);
}

campaign::Options guarantees_only() {
  campaign::Options options;
  options.criteria = {Criterion::guarantee};
  return options;
}

// The files of a shipped mission, without its scenarios and uplinks.
std::map<std::string, std::string> shipped(const std::string& name) {
  std::map<std::string, std::string> files;
  const auto dir = source_dir() / "missions" / name;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = std::filesystem::relative(e.path(), dir).generic_string();
    if (rel.starts_with("uplinks/") || rel.starts_with("scenarios/")) continue;
    files[rel] = read_all(e.path());
  }
  return files;
}

const campaign::Target& target(const campaign::Campaign& c, const std::string& id) {
  for (const auto& t : c.targets)
    if (t.id == id) return t;
  ADD_FAILURE() << "no target " << id;
  return c.targets.front();
}

// Runs every guarantee scenario of `c` with `uabt run --monitor-trace` and reads the trace
// back with `uabt coverage`, which judges it on the campaign's traps: each purpose must be
// covered (its goal reached) within the scenario's ticks.
void expect_scenarios_reach_their_goals(const campaign::Campaign& c,
                                        const std::filesystem::path& mission_dir,
                                        const std::filesystem::path& scratch,
                                        const std::string& label) {
  for (const auto& s : c.scenarios) {
    if (!s.name.starts_with("guarantee-")) continue;
    EXPECT_TRUE(s.problems.empty()) << label << " " << s.name;
    const auto file = scratch / (s.name + ".json");
    const auto trace = scratch / (s.name + ".jsonl");
    std::ofstream(file) << s.json;
    const CliRun run = run_uabt_in(
        scratch.string(), "run '" + mission_dir.string() + "' --scenario '" + file.string() +
                              "' --monitor-trace '" + trace.string() + "'");
    ASSERT_TRUE(std::filesystem::exists(trace)) << label << " " << s.name << "\n" << run.out;
    const CliRun checked =
        run_uabt_in(scratch.string(), "coverage '" + mission_dir.string() + "' '" + trace.string() +
                                          "' --format json");
    const auto j = nlohmann::json::parse(checked.out.substr(checked.out.find('{')));
    std::map<std::string, bool> covered;
    for (const auto& t : j["targets"]) covered[t["id"]] = t["covered"];
    for (std::size_t t : s.purpose)
      EXPECT_TRUE(covered[c.targets[t].id])
          << label << " " << s.name << ": " << c.targets[t].id << " is not reached\n"
          << s.json << checked.out;
  }
}

TEST(CampaignGuarantees, MslCuriosityTriggersAndEveryAtomDeciding) {
  const load::Mission m = load(source_dir() / "missions" / "msl_curiosity");
  const campaign::Campaign c = campaign::build_campaign(m, guarantees_only());
  std::vector<std::string> ids;
  for (const auto& t : c.targets) ids.push_back(t.id);
  const std::vector<std::string> expected = {
      "guarantee/HoldOnUnknown/trigger",
      "guarantee/HoldOnUnknown/condition/OnDust/true",
      "guarantee/HoldOnUnknown/condition/OnDust/false",
      "guarantee/HoldOnUnknown/condition/OnRocks/true",
      "guarantee/HoldOnUnknown/condition/OnRocks/false",
      "guarantee/HoldOnUnknown/response/navigation.selected = hold_position/true",
      "guarantee/HoldOnUnknown/response/navigation.selected = hold_position/false",
      "guarantee/ArmClosed/trigger",
      "guarantee/ArmClosed/condition/OpenToolArm.success/true",
      "guarantee/ArmClosed/condition/OpenToolArm.success/false",
      "guarantee/ArmClosed/response/drive.running/true",
      "guarantee/ArmClosed/response/drive.running/false"};
  EXPECT_EQ(ids, expected);
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    const auto& t = c.targets[k];
    EXPECT_EQ(t.criterion, Criterion::guarantee);
    // The guarantee itself is proved: its response cannot be made false where it is due.
    const bool refuted = t.id == expected[6] || t.id == expected[10];
    EXPECT_EQ(t.reachable, !refuted) << t.id << ": " << t.reason;
    EXPECT_EQ(c.covered[k], !refuted) << t.id;
  }
  EXPECT_EQ(target(c, expected[10]).reason,
            "no run that world.json allows reaches it (ArmClosed at " + path_prefix_for(m.dir) +
                "requirements.fret:20:12)");
  EXPECT_EQ(target(c, "guarantee/HoldOnUnknown/trigger").text,
            "the trigger of HoldOnUnknown fires (in navigation, upon !OnDust & !OnRocks)");
  EXPECT_TRUE(c.passed()) << campaign::campaign_text(c);
  // Fewer scenarios than reached targets: one run covers several.
  EXPECT_LT(c.scenarios.size(), 10u);
  TempMission scratch({});
  expect_scenarios_reach_their_goals(c, source_dir() / "missions" / "msl_curiosity", scratch.dir(),
                                     "msl_curiosity");
}

// A mission whose tree selects at `node` (alt0 when a holds, else fallback), then runs
// `actions` in sequence; requirements.fret holds the two selection requirements.
std::map<std::string, std::string> node_then(const std::vector<std::string>& actions,
                                             const std::string& domain) {
  std::string body = "    <Sequence>\n      <Adaptable ID=\"node\"/>\n";
  for (const auto& a : actions) body += "      <" + a + "/>\n";
  std::map<std::string, std::string> files;
  files["mission.xml"] = mission_with(body + "    </Sequence>");
  files["domain.fret"] = domain;
  files["alternatives/node/alt0.xml"] = alternative_tree("alt0", "<AlwaysSuccess/>");
  files["alternatives/node/fallback.xml"] = alternative_tree("fallback", "<AlwaysSuccess/>");
  files["requirements.fret"] =
      "R0: In node if a Mission shall satisfy selected_alt = alt0\n"
      "Default: In node Mission shall satisfy selected_alt = fallback\n";
  return files;
}

// One guarantee per timing that judges the response after its trigger, over a run where Act1
// succeeds at tick 1, Act2 runs at tick 1 and succeeds at tick 2, Act3 runs at tick 2 and
// succeeds at tick 3: each response atom can decide only after the trigger (Act1.success).
std::map<std::string, std::string> timed_mission() {
  auto files = node_then({"Act1", "Act2", "Act3"}, "boolean a\n");
  files["requirements.fret"] +=
      "Next: upon Act1.success the robot shall at the next timepoint satisfy Act2.success\n"
      "Eventually: upon Act1.success the robot shall eventually satisfy Act2.success\n"
      "Within: upon Act1.success the robot shall within 2 ticks satisfy Act2.success\n"
      "For: upon Act1.success the robot shall for 1 tick satisfy !Act2.success\n"
      "After: upon Act1.success the robot shall after 1 tick satisfy Act3.success\n"
      "Until: upon Act1.success the robot shall until Act3.success satisfy !Act2.success\n"
      "Before: upon Act1.success the robot shall before Act3.success satisfy Act2.success\n";
  files["world.json"] = R"({"actions": {"Act1": {"ticks": 1, "results": ["success"]},)"
                        R"( "Act2": {"ticks": 2, "results": ["success"]},)"
                        R"( "Act3": {"ticks": 2, "results": ["success"]}}})";
  return files;
}

TEST(CampaignGuarantees, AResponseAtomDecidesWhereTheTimingJudgesTheResponseNotAtTheTrigger) {
  TempMission dir(timed_mission());
  const load::Mission m = load(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, guarantees_only());
  ASSERT_TRUE(c.notes.empty()) << c.notes.front();
  // The target, the tick its trap is reached at (the trigger fires at tick 1), its text.
  const std::vector<std::tuple<std::string, std::uint64_t, std::string>> expected = {
      {"Next/response/Act2.success/true", 2, "(at the tick after its trigger)"},
      {"Eventually/response/Act2.success/true", 2,
       "(at the first tick it holds after its trigger)"},
      {"Within/response/Act2.success/true", 2,
       "(at the first tick it holds within 2 ticks of its trigger, else at the last tick of "
       "that window)"},
      {"For/response/Act2.success/true", 2,
       "(at the first tick it fails within 1 tick of its trigger, else at the last tick of "
       "that window)"},
      {"After/response/Act3.success/true", 3,
       "(at the first tick it holds within 1 tick of its trigger, too early, else 2 ticks after "
       "the trigger)"},
      {"Until/response/Act2.success/true", 2,
       "(at a tick from its trigger until Act3.success, while it held before)"},
      {"Before/response/Act2.success/true", 2,
       "(at the first tick it holds after its trigger and before Act3.success, else at "
       "Act3.success)"}};
  const auto replayer = campaign::Replayer::compiling(m, {});
  const prove::WorldModel world = prove::mission_world(m);
  std::map<std::string, prove::Goal> goals;
  for (const auto& g : campaign::guarantee_goals(m)) goals[g.id] = g;
  for (const auto& [id, tick, words] : expected) {
    const std::string full = "guarantee/" + id;
    const campaign::Target& t = target(c, full);
    EXPECT_TRUE(t.reachable) << full << ": " << t.reason;
    EXPECT_NE(t.text.find(words), std::string::npos) << t.text;
    std::size_t k = 0;
    while (k < c.targets.size() && c.targets[k].id != full) ++k;
    ASSERT_LT(k, c.targets.size());
    // Covered: the replay with the runtime's monitor reached the trap at the planned tick.
    EXPECT_TRUE(c.covered[k]) << full << "\n" << campaign::campaign_text(c);
    const auto answer = prove::reach(m, replayer.document(), world, {goals.at(full)}, {});
    ASSERT_EQ(answer.front().verdict, prove::Verdict::violated) << full;
    EXPECT_EQ(answer.front().witness->tick, tick) << full;
  }
  // Both engines decide every target's trap alike.
  prove::Options explicit_engine, symbolic_engine;
  explicit_engine.engine = "explicit";
  symbolic_engine.engine = "symbolic";
  for (const auto& [id, goal] : goals) {
    const auto e = prove::reach(m, replayer.document(), world, {goal}, explicit_engine);
    const auto s = prove::reach(m, replayer.document(), world, {goal}, symbolic_engine);
    EXPECT_EQ(e.front().verdict, s.front().verdict) << id;
    if (e.front().witness && s.front().witness) {
      EXPECT_EQ(e.front().witness->tick, s.front().witness->tick) << id;
    }
  }
  // Until's response is due at the trigger's tick too (FRET's until includes it): there
  // Act2.success is false and decides it.
  EXPECT_TRUE(target(c, "guarantee/Until/response/Act2.success/false").reachable);
  // Eventually judges only a tick where the response holds: false never decides it.
  EXPECT_FALSE(target(c, "guarantee/Eventually/response/Act2.success/false").reachable);
  EXPECT_TRUE(c.passed()) << campaign::campaign_text(c);
  expect_scenarios_reach_their_goals(c, dir.dir(), dir.dir().parent_path(), "timed");
}

TEST(CampaignGuarantees, ATriggerWorldJsonRulesOutIsUnreachableWithTheGuaranteesLine) {
  auto files = shipped("msl_curiosity");
  // The arm never opens: ArmClosed's trigger cannot fire.
  const std::string open = R"("OpenToolArm": {"ticks": 1, "results": ["success"]})";
  auto& world = files.at("world.json");
  ASSERT_NE(world.find(open), std::string::npos);
  world.replace(world.find(open), open.size(),
                R"("OpenToolArm": {"ticks": 1, "results": ["failure"]})");
  TempMission dir(files);
  const CliRun run =
      run_uabt_in(dir.dir().parent_path().string(), "tests m --out o --criterion guarantee");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("unreachable: the trigger of ArmClosed fires (upon OpenToolArm.success): "
                         "no run that world.json allows reaches it (ArmClosed at "
                         "m/requirements.fret:20:12)\n"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.rfind("m: 12 targets (guarantee 12), 5 unreachable; ", 0), 0u) << run.out;
}

TEST(CampaignGuarantees, ATargetNotDecidedWithinTheDepthIsListedAsSuch) {
  const load::Mission m = load(source_dir() / "missions" / "msl_curiosity");
  campaign::Options options = guarantees_only();
  options.prove_depth = 1;  // the engines stop after one tick: nothing is proved unreachable
  const campaign::Campaign c = campaign::build_campaign(m, options);
  const campaign::Target& drive = target(c, "guarantee/ArmClosed/response/drive.running/true");
  EXPECT_FALSE(drive.reachable);
  EXPECT_TRUE(drive.undecided);
  EXPECT_EQ(drive.reason, "not decided within 1 tick");
  const std::string text = campaign::campaign_text(c);
  EXPECT_EQ(text.rfind("msl_curiosity: 12 targets (guarantee 12), 0 unreachable, 2 not decided; "
                       "3 scenarios cover 10 of 10 reachable targets\n",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("not decided: drive.running is true and decides the response of ArmClosed "
                      "(at a tick from its trigger until CloseToolArm.success, while it held "
                      "before): not decided within 1 tick\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("unreachable: "), std::string::npos) << text;
  const auto summary = nlohmann::json::parse(campaign::campaign_json(c))["summary"];
  EXPECT_EQ(summary["undecided"], 2);
  EXPECT_EQ(summary["unreachable"], 0);
}

TEST(CampaignGuarantees, WithoutWorldJsonOneLineSaysTheyAreNotPlanned) {
  auto files = shipped("msl_curiosity");
  files.erase("world.json");
  TempMission dir(files);
  const CliRun run = run_uabt_in(dir.dir().parent_path().string(), "tests m --out o");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  const std::string line = "guarantee targets not planned: the mission has no world.json\n";
  EXPECT_NE(run.out.find(line), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find(line), run.out.rfind(line)) << run.out;
  EXPECT_EQ(run.out.find("guarantee-"), std::string::npos) << run.out;
}

TEST(CampaignGuarantees, AMissionWithoutATriggeredGuaranteeSaysWhyThereAreNoGuaranteeTargets) {
  // The paper's replication package states selection requirements only.
  const auto mission = replication_dir();
  if (!std::filesystem::exists(mission)) GTEST_SKIP() << "replication package not present";
  TempMission scratch({});
  const auto out = scratch.dir() / "campaign";
  const CliRun run =
      run_uabt_in(scratch.dir().string(), "tests '" + mission.string() + "' --out '" +
                                              out.string() + "' --criterion guarantee");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  const std::string note =
      "guarantee targets not planned: no guarantee of this mission has a trigger (a mode, an "
      "upon/if/when condition)";
  EXPECT_EQ(run.out,
            "bt-generator: 0 targets, 0 unreachable; 0 scenarios cover 0 of 0 reachable "
            "targets\n" +
                note + "\n");
  const auto summary = nlohmann::json::parse(read_all(out / "campaign.json"));
  EXPECT_EQ(summary["notes"], nlohmann::json::array({note})) << summary.dump(2);
  // uabt coverage says the same, in text and JSON.
  const std::string scenario = (scratch.dir() / "dust.json").string();
  scratch.write("dust.json",
                "{\"max_ticks\": 1, \"initial\": {\"OnDust\": true, \"OnRock\": false}}\n");
  const CliRun text =
      run_uabt_in(scratch.dir().string(), "coverage '" + mission.string() + "' '" + scenario + "'");
  EXPECT_NE(text.out.find("\n" + note + "\n"), std::string::npos) << text.out;
  const CliRun json = run_uabt_in(scratch.dir().string(), "coverage '" + mission.string() + "' '" +
                                                              scenario + "' --format json");
  EXPECT_EQ(nlohmann::json::parse(json.out)["notes"], nlohmann::json::array({note})) << json.out;
}

// A random small mission with world.json: a node, two actions with random contracts (one
// writes c), and one or two guarantees with a trigger over a, b, c and the actions.
std::map<std::string, std::string> random_world_mission(unsigned seed) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  auto files = node_then({"Act1", "Act2"}, "boolean a, b, c\n");
  const char* conditions[] = {"a", "!b", "c", "Act1.success", "Act1.failure", "Act2.running"};
  const char* responses[] = {"c", "!a", "Act2.success", "Act2.running", "b"};
  std::string reqs = files["requirements.fret"];
  for (int g = 0, n = 1 + pick(2); g < n; ++g) {
    std::string condition = conditions[pick(6)];
    if (pick(2)) condition += std::string(pick(2) ? " & " : " | ") + conditions[pick(6)];
    std::string response = responses[pick(5)];
    if (pick(2)) response += std::string(" | ") + responses[pick(5)];
    reqs += "G" + std::to_string(g) + ": " + (pick(2) ? "In node " : "") + "upon " + condition +
            " the robot shall " + (pick(2) ? "immediately" : "within 2 ticks") + " satisfy " +
            response + "\n";
  }
  files["requirements.fret"] = reqs;
  const char* results[] = {R"(["success"])", R"(["failure"])", R"(["success", "failure"])"};
  auto action = [&](const std::string& effect) {
    return std::string("{\"ticks\": [1, ") + std::to_string(1 + pick(2)) +
           "], \"results\": " + results[pick(3)] + (pick(2) ? ", " + effect : "") + "}";
  };
  files["world.json"] = std::string("{\"initial\": \"") + (pick(2) ? "!c" : "c") +
                        "\", \"actions\": {\"Act1\": " + action("\"on_success\": \"c = true\"") +
                        ", \"Act2\": " + action("\"on_failure\": \"c = false\"") + "}}";
  return files;
}

TEST(CampaignGuarantees, RandomWorldsReachedTargetsAreReachedAndUnreachableOnesAreProved) {
  std::size_t reached = 0, unreachable = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    TempMission dir(random_world_mission(seed));
    const load::Mission m = load(dir.dir());
    const campaign::Campaign c = campaign::build_campaign(m, guarantees_only());
    const std::string label = "seed " + std::to_string(seed);
    ASSERT_TRUE(c.notes.empty()) << label << ": " << c.notes.front();
    ASSERT_FALSE(c.targets.empty()) << label;
    expect_scenarios_reach_their_goals(c, dir.dir(), dir.dir().parent_path(), label);
    // Every target said unreachable: the explicit engine proves its trap.
    const auto replayer = campaign::Replayer::compiling(m, {});
    const prove::WorldModel world = prove::mission_world(m);
    std::map<std::string, prove::Goal> goals;
    for (const auto& g : campaign::guarantee_goals(m)) goals[g.id] = g;
    prove::Options explicit_engine;
    explicit_engine.engine = "explicit";
    for (std::size_t k = 0; k < c.targets.size(); ++k) {
      const campaign::Target& t = c.targets[k];
      EXPECT_FALSE(t.undecided) << label << " " << t.id << ": " << t.reason;
      if (t.reachable) {
        ++reached;
        EXPECT_TRUE(c.covered[k]) << label << " " << t.id << "\n" << campaign::campaign_text(c);
        continue;
      }
      ++unreachable;
      const auto answer =
          prove::reach(m, replayer.document(), world, {goals.at(t.id)}, explicit_engine);
      EXPECT_EQ(answer.front().verdict, prove::Verdict::proved) << label << " " << t.id;
    }
    EXPECT_TRUE(c.passed()) << label << "\n" << campaign::campaign_text(c);
  }
  EXPECT_GT(reached, 20u);
  EXPECT_GT(unreachable, 3u);
}

// msl_curiosity + on_mud: the gate's campaign plays in world.json's world, so no replay shows a
// guarantee violation the proof rules out (TakePicture succeeding with nothing dug).
TEST(CampaignWorld, EveryScenarioOfTheGatesCampaignRunsWithoutAViolation) {
  TempMission scratch({});
  const auto out = scratch.dir() / "o";
  const std::string missions = (source_dir() / "missions").string();
  const CliRun gate = run_uabt_in(missions,
                                  "gate msl_curiosity --uplink "
                                  "msl_curiosity/uplinks/on_mud --out '" +
                                      out.string() + "'");
  ASSERT_TRUE(std::filesystem::exists(out / "tests")) << gate.out;
  std::size_t runs = 0;
  for (const auto& e : std::filesystem::directory_iterator(out / "tests")) {
    if (e.path().extension() != ".json" || e.path().filename() == "campaign.json") continue;
    ++runs;
    const CliRun run = run_uabt_in(
        missions, "run '" + (out / "merged").string() + "' --scenario '" + e.path().string() + "'");
    EXPECT_EQ(run.out.find("violated"), std::string::npos) << e.path().filename() << "\n"
                                                           << run.out;
    const auto j = nlohmann::json::parse(read_all(e.path()));
    EXPECT_TRUE(j.contains("actions")) << e.path().filename();
    EXPECT_EQ(j["initial"].value("IsDug", true), false) << e.path().filename();
  }
  EXPECT_GT(runs, 5u);
}

}  // namespace
}  // namespace uabt::testing
