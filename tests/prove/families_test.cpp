// The benchmark families (tests/bench/prove_families.*) at small sizes: the generated missions
// load, pass the gate and get the verdicts the families promise, so the generator cannot rot.
#include <cctype>

#include "bench/prove_families.hpp"
#include "prove/symbolic.hpp"
#include "prove_support.hpp"

namespace uabt::testing {
namespace {

// BT nodes of a compiled file: every element of its trees but <root> and <BehaviorTree>.
std::size_t compiled_nodes(const std::string& xml) {
  const std::string trees = xml.substr(0, xml.find("<TreeNodesModel>"));
  std::size_t nodes = 0;
  for (auto at = trees.find('<'); at != std::string::npos; at = trees.find('<', at + 1))
    if (at + 1 < trees.size() && std::isalpha(static_cast<unsigned char>(trees[at + 1])) &&
        trees.compare(at, 5, "<root") != 0 && trees.compare(at, 13, "<BehaviorTree") != 0)
      ++nodes;
  return nodes;
}

// The gate's checks as `uabt gate` runs them, without its proofs (gate::check_mission): each
// adaptable node compiled in the selection style it declares.
gate::Outcome gated(const std::filesystem::path& dir) {
  std::string error;
  auto mission = load::load_mission(dir, {}, error);
  EXPECT_TRUE(mission) << error;
  if (!mission) return {};
  return gate::check_mission(std::move(*mission), {}, "test");
}

// `complete`: every reachable state explored (the explicit engine stops once every guarantee
// is violated).
void check_answers(const prove::Result& r, const bench::FamilyMission& family,
                   bool complete = true) {
  EXPECT_EQ(r.complete, complete);
  ASSERT_EQ(r.answers.size(), family.verdicts.size());
  for (const prove::Answer& a : r.answers) {
    ASSERT_TRUE(family.verdicts.count(a.requirement)) << a.requirement;
    EXPECT_EQ(prove::verdict_name(a.verdict), family.verdicts.at(a.requirement)) << a.requirement;
    if (family.violation_ticks.count(a.requirement)) {
      EXPECT_EQ(a.depth, family.violation_ticks.at(a.requirement)) << a.requirement;
      ASSERT_TRUE(a.counterexample) << a.requirement;
      EXPECT_EQ(a.counterexample->tick, family.violation_ticks.at(a.requirement));
    }
  }
}

// Proves the guarantees on the tree the gate compiled, as `uabt prove` does (prove_dir would
// force one selection style on every adaptable node).
void expect_answers(const bench::FamilyMission& family, const gate::Outcome& outcome,
                    const prove::Options& options = {}) {
  ASSERT_FALSE(outcome.compiled_xml.empty()) << format_text(outcome.report.findings);
  std::vector<Finding> findings;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  ASSERT_TRUE(doc);
  check_answers(
      prove::prove(*outcome.mission, *doc, prove::mission_world(*outcome.mission), options),
      family);
}

void expect_answers(const bench::FamilyMission& family) {
  ASSERT_TRUE(std::filesystem::exists(family.dir / "mission.xml"));
  expect_answers(family, gated(family.dir));
}

TEST(ProveFamilies, BinaryTreeOf23Nodes) {
  TempMission scratch({});
  const auto family = bench::generate_binary_tree(scratch.dir() / "binary", 23, 2);
  EXPECT_EQ(family.tree_nodes, 24);
  const std::string xml = read_all(family.dir / "mission.xml");
  // 11 Fallbacks, 12 leaves: 6 checks and 6 actions.
  std::size_t fallbacks = 0, checks = 0;
  for (auto at = xml.find("<Fallback>"); at != std::string::npos;
       at = xml.find("<Fallback>", at + 1))
    ++fallbacks;
  for (auto at = xml.find("<ScriptCondition"); at != std::string::npos;
       at = xml.find("<ScriptCondition", at + 1))
    ++checks;
  EXPECT_EQ(fallbacks, 11u);
  EXPECT_EQ(checks, 6u);
  expect_answers(family);
}

TEST(ProveFamilies, BinaryTreeWithThreeCounters) {
  TempMission scratch({});
  expect_answers(bench::generate_binary_tree(scratch.dir() / "binary", 71, 3));
}

TEST(ProveFamilies, ChecklistOfFive) {
  TempMission scratch({});
  const auto family = bench::generate_checklist(scratch.dir() / "checklist", 5);
  EXPECT_EQ(family.tree_nodes, 19);
  expect_answers(family);
}

// The symbolic engine finds a violation a short run shows by BMC before it spends IC3/PDR's
// full search or deeper induction on it: k-induction stops at 2 (it went on to the tick before
// the violation), with the same shortest violations.
TEST(ProveFamilies, SymbolicEngineFindsShortViolationsByBmcBeforeDeeperInduction) {
  TempMission scratch({});
  prove::Options options;
  options.engine = "symbolic";
  for (const auto& family : {bench::generate_checklist(scratch.dir() / "checklist", 5),
                             bench::generate_binary_tree(scratch.dir() / "binary", 23, 2)}) {
    SCOPED_TRACE(family.dir.filename().string());
    const gate::Outcome outcome = gated(family.dir);
    ASSERT_FALSE(outcome.compiled_xml.empty()) << format_text(outcome.report.findings);
    std::vector<Finding> findings;
    auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
    ASSERT_TRUE(doc);
    const prove::Result r =
        prove::prove(*outcome.mission, *doc, prove::mission_world(*outcome.mission), options);
    check_answers(r, family);
    EXPECT_EQ(r.induction_k, 2u);
  }
}

// BMC asks, per depth, one question per open guarantee and whether a run goes on; whether a
// run is stuck only when neither answer showed a run of that length. Binary tree of 23 nodes:
// two guarantees open at depths 1 and 2 (3 questions each), one (Bounded is proved by
// 2-induction) at depths 3 to 7 (2 each), and at depth 8 its violation (1): 17 questions, where
// the stuck question at every depth made 25.
TEST(ProveFamilies, SymbolicBmcAsksWhetherARunIsStuckOnlyWhenNothingShowsARun) {
  TempMission scratch({});
  const auto family = bench::generate_binary_tree(scratch.dir() / "binary", 23, 2);
  const gate::Outcome outcome = gated(family.dir);
  ASSERT_FALSE(outcome.compiled_xml.empty()) << format_text(outcome.report.findings);
  std::vector<Finding> findings;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  ASSERT_TRUE(doc);
  const prove::WorldModel world = prove::mission_world(*outcome.mission);
  prove::Model m(*outcome.mission, *doc, world);
  const prove::SymbolicSearch s = prove::symbolic_search(m, {});
  EXPECT_EQ(s.depth, 8u);
  EXPECT_EQ(s.deadlock_after, 0u);
  EXPECT_EQ(s.bmc_checks, 17u);
}

TEST(ProveFamilies, PreflightOfThree) {
  TempMission scratch({});
  const auto family = bench::generate_preflight(scratch.dir() / "preflight", 3);
  EXPECT_EQ(family.tree_nodes, 13);
  // The flags are the environment's: declared, conditions of the robot, written by no action.
  EXPECT_NE(read_all(family.dir / "domain.fret").find("boolean Ok_3\n"), std::string::npos);
  EXPECT_NE(read_all(family.dir / "nodes.xml").find("<Condition ID=\"Ok_3\"/>"), std::string::npos);
  EXPECT_EQ(read_all(family.dir / "world.json").find("on_success"), std::string::npos);
  const gate::Outcome outcome = gated(family.dir);
  EXPECT_TRUE(outcome.passed()) << format_text(outcome.report.findings);
  EXPECT_EQ(compiled_nodes(outcome.compiled_xml), 13u);
  // Both engines, and the same answers (the explicit one is what `auto` takes here).
  for (const char* engine : {"explicit", "symbolic"}) {
    SCOPED_TRACE(engine);
    prove::Options options;
    options.engine = engine;
    expect_answers(family, outcome, options);
  }
}

TEST(ProveFamilies, PreflightOfTen) {
  TempMission scratch({});
  expect_answers(bench::generate_preflight(scratch.dir() / "preflight", 10));
}

// The benchmark's largest size: the mission loads and passes the gate (its proofs are the
// benchmark's job), and its compiled tree is the checklist of 100 flags.
TEST(ProveFamilies, PreflightOfAHundredPassesTheGate) {
  TempMission scratch({});
  const auto family = bench::generate_preflight(scratch.dir() / "preflight", 100);
  EXPECT_EQ(family.tree_nodes, 304);
  const gate::Outcome outcome = gated(family.dir);
  EXPECT_TRUE(outcome.passed()) << format_text(outcome.report.findings);
  EXPECT_EQ(compiled_nodes(outcome.compiled_xml), 304u);
  EXPECT_NE(outcome.compiled_xml.find("<Ok_100/>"), std::string::npos);
  EXPECT_NE(outcome.compiled_xml.find("<Condition ID=\"Ok_100\"/>"), std::string::npos);
}

// Proves the guarantees on the tree the gate compiled; the answers the family promises.
prove::Result proved(const bench::FamilyMission& family, bool complete) {
  const gate::Outcome outcome = gated(family.dir);
  EXPECT_TRUE(outcome.passed()) << format_text(outcome.report.findings);
  std::vector<Finding> findings;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  if (!doc) {
    ADD_FAILURE() << "the compiled tree does not read back";
    return {};
  }
  prove::Result r =
      prove::prove(*outcome.mission, *doc, prove::mission_world(*outcome.mission), {});
  check_answers(r, family, complete);
  return r;
}

// Flags only the guarantee reads after the tick are chosen as its conjunction reaches them, left
// to right: a tick where Launch runs with k flags unread branches k + 1 ways, not 2^k. Tick 1
// takes 3 N + 1 transitions (a fix's three outcomes after each flag read false, and Launch after
// all read true). Tick 2 takes 3 N - 2 K + 2 from the state where FixK runs (its failure, its
// success with CheckK read false, three outcomes of each later fix, and the K ways the guarantee
// reads the K - 1 flags before CheckK once Launch starts), and N + 1 from the one where Launch
// runs: 2 N^2 + 5 N + 2 in all, a share linear in N per state. Every flag's two values after
// every tick took 30214 transitions at N = 10, 155648 at N = 12, and minutes at N = 50.
TEST(ProveFamilies, RecheckedFlagsAreReadAsTheGuaranteeReachesThem) {
  TempMission scratch({});
  for (const std::uint64_t n : {2, 6, 12}) {
    SCOPED_TRACE(n);
    const auto family = bench::generate_recheck(scratch.dir() / ("recheck" + std::to_string(n)),
                                                static_cast<int>(n));
    EXPECT_EQ(family.tree_nodes, static_cast<int>(5 * n + 3));
    const prove::Result r = proved(family, false);
    EXPECT_EQ(r.transitions, 2 * n * n + 5 * n + 2);
  }
}

// A flag once set stays set (an Environment requirement per flag): the guarantee is proved.
TEST(ProveFamilies, RecheckedFlagsThatStaySetAreProved) {
  TempMission scratch({});
  const auto family = bench::generate_recheck(scratch.dir() / "recheck", 6, true);
  EXPECT_NE(read_all(family.dir / "requirements.fret")
                .find("Keep6: upon Check6 Environment shall always satisfy Check6\n"),
            std::string::npos);
  EXPECT_EQ(proved(family, true).engine, "explicit");
}

// Two reals and an enum of the environment, two adaptable nodes (traverse reactive, sample
// not): the gate finds nothing to say about the guards (they partition the domain), then the
// four guarantees get their verdicts. Today the symbolic engine answers (the explicit one
// refuses real variables).
TEST(ProveFamilies, LunarSortie) {
  TempMission scratch({});
  const auto family = bench::generate_lunar(scratch.dir() / "lunar");
  const gate::Outcome outcome = gated(family.dir);
  EXPECT_TRUE(outcome.passed()) << format_text(outcome.report.findings);
  EXPECT_TRUE(outcome.report.findings.empty()) << format_text(outcome.report.findings);
  EXPECT_EQ(compiled_nodes(outcome.compiled_xml), static_cast<std::size_t>(family.tree_nodes));
  EXPECT_NE(outcome.compiled_xml.find("<ReactiveFallback name=\"traverse\">"), std::string::npos);
  EXPECT_NE(outcome.compiled_xml.find("<Fallback name=\"sample\">"), std::string::npos);
  expect_answers(family, outcome);
}

// The two traverse guarantees need the reactive selection the mission declares: compiled in the
// paper's sequence style, a direct drive started on flat sunlit ground in tick 1 runs on
// unchecked in tick 2, whatever slope and light the environment has chosen for it.
TEST(ProveFamilies, LunarSortieInTheSequenceStyle) {
  TempMission scratch({});
  auto family = bench::generate_lunar(scratch.dir() / "lunar");
  family.verdicts["DirectOnFlat"] = family.verdicts["HoldWhenSteep"] = "violated";
  family.violation_ticks["DirectOnFlat"] = family.violation_ticks["HoldWhenSteep"] = 2;
  check_answers(prove_dir(family.dir), family);
}

// The lunar sortie with a reserve the samples raise: every guard and DrillOnCharge compare the
// environment's battery with the mission's own state (`battery >= reserve + 40`). The explicit
// engine cuts the battery in each state it explores (it left the mission to the symbolic engine
// before: "cannot cut real 'battery' into cells"), and gives the sortie's verdicts.
TEST(ProveFamilies, LunarSortieWithAReserve) {
  TempMission scratch({});
  const auto family = bench::generate_lunar_reserve(scratch.dir() / "lunar_reserve");
  EXPECT_NE(read_all(family.dir / "requirements.fret").find("battery >= reserve + 40"),
            std::string::npos);
  EXPECT_NE(read_all(family.dir / "world.json")
                .find("HasSample = true; reserve = reserve < 60 ? reserve + 10 : 60"),
            std::string::npos);
  const gate::Outcome outcome = gated(family.dir);
  EXPECT_TRUE(outcome.passed()) << format_text(outcome.report.findings);
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  expect_answers(family, outcome, explicit_engine);
  // auto takes the explicit engine.
  std::vector<Finding> findings;
  auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  ASSERT_TRUE(doc);
  EXPECT_EQ(prove::prove(*outcome.mission, *doc, prove::mission_world(*outcome.mission), {}).engine,
            "explicit");
}

// The scale checklist's wide selections: a guard of N disjuncts, and an enum of N values of
// which the guard names one. Verdicts as promised, and the same states and transitions whatever
// N is: the explicit engine explores the cells the guard draws, not the values.
TEST(ProveFamilies, AWideSelectionIsProvedOverTheCellsItsGuardDraws) {
  TempMission scratch({});
  const auto answers = [&](const bench::FamilyMission& family) {
    const gate::Outcome outcome = gated(family.dir);
    EXPECT_TRUE(outcome.passed()) << format_text(outcome.report.findings);
    std::vector<Finding> findings;
    auto doc = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
    if (!doc) {
      ADD_FAILURE() << format_text(findings);
      return std::pair<std::uint64_t, std::uint64_t>{};
    }
    const prove::Result r =
        prove::prove(*outcome.mission, *doc, prove::mission_world(*outcome.mission), {});
    check_answers(r, family);
    return std::pair{r.states, r.transitions};
  };
  const auto small = answers(bench::generate_disjunct_site(scratch.dir() / "d20", 20));
  EXPECT_EQ(answers(bench::generate_disjunct_site(scratch.dir() / "d100", 100)), small);
  const auto few = answers(bench::generate_enum_site(scratch.dir() / "e4", 4));
  EXPECT_EQ(answers(bench::generate_enum_site(scratch.dir() / "e100", 100)), few);
}

TEST(ProveFamilies, BadSizesAreRefused) {
  TempMission scratch({});
  EXPECT_THROW(bench::generate_binary_tree(scratch.dir() / "b", 24), std::invalid_argument);
  EXPECT_THROW(bench::generate_checklist(scratch.dir() / "c", 0), std::invalid_argument);
  EXPECT_THROW(bench::generate_preflight(scratch.dir() / "p", 0), std::invalid_argument);
  EXPECT_THROW(bench::generate_recheck(scratch.dir() / "r", 1), std::invalid_argument);
}

}  // namespace
}  // namespace uabt::testing
