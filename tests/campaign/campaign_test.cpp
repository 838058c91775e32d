// The test campaign (uabt tests) and what runs cover (uabt coverage): random small missions
// checked against brute force over their domain, and the shipped missions' exact output.
#include <gtest/gtest.h>

#include <array>

#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include "base/files.hpp"
#include "base/number_text.hpp"
#include "campaign/campaign.hpp"
#include "cli/cli_support.hpp"
#include "fretish/expr.hpp"
#include "load/load_test_support.hpp"
#include "report/reports.hpp"
#include "smt/atoms.hpp"
#include "smt/evaluate.hpp"
#include "temp_mission.hpp"
#include "verify/verify.hpp"

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

// The initial states of the scenarios a target was planned in, as written (an MC/DC pair: two).
std::vector<State> planned_states(const campaign::Campaign& c, std::size_t target) {
  std::vector<State> states;
  for (const auto& s : c.scenarios)
    if (std::find(s.purpose.begin(), s.purpose.end(), target) != s.purpose.end())
      states.push_back(initial_of(s.json));
  return states;
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
    const auto replayer = campaign::Replayer::compiling(m, {});
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
      const std::vector<State> states = planned_states(c, k);
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

// A node the coverage stage cannot enumerate: 30 boolean flags (2^30 states) in simple guards;
// f29 and f30 never hold together, so R4 is never selected.
std::map<std::string, std::string> thirty_flags_mission() {
  std::string flags, r1, r2;
  for (int i = 1; i <= 30; ++i) flags += (i == 1 ? "f" : ", f") + std::to_string(i);
  for (int i = 1; i <= 10; ++i) r1 += (i == 1 ? "f" : " & f") + std::to_string(i);
  for (int i = 11; i <= 20; ++i) r2 += (i == 11 ? "f" : " | f") + std::to_string(i);
  std::map<std::string, std::string> files;
  files["mission.xml"] =
      mission_with("    <Sequence>\n      <Adaptable ID=\"node\"/>\n    </Sequence>");
  files["domain.fret"] = "boolean " + flags + "\nassume not_both: !(f29 & f30)\n";
  files["requirements.fret"] =
      "R1: In node if " + r1 + " Mission shall satisfy selected_alt = alt1\n" + "R2: In node if " +
      r2 + " Mission shall satisfy selected_alt = alt2\n" +
      "R3: In node if f21 & !f22 & (f23 | f24) & f25 & !f26 & f27 & !f28 Mission shall satisfy "
      "selected_alt = alt3\n"
      "R4: In node if f29 & f30 Mission shall satisfy selected_alt = alt4\n"
      "Default: In node Mission shall satisfy selected_alt = fallback\n";
  for (const char* alt : {"alt1", "alt2", "alt3", "alt4", "fallback"})
    files[std::string("alternatives/node/") + alt + ".xml"] =
        alternative_tree(alt, "<AlwaysSuccess/>");
  return files;
}

// Two integers wider than 2^32 and two reals: boundaries at 4000000000, 0, 50 and w + v = 60.
std::map<std::string, std::string> wide_integers_mission() {
  std::map<std::string, std::string> files;
  files["mission.xml"] =
      mission_with("    <Sequence>\n      <Adaptable ID=\"node\"/>\n    </Sequence>");
  files["domain.fret"] =
      "integer p in [0, 5000000000]\ninteger q in [-5000000000, 5000000000]\n"
      "real w in [0, 100]\nreal v in [0, 100]\nassume order: q <= p\n";
  files["requirements.fret"] =
      "R1: In node if p > 4000000000 & q < 0 Mission shall satisfy selected_alt = alt1\n"
      "R2: In node if p = q | w >= 50 | w + v < 60 Mission shall satisfy selected_alt = alt2\n"
      "R3: In node if p < 0 Mission shall satisfy selected_alt = alt3\n"
      "Default: In node Mission shall satisfy selected_alt = fallback\n";
  for (const char* alt : {"alt1", "alt2", "alt3", "fallback"})
    files[std::string("alternatives/node/") + alt + ".xml"] =
        alternative_tree(alt, "<AlwaysSuccess/>");
  return files;
}

// Every scenario of a campaign reaches its purpose, and again when run from its bytes.
void expect_every_scenario_reaches_its_target(const load::Mission& m, const campaign::Campaign& c) {
  const auto replayer = campaign::Replayer::compiling(m, {});
  for (const auto& s : c.scenarios) {
    EXPECT_TRUE(s.problems.empty()) << s.name;
    const campaign::RunRecord run = replayer.run(s.json, s.name + ".json");
    ASSERT_FALSE(run.observations.empty()) << s.name;
    EXPECT_EQ(run.observations.front().alternative, selects(m, initial_of(s.json)))
        << s.name << "\n"
        << s.json;
  }
  EXPECT_TRUE(c.passed()) << campaign::campaign_text(c);
}

std::map<std::string, const campaign::Target*> targets_by_id(const campaign::Campaign& c) {
  std::map<std::string, const campaign::Target*> out;
  for (const auto& t : c.targets) out[t.id] = &t;
  return out;
}

TEST(CampaignSolved, ThirtyFlagsGetDecisionAndMcdcTargetsThatTheirScenariosReach) {
  TempMission dir(thirty_flags_mission());
  const load::Mission m = load(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, {});
  EXPECT_TRUE(c.skipped.empty());
  std::map<Criterion, std::size_t> per;
  for (const auto& t : c.targets) ++per[t.criterion];
  EXPECT_EQ(per[Criterion::decision], 13u);  // 5 selections, 4 guards both ways
  EXPECT_EQ(per[Criterion::mcdc], 30u);      // every flag once
  expect_every_scenario_reaches_its_target(m, c);
  const auto by_id = targets_by_id(c);
  for (const auto& [id, t] : by_id) {
    if (id.find("R4") == std::string::npos && id != "node/decision/select/alt4") {
      EXPECT_TRUE(t->reachable) << id << ": " << t->reason;
    }
  }
  // The assumption rules R4's guard out: each of its targets says why.
  EXPECT_EQ(by_id.at("node/decision/select/alt4")->reason,
            "the guard of R4 holds in no state of the domain");
  EXPECT_EQ(by_id.at("node/decision/guard/R4/true")->reason,
            "the guard holds in no state of the domain");
  EXPECT_EQ(by_id.at("node/mcdc/R4/f29")->reason,
            "not independently testable: the guard of R4 holds in no state of the domain, so no "
            "atom can change it");
  EXPECT_TRUE(by_id.at("node/decision/guard/R4/false")->reachable);
}

TEST(CampaignSolved, ThirtyFlagsMcdcPairsDifferInExactlyOneFlag) {
  TempMission dir(thirty_flags_mission());
  const load::Mission m = load(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, only(Criterion::mcdc));
  std::size_t pairs = 0;
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    const auto& t = c.targets[k];
    if (!t.reachable) continue;
    EXPECT_TRUE(c.covered[k]) << t.id;
    const std::vector<State> states = planned_states(c, k);
    ASSERT_EQ(states.size(), 2u) << t.id;
    const std::string flag = t.id.substr(t.id.rfind('/') + 1);
    std::vector<std::string> changed;
    for (int i = 1; i <= 30; ++i) {
      const std::string f = "f" + std::to_string(i);
      if (find_value(states[0], f)->boolean != find_value(states[1], f)->boolean)
        changed.push_back(f);
    }
    EXPECT_EQ(changed, std::vector<std::string>{flag}) << t.id;
    EXPECT_NE(selects(m, states[0]), selects(m, states[1])) << t.id;
    ++pairs;
  }
  EXPECT_EQ(pairs, 28u);  // all but f29 and f30 of R4
}

TEST(CampaignSolved, WideIntegersGetBoundaryTargetsAndNoShare) {
  TempMission dir(wide_integers_mission());
  const load::Mission m = load(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, {});
  EXPECT_TRUE(c.skipped.empty());
  expect_every_scenario_reaches_its_target(m, c);
  std::map<std::string, std::string> boundary;
  for (const auto& t : c.targets)
    if (t.criterion == Criterion::boundary)
      boundary[t.id] = t.reachable ? state_json(t.witness.front()).dump() : t.reason;
  ASSERT_EQ(boundary.size(), 10u);
  for (const char* side : {"below", "at", "above"})
    EXPECT_EQ(boundary.count(std::string("node/boundary/line/w + v = 60/") + side), 1u) << side;
  EXPECT_EQ(boundary.count("node/boundary/p/4000000000|4000000001/below"), 1u);
  EXPECT_EQ(boundary.count("node/boundary/p/4000000000|4000000001/above"), 1u);
  EXPECT_EQ(boundary.count("node/boundary/q/-1|0/below"), 1u);
  EXPECT_EQ(boundary.count("node/boundary/q/-1|0/above"), 1u);
  // Witnesses are written as the domain writes numbers.
  EXPECT_NE(boundary.at("node/boundary/p/4000000000|4000000001/above").find("\"p\":4000000001"),
            std::string::npos);
  EXPECT_NE(boundary.at("node/boundary/w/50/at").find("\"w\":50"), std::string::npos);
  EXPECT_NE(boundary.at("node/boundary/w/50/below").find("\"w\":1"), std::string::npos);
  EXPECT_NE(boundary.at("node/boundary/w/50/above").find("\"w\":51"), std::string::npos);
  EXPECT_EQ(targets_by_id(c).at("node/mcdc/R3/p < 0")->reason,
            "not independently testable: p < 0 is false in every state of the domain");
  // What runs visited is counted, not measured: no share of 2^64 states.
  const campaign::Model model(m, {Criterion::decision});
  std::vector<campaign::RunRecord> runs;
  for (const auto& s : c.scenarios) runs.push_back(s.run);
  const auto visits = model.visits(runs);
  ASSERT_EQ(visits.size(), 1u);
  EXPECT_EQ(visits[0].share_not_computed, "the guards range over more than 2^24 states");
  campaign::CoverageReport report;
  report.mission = "wide";
  report.targets = model.targets();
  report.covered = model.covered(runs);
  report.visits = visits;
  EXPECT_NE(campaign::coverage_text(report).find(
                "  node: " + std::to_string(visits[0].visited.cells) +
                " states visited, share not computed: the guards range over more than 2^24 "
                "states\n"),
            std::string::npos)
      << campaign::coverage_text(report);
}

TEST(CampaignSolved, AStateTheTreeNeverTicksTheNodeInIsSolvedAgainElsewhere) {
  // The node is ticked only when x >= 2; x and y are too wide to enumerate.
  TempMission dir({{"mission.xml", mission_with("    <Fallback>\n"
                                                "      <ScriptCondition code=\"x &lt; 2\"/>\n"
                                                "      <Adaptable ID=\"node\"/>\n"
                                                "    </Fallback>")},
                   {"domain.fret", "integer x in [0, 5000000000]\ninteger y in [0, 5000000000]\n"},
                   {"requirements.fret",
                    "R1: In node if x < 1000000000 & y > 10 Mission shall satisfy selected_alt = "
                    "low\n"
                    "Other: In node Mission shall satisfy selected_alt = other\n"},
                   {"alternatives/node/low.xml", alternative_tree("low", "<AlwaysSuccess/>")},
                   {"alternatives/node/other.xml", alternative_tree("other", "<AlwaysSuccess/>")}});
  const load::Mission m = load(dir.dir());
  const campaign::Campaign c = campaign::build_campaign(m, {});
  EXPECT_TRUE(c.skipped.empty());
  EXPECT_FALSE(c.targets.empty());
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    EXPECT_TRUE(c.targets[k].reachable) << c.targets[k].id << ": " << c.targets[k].reason;
    EXPECT_TRUE(c.covered[k]) << c.targets[k].id;
  }
  for (const auto& s : c.scenarios) {
    EXPECT_TRUE(s.problems.empty()) << s.name;
    EXPECT_GE(find_value(initial_of(s.json), "x")->integer, 2) << s.json;
  }
}

// What a campaign found of each selection target: covered, missed, or unreachable and why.
std::map<std::string, std::string> outcome(const campaign::Campaign& c) {
  std::map<std::string, std::string> out;
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    const auto& t = c.targets[k];
    if (t.criterion == Criterion::guarantee) continue;
    std::string reason = t.reason;
    // How many states were tried before giving up depends on the witnesses.
    if (const auto tried = reason.find(" states tried"); tried != std::string::npos)
      reason.erase(reason.rfind(' ', tried - 1), tried - reason.rfind(' ', tried - 1));
    out[t.id] = t.reachable ? (c.covered[k] ? "covered" : "missed") : "unreachable: " + reason;
  }
  return out;
}

// One real whose guard 3 * slope > 1 changes at slope = 1/3, a number no decimal writes.
std::map<std::string, std::string> one_third_boundary_mission() {
  return {{"mission.xml", mission_with("    <Adaptable ID=\"node\"/>")},
          {"domain.fret", "real slope in [0, 1]\n"},
          {"requirements.fret",
           "R1: In node if 3 * slope > 1 Mission shall satisfy selected_alt = high\n"
           "Other: In node Mission shall satisfy selected_alt = other\n"},
          {"alternatives/node/high.xml", alternative_tree("high", "<AlwaysSuccess/>")},
          {"alternatives/node/other.xml", alternative_tree("other", "<AlwaysSuccess/>")}};
}

TEST(CampaignSolved, ABreakpointNoDecimalWritesGetsANumberInEveryScenario) {
  // 3 * slope > 1 changes at slope = 1/3, which no JSON number is: enumerated and solved nodes
  // both write a real as one real_value does, a number a scenario carries (the nearest double),
  // never the text "1/3", which uabt run would refuse as a string for a real.
  TempMission dir(one_third_boundary_mission());
  const load::Mission m = load(dir.dir());
  for (const bool solve : {false, true}) {
    campaign::Options options;
    options.criteria = {Criterion::boundary};
    options.solve_every_node = solve;
    const campaign::Campaign c = campaign::build_campaign(m, options);
    ASSERT_EQ(c.targets.size(), 3u);
    for (const auto& t : c.targets)
      for (const State& witness : t.witness)
        for (const auto& [name, value] : witness)
          EXPECT_EQ(value.to_string().find('/'), std::string::npos) << t.id << " solve " << solve;
    for (const auto& s : c.scenarios) {
      EXPECT_TRUE(s.problems.empty()) << s.name << "\n" << s.json;
      EXPECT_TRUE(nlohmann::json::parse(s.json)["initial"]["slope"].is_number()) << s.json;
    }
  }
}

TEST(CampaignSolved, ARunAtABreakpointsNearestDoubleIsOnTheBoundaryForEveryNode) {
  // The run's guard is computed in doubles, as BehaviorTree.CPP does: at 0.3333333333333333,
  // 3 * slope > 1 is false as at 1/3. Enumerated and solved nodes place that run on the
  // boundary alike; enumerated ones used to call the target not decided, since no double is
  // exactly 1/3, while solved ones called it covered.
  TempMission dir(one_third_boundary_mission());
  const load::Mission m = load(dir.dir());
  for (const bool solve : {false, true}) {
    campaign::Options options;
    options.criteria = {Criterion::boundary};
    options.solve_every_node = solve;
    const auto found = outcome(campaign::build_campaign(m, options));
    const std::map<std::string, std::string> all_covered{
        {"node/boundary/slope/1/3/below", "covered"},
        {"node/boundary/slope/1/3/at", "covered"},
        {"node/boundary/slope/1/3/above", "covered"}};
    EXPECT_EQ(found, all_covered) << "solve " << solve;
  }
}

TEST(CampaignCoverage, ATargetNotDecidedIsCountedAndListedAsTheCampaignDoes) {
  // With the engines stopped after one tick, two guarantee targets are not decided either way.
  // `uabt coverage` must say so as `uabt tests` does, not call them unreachable.
  const load::Mission m = load(source_dir() / "missions" / "msl_curiosity");
  campaign::Options options;
  options.criteria = {Criterion::guarantee};
  options.prove_depth = 1;
  const campaign::Campaign c = campaign::build_campaign(m, options);
  ASSERT_TRUE(targets_by_id(c).at("guarantee/ArmClosed/response/drive.running/true")->undecided);
  campaign::CoverageReport report;
  report.mission = "msl_curiosity";
  report.targets = c.targets;
  report.covered = c.covered;
  const std::string text = campaign::coverage_text(report);
  EXPECT_NE(text.find("0 unreachable, 2 not decided)"), std::string::npos) << text;
  EXPECT_NE(text.find("\nnot decided: drive.running is true and decides the response of "
                      "ArmClosed "),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("\nunreachable: "), std::string::npos) << text;
  const auto summary = nlohmann::json::parse(campaign::coverage_json(report))["summary"];
  EXPECT_EQ(summary["unreachable"], 0);
  EXPECT_EQ(summary["undecided"], 2);
}

TEST(CampaignSolved, SolvingAgreesWithEnumerationOnTheShippedMissions) {
  campaign::Options enumerating;
  enumerating.criteria = {Criterion::decision, Criterion::mcdc, Criterion::boundary};
  campaign::Options solving = enumerating;
  solving.solve_every_node = true;
  std::size_t targets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "missions")) {
    if (!entry.is_directory()) continue;
    const load::Mission m = load(entry.path());
    const auto enumerated = outcome(campaign::build_campaign(m, enumerating));
    EXPECT_EQ(outcome(campaign::build_campaign(m, solving)), enumerated) << entry.path();
    targets += enumerated.size();
  }
  EXPECT_GT(targets, 100u);
}

TEST(CampaignSolved, SolvingAgreesWithEnumerationOnRandomMissions) {
  for (unsigned seed = 1; seed <= kRandomMissions; ++seed) {
    TempMission dir(random_mission(seed));
    const load::Mission m = load(dir.dir());
    campaign::Options solving;
    solving.solve_every_node = true;
    const campaign::Campaign enumerated = campaign::build_campaign(m, {});
    const campaign::Campaign solved = campaign::build_campaign(m, solving);
    EXPECT_EQ(outcome(solved), outcome(enumerated)) << "seed " << seed;
    EXPECT_TRUE(solved.passed()) << "seed " << seed << "\n" << campaign::campaign_text(solved);
  }
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
    if (t.reachable) witness[t.id] = state_json(t.witness.front()).dump();
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
            "no run (whatever its actions return: no world.json bounds them) ticks node in a "
            "state where (x < 1)");
  EXPECT_FALSE(low.undecided);
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

TEST(CampaignCli, ANodeTooLargeToEnumerateGetsItsTargetsSolved) {
  // 26 booleans: more states than the campaign enumerates; its targets are solved one by one
  // (no hang), and it says so.
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
  EXPECT_NE(run.out.find(": 66 targets (decision 40, MC/DC 26), 0 unreachable; "),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find(" cover 66 of 66 reachable targets\n"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\ntargets of node solved one by one, not enumerated: the guards range "
                         "over more than 2^24 states\n"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("no targets for node"), std::string::npos) << run.out;
}

TEST(CampaignCli, ARunThatStopsOnATickErrorNamesTheLineOfTheMission) {
  // blackboard_defects reads target_range before anything writes it: a run in which
  // ReportRange does not write it stops there.
  TempMission scratch(std::map<std::string, std::string>{
      {"no_range.json", R"({"max_ticks": 3, "initial": {"terrain": "sand"}})"}});
  const CliRun run = run_uabt_in(
      (source_dir() / "missions").string(),
      "coverage blackboard_defects '" + (scratch.dir() / "no_range.json").string() + "'");
  EXPECT_NE(run.out.find("stopped: blackboard_defects/mission.xml:14:7: ScriptCondition "
                         "'in_reach': undefined blackboard key 'target_range'"),
            std::string::npos)
      << run.out;
  // The campaign's runs have ReportRange write it, and reach sampling.
  const CliRun tests = run_uabt_in(
      (source_dir() / "missions").string(),
      "tests blackboard_defects --criterion decision --out '" + scratch.dir().string() + "/out'");
  EXPECT_EQ(tests.exit_code, 0) << tests.out;
  EXPECT_EQ(tests.out.find("unreachable: sampling"), std::string::npos) << tests.out;
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
           state_json(o.state).dump() + "\n";
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

  const auto shared = campaign::Replayer::compiling(m, {});
  std::size_t left_running = 0;
  for (const auto& r : runs) {
    const campaign::RunRecord reused = shared.run(r.json, r.file, r.stop_after);
    const auto fresh_tree = campaign::Replayer::compiling(m, {});
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

namespace uabt::testing {
namespace {

// One element of a coverage map's SVG that marks a visited cell, with the panel it is drawn in:
// the panel's frame (its background rectangle) and its label.
struct DrawnMark {
  std::string tag;
  std::map<std::string, std::string> attributes;
  std::string title;
  double left = 0, top = 0, width = 0, height = 0;
  std::string panel;
};

std::vector<DrawnMark> visited_marks_of(const std::string& svg) {
  std::vector<DrawnMark> out;
  DrawnMark frame;
  const std::regex element(R"re(<(\w+)((?:\s+[\w:-]+="[^"]*")*)\s*/?>)re");
  const std::regex attribute(R"re(([\w:-]+)="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), element);
       it != std::sregex_iterator(); ++it) {
    std::map<std::string, std::string> a;
    const std::string attrs = (*it)[2];
    for (auto at = std::sregex_iterator(attrs.begin(), attrs.end(), attribute);
         at != std::sregex_iterator(); ++at)
      a[(*at)[1]] = (*at)[2];
    const std::string tag = (*it)[1];
    const std::size_t end = static_cast<std::size_t>(it->position() + it->length());
    const std::string content = svg.substr(end, svg.find('<', end) - end);
    if (tag == "rect" && a["fill"] == "#f4f4f4" && !a.count("class")) {
      frame.left = std::stod(a["x"]);
      frame.top = std::stod(a["y"]);
      frame.width = std::stod(a["width"]);
      frame.height = std::stod(a["height"]);
      frame.panel.clear();
    } else if (tag == "text" && a["font-weight"] == "600" && a["text-anchor"] == "middle" &&
               !a.count("font-size")) {
      frame.panel = content;
    } else if (a["class"] == "visited") {
      DrawnMark m = frame;
      m.tag = tag;
      m.attributes = a;
      const std::size_t title = svg.find("<title>", end) + 7;
      m.title = svg.substr(title, svg.find("</title>", title) - title);
      out.push_back(std::move(m));
    }
  }
  return out;
}

// The map's coordinates of a pixel of a mark's panel.
std::pair<double, double> to_map(const verify::CoverageMap& map, const DrawnMark& m, double px,
                                 double py) {
  const double x = map.x.lower + (px - m.left) / m.width * (map.x.upper - map.x.lower);
  const double y =
      map.y->lower + (m.top + m.height - py) / m.height * (map.y->upper - map.y->lower);
  return {x, y};
}

// A run that observed `states` at `node`, as `uabt coverage` reads one.
campaign::RunRecord observed(const std::string& source, const std::string& node,
                             const std::vector<State>& states) {
  campaign::RunRecord run;
  run.source = source;
  for (const State& s : states) run.observations.push_back({node, "", s, 1});
  return run;
}

const verify::Coverage& coverage_of(const verify::Result& result, const std::string& node) {
  for (const auto& c : result.coverage)
    if (c.adaptable == node) return c;
  throw std::runtime_error("no coverage of " + node);
}

TEST(CampaignCoverageMap, AVisitedCellIsDrawnWhereTheStateLies) {
  // planetary_landing's map: wind (real, cut at 15) across, battery (integer) up, one panel per
  // terrain. A state inside a cell, one on the boundary wind = 15, one at the corner.
  const load::Mission m = load(mission_dir("planetary_landing"));
  const campaign::Model model(m, {Criterion::decision});
  auto landing = [](double wind, std::int64_t battery, const char* terrain) {
    return State{{"wind", Value::of_real(wind, std::to_string(wind))},
                 {"battery", Value::of_int(battery)},
                 {"terrain", Value::of_enum(terrain)}};
  };
  const std::vector<campaign::RunRecord> runs = {
      observed("calm.json", "landing", {landing(5, 50, "flat")}),
      observed("edge.json", "landing", {landing(15, 7, "rocks"), landing(40, 100, "crater")}),
      observed("again.json", "landing", {landing(6, 50, "flat")})};
  const auto visits = model.visits(runs);
  ASSERT_EQ(visits.size(), 1u);
  ASSERT_EQ(visits[0].no_map, "");
  const verify::Result verified = verify::verify_mission(m, {});
  const verify::Coverage& coverage = coverage_of(verified, "landing");
  ASSERT_TRUE(coverage.map && coverage.map->y);
  const std::string svg = report::coverage_map_svg(m, coverage, visits[0].marks);
  const auto marks = visited_marks_of(svg);
  ASSERT_EQ(marks.size(), 3u) << svg;  // wind 5 and 6 lie in one cell

  // wind in (0, 15), battery 50, flat: a rectangle around (5, 50) and (6, 50), on the flat panel.
  EXPECT_EQ(marks[0].tag, "rect");
  EXPECT_EQ(marks[0].panel, "terrain = flat");
  EXPECT_EQ(marks[0].title,
            "visited by calm.json, again.json: wind in (0, 15) &amp; battery = 50 &amp; terrain "
            "= flat");
  const double x = std::stod(marks[0].attributes.at("x")),
               y = std::stod(marks[0].attributes.at("y"));
  const auto [x0, y1] = to_map(*coverage.map, marks[0], x, y);
  const auto [x1, y0] =
      to_map(*coverage.map, marks[0], x + std::stod(marks[0].attributes.at("width")),
             y + std::stod(marks[0].attributes.at("height")));
  EXPECT_LE(x0, 5);
  EXPECT_GE(x1, 6);
  EXPECT_NEAR(x0, 0, 0.01);
  EXPECT_NEAR(x1, 15, 0.01);
  EXPECT_LT(y0, 50);
  EXPECT_GT(y1, 50);
  EXPECT_GT(y0, 49);  // the row of 50 alone (widened to 3 px, about 1.8 values)
  EXPECT_LT(y1, 51);

  // wind = 15 is a boundary: a segment at x = 15 through battery 7, on the rocks panel.
  EXPECT_EQ(marks[1].tag, "line");
  EXPECT_EQ(marks[1].panel, "terrain = rocks");
  const auto [lx, ly0] = to_map(*coverage.map, marks[1], std::stod(marks[1].attributes.at("x1")),
                                std::stod(marks[1].attributes.at("y1")));
  const auto [lx2, ly1] = to_map(*coverage.map, marks[1], std::stod(marks[1].attributes.at("x2")),
                                 std::stod(marks[1].attributes.at("y2")));
  EXPECT_NEAR(lx, 15, 0.01);
  EXPECT_NEAR(lx2, 15, 0.01);
  EXPECT_LT(std::min(ly0, ly1), 7);
  EXPECT_GT(std::max(ly0, ly1), 7);

  // wind = 40 is the end of the range (a point cell): at x = 40, battery 100, on crater's panel.
  EXPECT_EQ(marks[2].panel, "terrain = crater");
  EXPECT_NE(marks[2].title.find("edge.json: wind = 40 &amp; battery = 100"), std::string::npos)
      << marks[2].title;
}

TEST(CampaignCoverageMap, AVisitedCellOfTwoRelatedRealsIsThePolygonTheStateLiesIn) {
  // r + s > 60 cuts the square [0, 50]² along a line: the map's cells are polygons.
  TempMission dir({{"mission.xml", mission_with("    <Adaptable ID=\"node\"/>")},
                   {"domain.fret", "real r in [0, 50]\nreal s in [0, 50]\n"},
                   {"requirements.fret",
                    "Far: In node if r + s > 60 Mission shall satisfy selected_alt = far\n"
                    "Near: In node Mission shall satisfy selected_alt = near\n"},
                   {"alternatives/node/far.xml", alternative_tree("far", "<AlwaysSuccess/>")},
                   {"alternatives/node/near.xml", alternative_tree("near", "<AlwaysSuccess/>")}});
  const load::Mission m = load(dir.dir());
  const campaign::Model model(m, {Criterion::decision});
  auto at = [](double r, double s) {
    return State{{"r", Value::of_real(r, std::to_string(r))},
                 {"s", Value::of_real(s, std::to_string(s))}};
  };
  const auto visits = model.visits({observed("far.json", "node", {at(40, 30)})});
  ASSERT_EQ(visits.size(), 1u);
  const verify::Result verified = verify::verify_mission(m, {});
  const verify::Coverage& coverage = coverage_of(verified, "node");
  ASSERT_TRUE(coverage.map && coverage.map->y);
  const std::string svg = report::coverage_map_svg(m, coverage, visits[0].marks);
  const auto marks = visited_marks_of(svg);
  ASSERT_EQ(marks.size(), 1u) << svg;
  ASSERT_EQ(marks[0].tag, "polygon");
  // The state lies inside the polygon (ray casting), and the polygon lies above the line.
  std::vector<std::pair<double, double>> polygon;
  std::istringstream points(marks[0].attributes.at("points"));
  for (std::string pair; points >> pair;) {
    const auto comma = pair.find(',');
    polygon.push_back(to_map(*coverage.map, marks[0], std::stod(pair.substr(0, comma)),
                             std::stod(pair.substr(comma + 1))));
  }
  ASSERT_GE(polygon.size(), 3u);
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const auto [xi, yi] = polygon[i];
    const auto [xj, yj] = polygon[j];
    if ((yi > 30) != (yj > 30) && 40 < (xj - xi) * (30 - yi) / (yj - yi) + xi) inside = !inside;
  }
  EXPECT_TRUE(inside) << marks[0].attributes.at("points");
  for (const auto& [r, s] : polygon) EXPECT_GE(r + s, 60 - 0.1) << r << ", " << s;
}

TEST(CampaignCoverageMap, WithoutVisitedCellsTheMapIsTheReportsOwn) {
  // The map `uabt gate` wrote into reports/planetary_landing/report.html, byte for byte.
  const load::Mission m = load(mission_dir("planetary_landing"));
  const verify::Result verified = verify::verify_mission(m, {});
  std::string svg = report::coverage_map_svg(m, coverage_of(verified, "landing"), {});
  const std::string xmlns = " xmlns=\"http://www.w3.org/2000/svg\"";
  svg.erase(svg.find(xmlns), xmlns.size());
  const std::string page = read_all(source_dir() / "reports/planetary_landing/report.html");
  const std::size_t title = page.find("<title>Selected alternative of landing");
  ASSERT_NE(title, std::string::npos);
  const std::size_t begin = page.rfind("<svg", title);
  const std::size_t end = page.find("</svg>", title) + 6;
  EXPECT_EQ(page.substr(begin, end - begin), svg);
  EXPECT_EQ(svg.find("visited"), std::string::npos);
}

// A guard the assumptions rule out never changes, whatever an atom does: that is the reason each
// of its atoms has no MC/DC pair, on both paths (enumerated and solved).
TEST(CampaignMcdc, AGuardTheAssumptionsRuleOutIsTheReasonForEachOfItsAtoms) {
  std::map<std::string, std::string> files;
  files["mission.xml"] =
      mission_with("    <Sequence>\n      <Adaptable ID=\"node\"/>\n    </Sequence>");
  files["domain.fret"] = "boolean a, b\nassume not_both: !(a & b)\n";
  files["requirements.fret"] =
      "R1: In node if a & b Mission shall satisfy selected_alt = both\n"
      "Default: In node Mission shall satisfy selected_alt = fallback\n";
  for (const char* alt : {"both", "fallback"})
    files[std::string("alternatives/node/") + alt + ".xml"] =
        alternative_tree(alt, "<AlwaysSuccess/>");
  TempMission dir(files);
  const load::Mission m = load(dir.dir());
  for (const bool solve : {false, true}) {
    campaign::Options options;
    options.solve_every_node = solve;
    const campaign::Campaign c = campaign::build_campaign(m, options);
    for (const char* atom : {"a", "b"}) {
      const auto t = std::find_if(c.targets.begin(), c.targets.end(), [&](const auto& t) {
        return t.id == std::string("node/mcdc/R1/") + atom;
      });
      ASSERT_NE(t, c.targets.end()) << atom;
      EXPECT_FALSE(t->reachable);
      EXPECT_EQ(t->reason,
                "not independently testable: the guard of R1 holds in no state of the domain, so "
                "no atom can change it")
          << (solve ? "solved" : "enumerated");
    }
  }
}

}  // namespace
}  // namespace uabt::testing
