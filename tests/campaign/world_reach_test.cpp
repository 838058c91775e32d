// The campaign searches for its selection targets with the world model `uabt prove` explores:
// an action without a world.json contract may fail, so a node behind it in a Fallback is
// reached; a target is unreachable only where prove shows no run gets there.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "campaign/campaign.hpp"
#include "campaign/world_reach.hpp"
#include "cli/cli_support.hpp"
#include "load/load_test_support.hpp"
#include "prove/reach.hpp"
#include "prove/world_model.hpp"
#include "temp_mission.hpp"

namespace uabt::testing {
namespace {

using campaign::Criterion;

// The node sits behind an action in a Fallback: it is ticked only in a run where AtDock fails.
// No nodes.xml and no world.json.
std::map<std::string, std::string> behind_fallback(const std::string& domain,
                                                   const std::string& requirements) {
  std::map<std::string, std::string> files{
      {"mission.xml", mission_with("    <Sequence name=\"main\">\n"
                                   "      <Fallback>\n"
                                   "        <AtDock/>\n"
                                   "        <Adaptable ID=\"drive\"/>\n"
                                   "      </Fallback>\n"
                                   "      <Collect/>\n"
                                   "    </Sequence>")},
      {"domain.fret", domain},
      {"requirements.fret", requirements},
      {"alternatives/drive/slow.xml", alternative_tree("slow", "<AlwaysSuccess/>")},
      {"alternatives/drive/careful.xml", alternative_tree("careful", "<AlwaysSuccess/>")},
      {"alternatives/drive/fast.xml", alternative_tree("fast", "<AlwaysSuccess/>")}};
  if (requirements.find("crawl") != std::string::npos)
    files["alternatives/drive/crawl.xml"] = alternative_tree("crawl", "<AlwaysSuccess/>");
  return files;
}

const char* kEnumRequirements =
    "R1: In drive if ground = ice Mission shall satisfy selected_alt = slow\n"
    "R2: In drive if ground = regolith Mission shall satisfy selected_alt = careful\n"
    "R3: In drive if ground = basalt Mission shall satisfy selected_alt = fast\n";

// Each enum atom's MC/DC target: no other atom can stay as it is when it changes.
std::map<std::string, std::string> enum_mcdc(
    const std::vector<std::pair<std::string, std::string>>& atoms) {
  std::map<std::string, std::string> out;
  for (const auto& [requirement, atom] : atoms)
    out["drive/mcdc/" + requirement + "/" + atom] =
        "not independently testable: " + atom +
        " never changes alone: the domain or the other atoms tie it to them";
  return out;
}

std::string outcome(const campaign::Campaign& c, std::size_t k) {
  const campaign::Target& t = c.targets[k];
  if (t.undecided) return "not decided: " + t.reason;
  if (!t.reachable) return "unreachable: " + t.reason;
  return c.covered[k] ? "covered" : "missed";
}

// Every target is covered, but those listed (id: reason) are unreachable; every scenario
// reaches its purpose, and AtDock fails in each.
void expect_covered_behind_fallback(const campaign::Campaign& c,
                                    const std::map<std::string, std::string>& unreachable = {}) {
  ASSERT_FALSE(c.targets.empty());
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    const auto it = unreachable.find(c.targets[k].id);
    EXPECT_EQ(outcome(c, k), it == unreachable.end() ? "covered" : "unreachable: " + it->second)
        << c.targets[k].id;
  }
  ASSERT_FALSE(c.scenarios.empty());
  for (const auto& s : c.scenarios) {
    EXPECT_TRUE(s.problems.empty()) << s.name << ": " << s.problems.front();
    const auto j = nlohmann::json::parse(s.json);
    EXPECT_EQ(j["actions"]["AtDock"]["runs"][0]["result"], "failure") << s.json;
  }
  EXPECT_TRUE(c.passed());
}

TEST(CampaignWorldReach, ANodeBehindAnActionInAFallbackIsReachedWhereTheActionFails) {
  TempMission dir(behind_fallback("enum ground in {ice, regolith, basalt}\n", kEnumRequirements));
  const load::Mission m = load_dir(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, {});
  expect_covered_behind_fallback(
      c,
      enum_mcdc({{"R1", "ground = ice"}, {"R2", "ground = regolith"}, {"R3", "ground = basalt"}}));
  std::set<std::string> selected;
  for (const auto& s : c.scenarios)
    for (const auto& o : s.run.observations) selected.insert(o.alternative);
  EXPECT_EQ(selected, (std::set<std::string>{"slow", "careful", "fast"}));
}

TEST(CampaignWorldReach, IntegerGuardsBehindAFallbackAreReachedWithTheirBoundaries) {
  TempMission dir(behind_fallback(
      "integer depth in [0, 10]\n",
      "R1: In drive if depth < 3 Mission shall satisfy selected_alt = slow\n"
      "R2: In drive if depth >= 3 & depth < 7 Mission shall satisfy selected_alt = careful\n"
      "R3: In drive Mission shall satisfy selected_alt = fast\n"));
  const load::Mission m = load_dir(dir.dir());
  expect_covered_behind_fallback(campaign::build_campaign(m, {}));
}

TEST(CampaignWorldReach, RealGuardsBehindAFallbackAreReachedWithTheirBoundaries) {
  TempMission dir(behind_fallback(
      "real slope in [0, 30]\n",
      "R1: In drive if slope < 10.5 Mission shall satisfy selected_alt = slow\n"
      "R2: In drive if slope >= 10.5 & slope < 20 Mission shall satisfy selected_alt = careful\n"
      "R3: In drive Mission shall satisfy selected_alt = fast\n"));
  const load::Mission m = load_dir(dir.dir());
  expect_covered_behind_fallback(campaign::build_campaign(m, {}));
}

TEST(CampaignWorldReach, AShadowedRequirementBehindAFallbackIsUnreachableWithItsReason) {
  TempMission dir(
      behind_fallback("enum ground in {ice, regolith, basalt}\n",
                      std::string(kEnumRequirements) +
                          "R4: In drive if ground = ice Mission shall satisfy selected_alt = "
                          "crawl\n"));
  const load::Mission m = load_dir(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, {});
  std::map<std::string, std::string> unreachable = enum_mcdc({{"R1", "ground = ice"},
                                                              {"R2", "ground = regolith"},
                                                              {"R3", "ground = basalt"},
                                                              {"R4", "ground = ice"}});
  unreachable["drive/decision/select/crawl"] =
      "wherever the guard of R4 holds, an earlier requirement (R1) holds too and is selected "
      "first";
  expect_covered_behind_fallback(c, unreachable);
}

TEST(CampaignWorldReach, ANodeWorldJsonNeverLetsARunTickIsAPathNoRunTakes) {
  std::map<std::string, std::string> files =
      behind_fallback("enum ground in {ice, regolith, basalt}\n", kEnumRequirements);
  files["world.json"] = R"({"actions": {"AtDock": {"results": ["success"]}}})";
  TempMission dir(files);
  const load::Mission m = load_dir(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, {});
  ASSERT_FALSE(c.targets.empty());
  const std::map<std::string, std::string> mcdc =
      enum_mcdc({{"R1", "ground = ice"}, {"R2", "ground = regolith"}, {"R3", "ground = basalt"}});
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    const auto domain = mcdc.find(c.targets[k].id);
    EXPECT_EQ(outcome(c, k),
              "unreachable: " + (domain != mcdc.end()
                                     ? domain->second
                                     : "a path no run takes: no run that world.json allows "
                                       "ticks drive"))
        << c.targets[k].id;
  }
  EXPECT_TRUE(c.scenarios.empty());
  // A contract that lets AtDock fail after a few ticks: every target is reached.
  dir.write("world.json",
            R"({"actions": {"AtDock": {"ticks": [2, 3], "results": ["success", "failure"]}}})");
  const load::Mission again = load_dir(dir.dir());
  const campaign::Campaign reached = campaign::build_campaign(again, {});
  for (std::size_t k = 0; k < reached.targets.size(); ++k)
    EXPECT_EQ(outcome(reached, k), mcdc.count(reached.targets[k].id)
                                       ? "unreachable: " + mcdc.at(reached.targets[k].id)
                                       : "covered")
        << reached.targets[k].id;
  for (const auto& s : reached.scenarios) {
    const auto j = nlohmann::json::parse(s.json);
    EXPECT_EQ(j["actions"]["AtDock"]["runs"][0]["ticks"], 2) << s.json;
  }
}

TEST(CampaignWorldReach, UabtTestsWritesScenariosThatUabtRunAndCoverageReplayToEveryTarget) {
  TempMission dir(behind_fallback("enum ground in {ice, regolith, basalt}\n", kEnumRequirements));
  const std::string at = dir.dir().string();
  const CliRun tests = run_uabt_in(at, "tests . --out out");
  ASSERT_EQ(tests.exit_code, 0) << tests.out;
  const auto summary =
      nlohmann::json::parse(read_all(dir.dir() / "out" / "campaign.json"))["summary"];
  EXPECT_EQ(summary["targets"], 12);
  EXPECT_EQ(summary["reachable"], 9);  // each MC/DC target is ruled out by the domain
  EXPECT_EQ(summary["covered"], 9);
  // uabt run replays a scenario through AtDock's failure to drive.
  const CliRun run = run_uabt_in(at, "run . --scenario out/drive-01.json");
  EXPECT_NE(run.out.find("tick 1: drive selects slow (R1)\n"), std::string::npos) << run.out;
  // One scenario covers some targets and lists the others it misses; all of them cover all.
  const CliRun one = run_uabt_in(at, "coverage . out/drive-01.json");
  EXPECT_EQ(one.exit_code, 1) << one.out;
  EXPECT_NE(one.out.find("\nmissed: drive selects "), std::string::npos) << one.out;
  const CliRun all = run_uabt_in(at, "coverage . out");
  EXPECT_EQ(all.exit_code, 0) << all.out;
  EXPECT_EQ(all.out.find("missed:"), std::string::npos) << all.out;
}

// For each selection target of each shipped mission, prove is asked whether a run reaches it
// (the node ticked in a state of the target; for an MC/DC pair, both states of some pair): its
// answer and the campaign's verdict agree.
TEST(CampaignWorldReach, ProveAgreesWithTheCampaignOnEveryTargetOfTheShippedMissions) {
  campaign::Options options;
  options.criteria = {Criterion::decision, Criterion::mcdc, Criterion::boundary};
  std::size_t reachable = 0, unreachable = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "missions")) {
    if (!entry.is_directory()) continue;
    const load::Mission m = load_dir(entry.path());
    const campaign::Campaign c = campaign::build_campaign(m, options);
    const campaign::Model model(m, options.criteria);
    ASSERT_EQ(model.targets().size(), c.targets.size()) << entry.path();
    std::vector<prove::Goal> goals;
    std::vector<std::optional<campaign::Model::ReachCondition>> reach;
    auto goal = [&](std::size_t node, const std::string& condition) {
      goals.push_back(
          campaign::node_goal(m, model, node, condition, "target-" + std::to_string(goals.size())));
      return goals.size() - 1;
    };
    std::vector<std::vector<std::size_t>> asked(c.targets.size());
    for (std::size_t t = 0; t < c.targets.size(); ++t) {
      reach.push_back(model.reach_condition(t));
      ASSERT_TRUE(reach.back()) << c.targets[t].id;
      if (reach.back()->pairs.empty())
        asked[t].push_back(goal(reach.back()->node, reach.back()->single));
      for (const auto& [s, u] : reach.back()->pairs) {
        asked[t].push_back(goal(reach.back()->node, s));
        asked[t].push_back(goal(reach.back()->node, u));
      }
    }
    const auto replayer = campaign::Replayer::compiling(m, options.compile);
    const prove::WorldModel world = prove::mission_world(m);
    const std::vector<prove::Reach> answers =
        prove::reach(m, replayer.document(), world, goals, prove::Options{});
    for (std::size_t t = 0; t < c.targets.size(); ++t) {
      const campaign::Target& target = c.targets[t];
      auto is = [&](std::size_t g, prove::Verdict v) { return answers[g].verdict == v; };
      bool reached = false, none = true;
      if (reach[t]->pairs.empty()) {
        reached = !asked[t].empty() && is(asked[t][0], prove::Verdict::violated);
        none = asked[t].empty() || is(asked[t][0], prove::Verdict::proved);
      }
      for (std::size_t p = 0; p + 1 < asked[t].size() && !reach[t]->pairs.empty(); p += 2) {
        reached = reached || (is(asked[t][p], prove::Verdict::violated) &&
                              is(asked[t][p + 1], prove::Verdict::violated));
        none = none && (is(asked[t][p], prove::Verdict::proved) ||
                        is(asked[t][p + 1], prove::Verdict::proved));
      }
      EXPECT_FALSE(target.undecided) << entry.path() << ": " << target.id << ": " << target.reason;
      if (target.reachable) {
        ++reachable;
        EXPECT_TRUE(c.covered[t]) << entry.path() << ": " << target.id;
        EXPECT_TRUE(reached) << entry.path() << ": " << target.id;
      } else {
        ++unreachable;
        EXPECT_TRUE(none) << entry.path() << ": " << target.id << ": " << target.reason;
      }
    }
  }
  EXPECT_GT(reachable, 50u);
  // Every selection target of the shipped missions is reached: each was asked of prove.
  EXPECT_EQ(unreachable, 0u);
}

}  // namespace
}  // namespace uabt::testing
