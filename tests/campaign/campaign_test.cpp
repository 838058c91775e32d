// The test campaign (uabt tests) and what runs cover (uabt coverage): random small missions
// checked against brute force over their domain, and the shipped missions' exact output.
#include <gtest/gtest.h>

#include <array>

#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "base/files.hpp"
#include "campaign/campaign.hpp"
#include "cli/cli_support.hpp"
#include "fretish/expr.hpp"
#include "load/load_test_support.hpp"
#include "smt/atoms.hpp"
#include "smt/evaluate.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

using campaign::Criterion;

load::Mission load(const std::filesystem::path& dir) {
  return load_dir(dir);
}

// A random node over a, b (booleans), x in [0, 5], t in {p, q, r} and a real w in [0, 10]:
// two to four guarded requirements of one to three atoms, sometimes a default, sometimes an
// assumption; the tree ticks the node first.
std::map<std::string, std::string> random_mission(unsigned seed) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  auto atom = [&]() -> std::string {
    switch (pick(8)) {
      case 0: return "a";
      case 1: return "!b";
      case 2: return "x < " + std::to_string(pick(6));
      case 3: return "x = " + std::to_string(pick(6));
      case 4: return "x >= " + std::to_string(pick(6));
      case 5: return std::string("t = ") + "pqr"[pick(3)];
      case 6: return "w < " + std::to_string(pick(11));
      default: return "w >= " + std::to_string(pick(11)) + ".5";
    }
  };
  std::map<std::string, std::string> files;
  files["mission.xml"] =
      mission_with("    <Sequence>\n      <Adaptable ID=\"node\"/>\n    </Sequence>");
  files["domain.fret"] =
      "boolean a, b\ninteger x in [0, 5]\nenum t in {p, q, r}\nreal w in [0, 10]\n";
  if (pick(3) == 0) files["domain.fret"] += "assume no_ab: !(a & b)\n";
  std::string reqs;
  const int k = 2 + pick(3);
  for (int i = 0; i < k; ++i) {
    std::string guard = atom();
    for (int j = pick(3); j > 0; --j) guard += (pick(2) ? " & " : " | ") + atom();
    const std::string alt = "alt" + std::to_string(i);
    reqs += "R" + std::to_string(i) + ": In node if " + guard +
            " Mission shall satisfy selected_alt = " + alt + "\n";
    files["alternatives/node/" + alt + ".xml"] = alternative_tree(alt, "<AlwaysSuccess/>");
  }
  if (pick(2)) {
    reqs += "Default: In node Mission shall satisfy selected_alt = fallback\n";
    files["alternatives/node/fallback.xml"] = alternative_tree("fallback", "<AlwaysSuccess/>");
  }
  files["requirements.fret"] = reqs;
  return files;
}

// Every state of the random domain, the real at points on, between and beside the guards'
// boundaries (integers and halves cut [0, 10] finer than any guard does).
std::vector<State> brute_force(const load::Mission& m) {
  std::vector<State> out;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int x = 0; x <= 5; ++x)
        for (const char* t : {"p", "q", "r"})
          for (int w4 = 0; w4 <= 40; ++w4) {
            const double w = w4 / 4.0;
            State s{{"a", Value::of_bool(a)},
                    {"b", Value::of_bool(b)},
                    {"x", Value::of_int(x)},
                    {"t", Value::of_enum(t)},
                    {"w", Value::of_real(w, std::to_string(w))}};
            if (smt::satisfies_domain(m.domain, s)) out.push_back(std::move(s));
          }
  return out;
}

// What a state selects: the first requirement whose guard holds ("" in a gap).
std::string selects(const load::Mission& m, const State& s) {
  for (const auto* r : m.selections_for("node"))
    if (!r->guard || smt::evaluate(*r->guard, m.domain, s)) return r->alternative;
  return "";
}

State initial_of(const std::string& scenario) {
  State s;
  const auto j = nlohmann::json::parse(scenario);
  for (const auto& [name, v] : j["initial"].items()) {
    if (v.is_boolean())
      s.emplace_back(name, Value::of_bool(v.get<bool>()));
    else if (v.is_string())
      s.emplace_back(name, Value::of_enum(v.get<std::string>()));
    else if (name == "x")
      s.emplace_back(name, Value::of_int(v.get<std::int64_t>()));
    else
      s.emplace_back(name, Value::of_real(v.get<double>(), v.dump()));
  }
  return s;
}

constexpr unsigned kRandomMissions = 40;

campaign::Options only(Criterion criterion) {
  campaign::Options options;
  options.criteria = {criterion};
  return options;
}

TEST(CampaignRandom, EveryScenarioReachesItsTargetWhenRun) {
  for (unsigned seed = 1; seed <= kRandomMissions; ++seed) {
    TempMission dir(random_mission(seed));
    const load::Mission m = load(dir.dir());
    const campaign::Campaign c = campaign::build_campaign(m, {});
    const campaign::Replayer replayer(m, {});
    for (const auto& s : c.scenarios) {
      EXPECT_TRUE(s.problems.empty()) << "seed " << seed << " " << s.name;
      // Run again from its bytes, as `uabt run` reads the file.
      const campaign::RunRecord run = replayer.run(s.json, s.name + ".json");
      ASSERT_FALSE(run.observations.empty()) << "seed " << seed << " " << s.name;
      const State planned = initial_of(s.json);
      EXPECT_EQ(run.observations.front().alternative, selects(m, planned))
          << "seed " << seed << " " << s.name << "\n"
          << s.json;
    }
    EXPECT_TRUE(c.passed()) << "seed " << seed << "\n" << campaign::campaign_text(c);
  }
}

TEST(CampaignRandom, EveryReachableDecisionTargetIsCoveredAndOnlyThose) {
  for (unsigned seed = 1; seed <= kRandomMissions; ++seed) {
    TempMission dir(random_mission(seed));
    const load::Mission m = load(dir.dir());
    const campaign::Campaign c = campaign::build_campaign(m, {});
    std::set<std::string> can;  // decision target ids some state of the domain reaches
    for (const State& s : brute_force(m)) {
      const std::string alt = selects(m, s);
      if (!alt.empty()) can.insert("node/decision/select/" + alt);
      for (const auto* r : m.selections_for("node"))
        if (r->guard)
          can.insert("node/decision/guard/" + r->id + "/" +
                     (smt::evaluate(*r->guard, m.domain, s) ? "true" : "false"));
    }
    for (std::size_t k = 0; k < c.targets.size(); ++k) {
      const auto& t = c.targets[k];
      if (t.criterion != Criterion::decision) continue;
      EXPECT_EQ(t.reachable, can.count(t.id) > 0)
          << "seed " << seed << " " << t.id << ": " << t.reason;
      if (t.reachable) {
        EXPECT_TRUE(c.covered[k]) << "seed " << seed << " " << t.id;
      }
    }
  }
}

TEST(CampaignRandom, McdcPairsDifferInExactlyOneAtom) {
  std::size_t pairs = 0;
  for (unsigned seed = 1; seed <= kRandomMissions; ++seed) {
    TempMission dir(random_mission(seed));
    const load::Mission m = load(dir.dir());
    const campaign::Campaign c = campaign::build_campaign(m, only(Criterion::mcdc));
    const auto domain = brute_force(m);
    for (std::size_t k = 0; k < c.targets.size(); ++k) {
      const auto& t = c.targets[k];
      if (!t.reachable) continue;
      ASSERT_TRUE(c.covered[k]) << t.id;
      // The pair as written: the two scenarios the target was planned in.
      std::vector<State> states;
      for (const auto& s : c.scenarios)
        if (std::find(s.purpose.begin(), s.purpose.end(), k) != s.purpose.end())
          states.push_back(initial_of(s.json));
      ASSERT_EQ(states.size(), 2u) << t.id;
      const std::string requirement = t.id.substr(10, t.id.find('/', 10) - 10);
      const std::string atom_text = t.id.substr(t.id.find('/', 10) + 1);
      // Atoms that hold in the same states (or the opposite ones) are one condition.
      auto same_condition = [&](const fretish::Expr& a, const fretish::Expr& b) {
        bool equal = true, opposite = true;
        for (const State& s : domain) {
          const bool x = smt::evaluate(a, m.domain, s), y = smt::evaluate(b, m.domain, s);
          equal = equal && x == y;
          opposite = opposite && x != y;
        }
        return equal || opposite;
      };
      const fretish::Expr* target_atom = nullptr;
      std::vector<const fretish::Expr*> atoms;
      smt::Typing typing;
      for (const auto* r : m.selections_for("node")) {
        if (!r->guard) continue;
        std::vector<Finding> ignored;
        smt::check_condition(*r->guard, m.domain, r->guard_location, typing, ignored);
        for (const auto* a : smt::atom_occurrences(*r->guard, typing)) {
          atoms.push_back(a);
          if (r->id == requirement && fretish::to_fretish(*a) == atom_text) target_atom = a;
        }
      }
      ASSERT_NE(target_atom, nullptr) << t.id;
      EXPECT_NE(smt::evaluate(*target_atom, m.domain, states[0]),
                smt::evaluate(*target_atom, m.domain, states[1]))
          << t.id;
      for (const auto* a : atoms) {
        if (smt::evaluate(*a, m.domain, states[0]) == smt::evaluate(*a, m.domain, states[1]))
          continue;
        EXPECT_TRUE(same_condition(*a, *target_atom))
            << "seed " << seed << " " << t.id << ": " << fretish::to_fretish(*a) << " changes too";
      }
      EXPECT_NE(selects(m, states[0]), selects(m, states[1])) << t.id;
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 20u);  // the random missions do exercise MC/DC
}

std::string run_tests_command(const std::string& mission, const std::filesystem::path& out,
                              int& exit_code) {
  const CliRun run = run_uabt_in((source_dir() / "missions").string(),
                                 "tests " + mission + " --out '" + out.string() + "'");
  exit_code = run.exit_code;
  return run.out;
}

// `uabt tests` of msl_curiosity with the on_mud uplink merged, written to `out`.
CliRun run_on_mud_tests(const std::filesystem::path& out) {
  return run_uabt_in(
      (source_dir() / "missions").string(),
      "tests msl_curiosity --uplink msl_curiosity/uplinks/on_mud --out '" + out.string() + "'");
}

TEST(CampaignCli, MslCuriosityGolden) {
  TempMission scratch({});
  const auto out = scratch.dir() / "campaign";
  int exit_code = -1;
  const std::string text = run_tests_command("msl_curiosity", out, exit_code);
  EXPECT_EQ(exit_code, 0) << text;
  const auto golden = source_dir() / "tests/campaign/golden";
  EXPECT_EQ(text, read_all(golden / "msl_curiosity.txt"));
  EXPECT_EQ(read_all(out / "campaign.json"), read_all(golden / "msl_curiosity_campaign.json"));
  EXPECT_EQ(read_all(out / "navigation-02.json"),
            read_all(golden / "msl_curiosity_navigation-02.json"));
  EXPECT_EQ(read_all(out / "junit.xml"), read_all(golden / "msl_curiosity_junit.xml"));
}

TEST(CampaignCli, SameInputSameBytes) {
  TempMission scratch({});
  int code1 = -1, code2 = -1;
  run_tests_command("planetary_landing", scratch.dir() / "one", code1);
  run_tests_command("planetary_landing", scratch.dir() / "two", code2);
  EXPECT_EQ(code1, 0);
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(scratch.dir() / "one")) {
    ++files;
    EXPECT_EQ(read_all(e.path()), read_all(scratch.dir() / "two" / e.path().filename()))
        << e.path().filename();
  }
  EXPECT_GT(files, 3u);
}

TEST(CampaignTargets, ComplementaryAtomsAreOneConditionForMcdc) {
  // `wind < 15` and `wind >= 15` (Nominal, Hover) change together: that is still changing
  // one condition alone, so every MC/DC target of planetary_landing is testable.
  const load::Mission m = load(mission_dir("planetary_landing"));
  const campaign::Campaign c = campaign::build_campaign(m, {});
  std::size_t mcdc = 0;
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    EXPECT_TRUE(c.targets[k].reachable) << c.targets[k].id << ": " << c.targets[k].reason;
    EXPECT_TRUE(c.covered[k]) << c.targets[k].id;
    mcdc += c.targets[k].criterion == Criterion::mcdc ? 1 : 0;
  }
  EXPECT_EQ(mcdc, 9u);
}

TEST(CampaignTargets, BoundariesOfRealsAndIntegers) {
  const load::Mission m = load(mission_dir("planetary_landing"));
  const campaign::Model model(m, {Criterion::boundary});
  std::map<std::string, std::string> witness;
  for (const auto& t : model.targets())
    if (t.reachable) witness[t.id] = campaign::state_json(t.witness.front());
  // wind < 15 / wind >= 15: one scenario on the point boundary, one on each side.
  EXPECT_EQ(witness.at("landing/boundary/wind/15/at"),
            R"({"wind":15,"battery":0,"terrain":"flat"})");
  EXPECT_EQ(witness.at("landing/boundary/wind/15/below"),
            R"({"wind":1,"battery":0,"terrain":"flat"})");
  EXPECT_EQ(witness.at("landing/boundary/wind/15/above"),
            R"({"wind":16,"battery":0,"terrain":"flat"})");
  // battery > 10 / battery <= 10: the last value on each side.
  EXPECT_EQ(witness.at("landing/boundary/battery/10|11/below"),
            R"({"wind":0,"battery":10,"terrain":"flat"})");
  EXPECT_EQ(witness.at("landing/boundary/battery/10|11/above"),
            R"({"wind":0,"battery":11,"terrain":"flat"})");
  EXPECT_EQ(witness.size(), 5u);
}

TEST(CampaignTargets, StatesTheTreeNeverTicksTheNodeInAreNotReached) {
  // The node is ticked only when x >= 2, so R1 (x < 1) is selected by no run.
  TempMission dir({{"mission.xml", mission_with("    <Fallback>\n"
                                                "      <ScriptCondition code=\"x &lt; 2\"/>\n"
                                                "      <Adaptable ID=\"node\"/>\n"
                                                "    </Fallback>")},
                   {"domain.fret", "integer x in [0, 5]\n"},
                   {"requirements.fret",
                    "R1: In node if x < 1 Mission shall satisfy selected_alt = low\n"
                    "Other: In node Mission shall satisfy selected_alt = other\n"},
                   {"alternatives/node/low.xml", alternative_tree("low", "<AlwaysSuccess/>")},
                   {"alternatives/node/other.xml", alternative_tree("other", "<AlwaysSuccess/>")}});
  const load::Mission m = load(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, only(Criterion::decision));
  std::map<std::string, const campaign::Target*> by_id;
  for (const auto& t : c.targets) by_id[t.id] = &t;
  const campaign::Target& low = *by_id.at("node/decision/select/low");
  EXPECT_FALSE(low.reachable);
  EXPECT_EQ(low.reason,
            "no run reaches it: in the 2 states tried for it, node is not ticked (1 tick, verdict "
            "success)");
  EXPECT_TRUE(by_id.at("node/decision/select/other")->reachable);
  EXPECT_TRUE(c.passed());
  for (const auto& s : c.scenarios) EXPECT_TRUE(s.problems.empty()) << s.name;
}

TEST(CampaignCoverage, ScenariosAndMonitorTraces) {
  const auto missions = (source_dir() / "missions").string();
  const CliRun run = run_uabt_in(missions,
                                 "coverage msl_curiosity "
                                 "msl_curiosity/scenarios/dusty_start.json");
  EXPECT_EQ(run.exit_code, 1);
  // The decision and MC/DC targets; the guarantee targets' lines follow
  // (CampaignCoverage.GuaranteeTargetsMissedEachGetTheCampaignsScenario).
  EXPECT_EQ(run.out.substr(0, run.out.find("missed: the trigger of HoldOnUnknown")),
            "msl_curiosity: 1 run covers 8 of 19 reachable targets (decision 7, MC/DC 2, "
            "guarantee 12; 2 unreachable)\n"
            "  msl_curiosity/scenarios/dusty_start.json: 1 observation in 58 ticks\n"
            "  navigation: 1 of 3 states visited, 33.3% (1/3) of the space\n"
            "missed: navigation selects on_rocks (Req2); covered by initial "
            "{\"OnDust\":false,\"OnRocks\":true}\n"
            "missed: navigation selects hold_position (Safe); covered by initial "
            "{\"OnDust\":false,\"OnRocks\":false}\n"
            "missed: the guard of Req1 (OnDust) is false; covered by initial "
            "{\"OnDust\":false,\"OnRocks\":false}\n"
            "missed: the guard of Req2 (OnRocks) is true; covered by initial "
            "{\"OnDust\":false,\"OnRocks\":true}\n"
            "missed: MC/DC of OnDust in Req1: changing it alone changes the guard and the "
            "selected alternative; covered by initial {\"OnDust\":false,\"OnRocks\":false} and "
            "{\"OnDust\":true,\"OnRocks\":false}\n"
            "missed: MC/DC of OnRocks in Req2: changing it alone changes the guard and the "
            "selected alternative; covered by initial {\"OnDust\":false,\"OnRocks\":false} and "
            "{\"OnDust\":false,\"OnRocks\":true}\n");
  // A monitor trace: every tick's state counts; terrain changes mid-drive.
  TempMission scratch({});
  const auto trace = scratch.dir() / "trace.jsonl";
  const CliRun recorded =
      run_uabt_in(missions,
                  "run msl_curiosity --scenario msl_curiosity/scenarios/rocks_mid_drive.json "
                  "--monitor-trace '" +
                      trace.string() + "'");
  ASSERT_TRUE(std::filesystem::exists(trace)) << recorded.out;
  const CliRun traced =
      run_uabt_in(missions, "coverage msl_curiosity '" + trace.string() + "' --format json");
  const auto j = nlohmann::json::parse(traced.out);
  EXPECT_EQ(j["summary"]["covered"], 12);
  EXPECT_EQ(j["summary"]["reachable"], 19);
  for (const auto& t : j["targets"])
    if (t["id"] == "navigation/decision/select/on_rocks") {
      EXPECT_EQ(t["covered"], true);
    }
}

TEST(CampaignCli, JunitHasOneTestcasePerScenario) {
  TempMission scratch({});
  int exit_code = -1;
  run_tests_command("planetary_landing", scratch.dir(), exit_code);
  const std::string junit = read_all(scratch.dir() / "junit.xml");
  std::size_t cases = 0, scenarios = 0;
  for (std::size_t at = junit.find("<testcase"); at != std::string::npos;
       at = junit.find("<testcase", at + 1))
    ++cases;
  for (const auto& e : std::filesystem::directory_iterator(scratch.dir()))
    if (e.path().filename().string().starts_with("landing-")) ++scenarios;
  EXPECT_EQ(cases, scenarios);
  EXPECT_EQ(scenarios, 9u);
  EXPECT_NE(junit.find("tests=\"9\" failures=\"0\""), std::string::npos) << junit;
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

TEST(CampaignCoverage, AScenarioThatDoesNotFitTheMissionIsRefusedWithItsPosition) {
  TempMission scratch(
      std::map<std::string, std::string>{{"bad.json", "{\"initial\": {\"OnDust\": 3}}\n"}});
  const CliRun run =
      run_uabt_in((source_dir() / "missions").string(),
                  "coverage msl_curiosity '" + (scratch.dir() / "bad.json").string() + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, (scratch.dir() / "bad.json").string() +
                         ":1:24: error: OnDust = 3 is not a boolean (true or false) (declared "
                         "boolean at domain.fret:2:9)\n");
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

TEST(CampaignCoverage, AFolderFromUabtTestsIsReadAsItsScenariosWithoutItsSummary) {
  TempMission scratch({});
  const auto out = scratch.dir() / "campaign";
  int exit_code = -1;
  run_tests_command("msl_curiosity", out, exit_code);
  ASSERT_EQ(exit_code, 0);
  const std::string missions = (source_dir() / "missions").string();
  const CliRun folder = run_uabt_in(missions, "coverage msl_curiosity '" + out.string() + "'");
  EXPECT_EQ(folder.exit_code, 0) << folder.out;
  EXPECT_NE(folder.out.find("6 runs cover 19 of 19 reachable targets (decision 7, MC/DC 2, "
                            "guarantee 12; 2 unreachable)"),
            std::string::npos)
      << folder.out;
  // What a shell glob over the folder gives: the summary is named, not read as a scenario.
  const CliRun summary =
      run_uabt_in(missions, "coverage msl_curiosity '" + (out / "navigation-01.json").string() +
                                "' '" + (out / "campaign.json").string() + "'");
  EXPECT_EQ(summary.exit_code, 1);
  EXPECT_EQ(summary.out, (out / "campaign.json").string() +
                             ": error: this is the summary `uabt tests` writes beside its "
                             "scenarios, not a scenario: name the scenarios or their folder\n");
  std::filesystem::create_directories(scratch.dir() / "empty");
  const CliRun empty =
      run_uabt_in(missions, "coverage msl_curiosity '" + (scratch.dir() / "empty").string() + "'");
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.out.find("no scenario (.json) or monitor trace (.jsonl) in this folder"),
            std::string::npos)
      << empty.out;
}

TEST(CampaignCli, ANodeTooLargeToEnumerateIsNamedAndGetsNoTargets) {
  // 26 booleans: more states than the campaign enumerates; it says so rather than hanging.
  std::string domain = "boolean b0";
  std::string requirements;
  for (int i = 1; i < 26; ++i) domain += ", b" + std::to_string(i);
  for (int i = 0; i < 13; ++i)
    requirements += "R" + std::to_string(i) + ": In node if b" + std::to_string(2 * i) + " & !b" +
                    std::to_string(2 * i + 1) + " Mission shall satisfy selected_alt = a" +
                    std::to_string(i) + "\n";
  requirements += "Default: In node Mission shall satisfy selected_alt = fallback\n";
  std::map<std::string, std::string> files = {
      {"mission.xml", mission_with("    <Adaptable ID=\"node\" policy=\"first\"/>")},
      {"domain.fret", domain + "\n"},
      {"requirements.fret", requirements},
      {"alternatives/node/fallback.xml", alternative_tree("fallback", "<AlwaysSuccess/>")}};
  for (int i = 0; i < 13; ++i)
    files["alternatives/node/a" + std::to_string(i) + ".xml"] =
        alternative_tree("a" + std::to_string(i), "<AlwaysSuccess/>");
  TempMission m(files);
  const CliRun run = run_uabt_in(m.dir().string(), "tests . --out campaign");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find(": 0 targets, 0 unreachable; 0 scenarios cover 0 of 0 reachable targets\n"
                         "no targets for node: the guards range over more than 2^24 states\n"),
            std::string::npos)
      << run.out;
}

TEST(CampaignCli, ARunThatStopsOnATickErrorNamesTheLineOfTheMission) {
  // blackboard_defects reads target_range before anything writes it: no run reaches sampling.
  TempMission scratch({});
  const CliRun run = run_uabt_in(
      (source_dir() / "missions").string(),
      "tests blackboard_defects --criterion decision --out '" + scratch.dir().string() + "'");
  EXPECT_NE(run.out.find("unreachable: sampling selects scoop (Sand): no run reaches it: in the 2 "
                         "states tried for it, sampling is not ticked (1 tick, verdict error: "
                         "blackboard_defects/mission.xml:14:7: ScriptCondition 'in_reach': "
                         "undefined blackboard key 'target_range'"),
            std::string::npos)
      << run.out;
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

TEST(CampaignCli, AnUplinkGetsAScenarioPerBehaviourChangeAsTheGateWritesIt) {
  TempMission scratch({});
  const auto out = scratch.dir() / "d";
  const std::string missions = (source_dir() / "missions").string();
  const CliRun tests = run_on_mud_tests(out);
  EXPECT_EQ(tests.exit_code, 0) << tests.out;
  EXPECT_NE(tests.out.find("  navigation-change-01.json: behaviour change: node navigation moves "
                           "from hold_position to on_mud, reached at tick 1\n"),
            std::string::npos)
      << tests.out;
  const std::string change = read_all(out / "navigation-change-01.json");
  EXPECT_NE(change.find("\"description\": \"Test campaign: behaviour change: node navigation "
                        "moves from hold_position to on_mud\""),
            std::string::npos)
      << change;
  EXPECT_NE(read_all(out / "campaign.json").find("\"behaviour_change_scenarios\": 1"),
            std::string::npos);
  // The gate's campaign of the same uplink is the same, file for file.
  const auto gated = scratch.dir() / "g";
  const CliRun gate =
      run_uabt_in(missions, "gate msl_curiosity --uplink msl_curiosity/uplinks/on_mud --out '" +
                                gated.string() + "'");
  ASSERT_EQ(gate.exit_code, 0) << gate.out;
  for (const auto& e : std::filesystem::directory_iterator(gated / "tests"))
    EXPECT_EQ(read_all(e.path()), read_all(out / e.path().filename())) << e.path().filename();
  // Replayed on the merged mission, the scenario selects the uplink's new alternative.
  const CliRun run =
      run_uabt_in(missions, "run '" + (gated / "merged").string() + "' --scenario '" +
                                (out / "navigation-change-01.json").string() + "'");
  EXPECT_EQ(run.out.find("tick 1: navigation selects "),
            run.out.find("tick 1: navigation selects on_mud (Req3)"))
      << run.out;
  EXPECT_NE(run.out.find("tick 1: navigation selects on_mud (Req3)"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

std::string record_text(const campaign::RunRecord& r) {
  std::string out =
      r.source + " | " + r.verdict + " | " + r.error + " | " + std::to_string(r.ticks) + "\n";
  for (const auto& o : r.observations)
    out += "  " + o.adaptable + " " + o.alternative + " at " + std::to_string(o.tick) + " in " +
           campaign::state_json(o.state) + "\n";
  return out;
}

TEST(CampaignReplay, OneTreeResetBetweenRunsRunsExactlyAsAFreshTree) {
  const load::Mission m = load(mission_dir("msl_curiosity"));
  const campaign::Campaign c = campaign::build_campaign(m, {});
  const auto scenarios = mission_dir("msl_curiosity") / "scenarios";
  struct Run {
    std::string json, file;
    std::set<std::string> stop_after;
  };
  std::vector<Run> runs;
  // Stopped once navigation selected, with its drive still RUNNING: the next run must not see
  // the actions, counters or blackboard it left.
  runs.push_back({read_all(scenarios / "dusty_start.json"), "dusty_start.json", {"navigation"}});
  for (const auto& s : c.scenarios) runs.push_back({s.json, s.name + ".json", {}});
  for (const char* name : {"rocks_mid_drive.json", "short_drive.json", "dusty_start.json"})
    runs.push_back({read_all(scenarios / name), name, {}});
  runs.push_back({read_all(scenarios / "rocks_mid_drive.json"), "again.json", {"navigation"}});
  runs.push_back({c.scenarios.front().json, "first-again.json", {}});

  const campaign::Replayer shared(m, {});
  std::size_t left_running = 0;
  for (const auto& r : runs) {
    const campaign::RunRecord reused = shared.run(r.json, r.file, r.stop_after);
    const campaign::Replayer fresh_tree(m, {});
    const campaign::RunRecord fresh = fresh_tree.run(r.json, r.file, r.stop_after);
    EXPECT_EQ(record_text(reused), record_text(fresh));
    EXPECT_FALSE(fresh.observations.empty()) << r.file;
    if (!r.stop_after.empty()) left_running += fresh.verdict == "timeout" ? 1 : 0;
  }
  EXPECT_EQ(left_running, 2u);  // the two runs stopped mid-drive, with the root RUNNING
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

std::string landing_scenario(const std::string& wind) {
  return "{\"max_ticks\": 5, \"initial\": {\"wind\": " + wind +
         ", \"battery\": 50, \"terrain\": \"flat\"}}\n";
}

TEST(CampaignCoverage, VisitedCellsHoldTheirExactShareOfTheSpace) {
  // planetary_landing: wind real in [0, 40] cut at 15, battery integer in [0, 100], terrain one
  // of 4. Runs at wind 5, 15 and 20 (battery 50, flat) visit the cells (0, 15) and (15, 40),
  // of lengths 15 and 25, and the point 15, of measure 0.
  TempMission scratch({{"below.json", landing_scenario("5")},
                       {"at.json", landing_scenario("15")},
                       {"above.json", landing_scenario("20")}});
  const long long whole = 40 * 101 * 4, visited = 15 + 25;
  const long long g = std::gcd(visited, whole);
  const std::string share = std::to_string(visited / g) + "/" + std::to_string(whole / g);
  EXPECT_EQ(share, "1/404");
  const std::string runs = "'" + (scratch.dir() / "below.json").string() + "' '" +
                           (scratch.dir() / "at.json").string() + "' '" +
                           (scratch.dir() / "above.json").string() + "'";
  const std::string missions = (source_dir() / "missions").string();
  const CliRun json =
      run_uabt_in(missions, "coverage planetary_landing " + runs + " --format json");
  const auto j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["visits"].size(), 1u) << json.out;
  const auto& v = j["visits"][0];
  EXPECT_EQ(v["adaptable"], "landing");
  EXPECT_EQ(v["counted"], false);
  EXPECT_EQ(v["cells"], 5 * 101 * 4);  // wind: 0, (0, 15), 15, (15, 40), 40
  EXPECT_EQ(v["visited_cells"], 3);
  EXPECT_EQ(v["visited_share_exact"], share);
  EXPECT_EQ(v["visited_boundary_cells"], 1);
  EXPECT_EQ(v["visited_boundary"], "a boundary point");
  std::map<std::string, nlohmann::json> targets;
  for (const auto& t : j["targets"]) targets[t["id"]] = t;
  // Every state with wind in (0, 15): 15 of the 40 of wind; the runs visited 15 of 16160.
  EXPECT_EQ(targets["landing/boundary/wind/15/below"]["share_exact"], "3/8");
  EXPECT_EQ(targets["landing/boundary/wind/15/below"]["visited_share_exact"], "3/3232");
  EXPECT_EQ(targets["landing/boundary/wind/15/at"]["share_exact"], "0");
  EXPECT_EQ(targets["landing/boundary/wind/15/at"]["visited_cells"], 1);
  EXPECT_EQ(targets["landing/boundary/wind/15/at"]["visited_boundary_cells"], 1);
  EXPECT_FALSE(targets["landing/mcdc/Nominal/wind < 15"].contains("share"));

  const CliRun text = run_uabt_in(missions, "coverage planetary_landing " + runs);
  EXPECT_NE(text.out.find("  landing: 3 of 2020 cells visited, 0.2% (1/404) of the space; 1 of "
                          "the cells on a boundary: 0% of the space (a boundary point)\n"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("visited: wind = 15, on the boundary: 0% of the space (a boundary "
                          "point)\n"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("visited: wind in (0, 15), just below the boundary 15: 0.1% (3/3232) "
                          "of the space\n"),
            std::string::npos)
      << text.out;
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

// The guarantee targets (and their ids) that `uabt coverage --format json` reports missed.
std::vector<std::string> missed_guarantees(const nlohmann::json& report) {
  std::vector<std::string> out;
  for (const auto& t : report["targets"])
    if (t["criterion"] == "guarantee" && t["reachable"] == true && t["covered"] == false)
      out.push_back(t["id"]);
  return out;
}

TEST(CampaignCoverage, AnUplinkCampaignIsReadBackWithTheSameUplink) {
  TempMission scratch({});
  const auto out = scratch.dir() / "campaign";
  const std::string missions = (source_dir() / "missions").string();
  const CliRun tests = run_on_mud_tests(out);
  ASSERT_EQ(tests.exit_code, 0) << tests.out;
  const CliRun run =
      run_uabt_in(missions, "coverage msl_curiosity --uplink msl_curiosity/uplinks/on_mud '" +
                                out.string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(run.out.substr(0, run.out.find('\n')),
            "msl_curiosity: 9 runs cover 25 of 25 reachable targets (decision 10, MC/DC 3, "
            "guarantee 14; 2 unreachable)")
      << run.out;
}

TEST(CampaignCoverage, TheCampaignFolderCoversEveryReachableGuaranteeTarget) {
  TempMission scratch({});
  const auto out = scratch.dir() / "campaign";
  int exit_code = -1;
  run_tests_command("msl_curiosity", out, exit_code);
  ASSERT_EQ(exit_code, 0);
  const CliRun run = run_uabt_in((source_dir() / "missions").string(),
                                 "coverage msl_curiosity '" + out.string() + "' --format json");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  const auto j = nlohmann::json::parse(run.out);
  std::size_t guarantee = 0, reachable = 0, covered = 0;
  for (const auto& t : j["targets"]) {
    if (t["criterion"] != "guarantee") continue;
    ++guarantee;
    reachable += t["reachable"] == true;
    covered += t["covered"] == true;
  }
  EXPECT_EQ(guarantee, 12u);
  EXPECT_EQ(reachable, 10u);
  EXPECT_EQ(covered, 10u);
  EXPECT_EQ(j["summary"]["covered"], 19);
  EXPECT_EQ(j["summary"]["not_judged"], 0);
}

TEST(CampaignCoverage, GuaranteeTargetsMissedEachGetTheCampaignsScenario) {
  const std::string missions = (source_dir() / "missions").string();
  const CliRun run = run_uabt_in(
      missions, "coverage msl_curiosity msl_curiosity/scenarios/dusty_start.json --format json");
  EXPECT_EQ(run.exit_code, 1);
  const auto j = nlohmann::json::parse(run.out);
  EXPECT_EQ(missed_guarantees(j),
            (std::vector<std::string>{
                "guarantee/HoldOnUnknown/trigger", "guarantee/HoldOnUnknown/condition/OnDust/false",
                "guarantee/HoldOnUnknown/condition/OnRocks/true",
                "guarantee/HoldOnUnknown/condition/OnRocks/false",
                "guarantee/HoldOnUnknown/response/navigation.selected = hold_position/true"}));
  // Each with the scenario that covers it; given to coverage, that scenario does.
  TempMission scratch({});
  for (const auto& t : j["targets"]) {
    if (t["criterion"] != "guarantee" || t["covered"] == true || t["reachable"] == false) continue;
    ASSERT_TRUE(t.contains("scenario")) << t.dump();
    const auto file = scratch.dir() / "suggested.json";
    write_file_atomically(file, t["scenario"].dump(2) + "\n");
    const CliRun again =
        run_uabt_in(missions, "coverage msl_curiosity '" + file.string() + "' --format json");
    bool covers = false;
    const auto report = nlohmann::json::parse(again.out);
    for (const auto& u : report["targets"])
      if (u["id"] == t["id"]) covers = u["covered"] == true;
    EXPECT_TRUE(covers) << t["id"];
  }
  // In text: the scenario on one line, without its description.
  const CliRun text =
      run_uabt_in(missions, "coverage msl_curiosity msl_curiosity/scenarios/dusty_start.json");
  EXPECT_NE(
      text.out.find(
          "missed: the trigger of HoldOnUnknown fires (in navigation, upon !OnDust & "
          "!OnRocks); covered by the scenario {\"max_ticks\":1,\"initial\":{\"IsInLocation\":"
          "false,\"IsDug\":false,\"IsPictureTaken\":false,\"OnDust\":false,\"OnRocks\":false},"
          "\"actions\":{"),
      std::string::npos)
      << text.out;
}

TEST(CampaignCoverage, AMonitorTraceWithoutWhatATrapReadsDoesNotJudgeIt) {
  TempMission scratch({});
  const std::string missions = (source_dir() / "missions").string();
  const auto trace = scratch.dir() / "trace.jsonl";
  run_uabt_in(missions,
              "run msl_curiosity --scenario msl_curiosity/scenarios/rocks_mid_drive.json "
              "--monitor-trace '" +
                  trace.string() + "'");
  ASSERT_TRUE(std::filesystem::exists(trace));
  // The same trace without drive.running, which ArmClosed's response reads.
  std::string lines, line;
  std::istringstream in(read_all(trace));
  while (std::getline(in, line)) {
    auto j = nlohmann::ordered_json::parse(line);
    if (j.contains("state")) j["state"].erase("drive.running");
    lines += j.dump() + "\n";
  }
  const auto lacking = scratch.dir() / "lacking.jsonl";
  write_file_atomically(lacking, lines);
  const CliRun run = run_uabt_in(missions, "coverage msl_curiosity '" + lacking.string() + "'");
  EXPECT_EQ(run.out.substr(0, run.out.find('\n')),
            "msl_curiosity: 1 run covers 11 of 19 reachable targets (decision 7, MC/DC 2, "
            "guarantee 12; 2 unreachable, 1 not judged)");
  EXPECT_NE(run.out.find("not judged: drive.running is false and decides the response of "
                         "ArmClosed (at a tick from its trigger until CloseToolArm.success, "
                         "while it held before): " +
                         lacking.string() + ": the trace lacks drive.running\n"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("missed: drive.running"), std::string::npos) << run.out;
}

// ArmClosed (`until`): its response's atoms decide at the ticks from the arm opening until it
// closes (FRET's until includes the trigger's tick, not the stop's), not at any tick where
// OpenToolArm.success holds.
TEST(CampaignCoverage, ArmClosedsResponseAtomsDecideFromTheArmOpeningUntilItCloses) {
  TempMission scratch({});
  const std::string missions = (source_dir() / "missions").string();
  // Per tick: OpenToolArm.success, CloseToolArm.success, drive.running.
  auto covered = [&](const std::string& name, const std::vector<std::array<bool, 3>>& ticks) {
    std::string lines;
    for (std::size_t t = 0; t < ticks.size(); ++t)
      lines += nlohmann::ordered_json{{"tick", t + 1},
                                      {"state",
                                       {{"OpenToolArm.success", ticks[t][0]},
                                        {"CloseToolArm.success", ticks[t][1]},
                                        {"drive.running", ticks[t][2]}}}}
                   .dump() +
               "\n";
    const auto file = scratch.dir() / name;
    write_file_atomically(file, lines);
    const CliRun run =
        run_uabt_in(missions, "coverage msl_curiosity '" + file.string() + "' --format json");
    std::map<std::string, bool> out;
    const auto report = nlohmann::json::parse(run.out);
    for (const auto& t : report["targets"]) {
      const std::string id = t["id"].get<std::string>();
      if (id.starts_with("guarantee/ArmClosed/response/")) out[id.substr(29)] = t["covered"];
    }
    return out;
  };
  // The arm opens at tick 1 with no drive, a drive runs at tick 2, the arm closes at tick 3:
  // drive.running decides the response at ticks 1 and 2 (true at tick 2, after the trigger).
  const auto window = covered(
      "window.jsonl", {{{true, false, false}}, {{false, false, true}}, {{false, true, false}}});
  EXPECT_TRUE(window.at("drive.running/false"));
  EXPECT_TRUE(window.at("drive.running/true"));
  // The arm closes at the tick it opens: the response is due at no tick.
  const auto closed = covered("closed.jsonl", {{{true, true, false}}, {{false, false, true}}});
  EXPECT_FALSE(closed.at("drive.running/false"));
  EXPECT_FALSE(closed.at("drive.running/true"));
  // After a drive ran in the window the response is decided already: a later tick is not.
  const auto decided = covered("decided.jsonl", {{{true, false, true}}, {{false, false, false}}});
  EXPECT_TRUE(decided.at("drive.running/true"));
  EXPECT_FALSE(decided.at("drive.running/false"));
}

}  // namespace
}  // namespace uabt::testing
