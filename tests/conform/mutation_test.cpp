// Mutation testing of the conformance checker: every mutant that departs from the
// requirements must be caught (some error finding), every equivalent rewrite accepted.
#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "conform_test_util.hpp"
#include "guard_oracle.hpp"
#include "guarded_mission.hpp"
#include "mutator.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

using mutation::Kind;

struct Tally {
  int mutants = 0;
  int must_catch = 0;  // non-equivalent (or a deviation from the prescribed shape)
  int caught = 0;
  int must_accept = 0;  // equivalent rewrites
  int accepted = 0;
  int behaviour_preserving_deviations = 0;  // e.g. reordered branches with disjoint guards
};

using Tallies = std::map<std::string, Tally>;

Tallies& overall() {
  static Tallies t;
  return t;
}

std::string rate(int num, int den) {
  if (den == 0) return "-";
  std::ostringstream out;
  out << num << "/" << den << " (" << std::fixed << std::setprecision(1) << 100.0 * num / den
      << "%)";
  return out.str();
}

void print(const std::string& title, const Tallies& tallies) {
  std::cout << "\nMutation kill rate — " << title << "\n"
            << std::left << std::setw(30) << "operator" << std::setw(8) << "mutants"
            << std::setw(22) << "killed/non-equiv." << std::setw(22) << "accepted/equiv."
            << "caught but behaviour-preserving\n";
  Tally sum;
  for (const auto& op : mutation::operator_names()) {
    const auto it = tallies.find(op);
    if (it == tallies.end()) continue;
    const Tally& t = it->second;
    std::cout << std::left << std::setw(30) << op << std::setw(8) << t.mutants << std::setw(22)
              << rate(t.caught, t.must_catch) << std::setw(22) << rate(t.accepted, t.must_accept)
              << t.behaviour_preserving_deviations << "\n";
    sum.mutants += t.mutants;
    sum.must_catch += t.must_catch;
    sum.caught += t.caught;
    sum.must_accept += t.must_accept;
    sum.accepted += t.accepted;
    sum.behaviour_preserving_deviations += t.behaviour_preserving_deviations;
  }
  std::cout << std::left << std::setw(30) << "total" << std::setw(8) << sum.mutants << std::setw(22)
            << rate(sum.caught, sum.must_catch) << std::setw(22)
            << rate(sum.accepted, sum.must_accept) << sum.behaviour_preserving_deviations << "\n";
}

// Prints the table over every subject that ran in this process.
class OverallReport : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!overall().empty()) print("all subjects", overall());
  }
};
const auto* const kOverallReport = ::testing::AddGlobalTestEnvironment(new OverallReport);

struct Subject {
  std::string name;
  load::Mission mission;
  bt::Document compiled;
};

enum class Source { shipped, replication, guarded };

struct Case {
  const char* name;
  Source source;
  const char* mission;
  compile::SelectionStyle style;
};

// The rules that may rightly catch a mutant of each operator: a mutant caught only by some
// unrelated rule would hide a gap in the rule meant for it.
const std::set<std::string>& expected_checks(const std::string& op) {
  static const std::set<std::string> guard = {"compiled-guard-mismatch", "bt-structure"};
  static const std::map<std::string, std::set<std::string>> table = {
      {"reorder-branches", {"compiled-order"}},
      {"negate-guard", guard},
      {"remove-inverter", guard},
      {"drop-guard", guard},
      {"drop-guard-leaf", guard},
      {"drop-conjunct", guard},
      {"rename-atom", guard},
      {"swap-guards", guard},
      {"change-kind-guard", guard},
      {"change-script-operator", {"compiled-guard-mismatch", "compiled-fixed-part-changed"}},
      {"change-script-constant", {"compiled-guard-mismatch", "compiled-fixed-part-changed"}},
      {"drop-branch", {"compiled-missing-alternative"}},
      {"duplicate-branch", {"compiled-missing-alternative"}},
      {"change-attribute-alternative",
       {"compiled-alternative-mismatch", "compiled-dangling-subtree"}},
      {"change-attribute-fixed", {"compiled-fixed-part-changed"}},
      {"change-kind-fixed", {"compiled-fixed-part-changed"}},
      {"change-kind-alternative", {"compiled-alternative-mismatch"}},
      {"break-arity", {"bt-structure"}},
      {"dangle-subtree", {"compiled-dangling-subtree"}},
      {"reinsert-adaptable", {"compiled-adaptable-left"}},
  };
  static const std::set<std::string> none;
  const auto it = table.find(op);
  return it == table.end() ? none : it->second;
}

mutation::Layout layout_of(const load::Mission& m) {
  mutation::Layout layout;
  for (const auto& site : m.adaptables)
    if (std::find(layout.adaptables.begin(), layout.adaptables.end(), site.id) ==
        layout.adaptables.end())
      layout.adaptables.push_back(site.id);
  for (const auto& t : m.tree.trees) layout.fixed_trees.insert(t.id);
  for (const auto& alt : m.alternatives)
    for (const auto& t : alt.document.trees) layout.alternative_trees.insert(t.id);
  return layout;
}

class Mutation : public ::testing::TestWithParam<Case> {};

TEST_P(Mutation, EveryDeviationCaughtEveryRewriteAccepted) {
  const Case& c = GetParam();
  std::optional<TempMission> temp;
  load::Mission m;
  bt::Document compiled;
  switch (c.source) {
    case Source::shipped:
      m = load_or_fail(mission_dir(c.mission));
      compiled = compile_or_fail(m, c.style);
      break;
    case Source::replication: {
      if (!std::filesystem::exists(replication_dir())) GTEST_SKIP() << "no replication package";
      m = load_or_fail(replication_dir());
      std::vector<Finding> read_findings;
      auto doc = bt::read_document(replication_dir() / "output" / "concrete_mission.xml", {},
                                   read_findings);
      ASSERT_TRUE(doc.has_value());
      compiled = std::move(*doc);
      break;
    }
    case Source::guarded:
      temp.emplace(guarded_mission_files(), "guarded");
      m = load_or_fail(temp->dir());
      compiled = compile_or_fail(m, c.style);
      break;
  }
  ASSERT_FALSE(has_errors(m.findings)) << describe(m.findings);
  const auto baseline = conform::conform_tree(m, compiled);
  ASSERT_TRUE(baseline.findings.empty()) << describe(baseline.findings);

  const mutation::Layout layout = layout_of(m);
  const auto mutants = mutation::all_mutants(compiled, layout);
  ASSERT_FALSE(mutants.empty());
  Tallies tallies;
  for (const auto& mutant : mutants) {
    SCOPED_TRACE(mutant.op + ": " + mutant.description);
    Tally& t = tallies[mutant.op];
    ++t.mutants;
    bool must_catch = mutant.kind == Kind::deviation;
    std::string oracle_reason;
    if (mutant.kind != Kind::deviation) {
      const auto verdict =
          oracle::same_guards(compiled, mutant.document, layout.adaptables, m.domain);
      if (mutant.kind == Kind::rewrite) {
        ASSERT_TRUE(verdict.equivalent)
            << "the mutator's rewrite changes a guard: " << verdict.reason;
      }
      must_catch = !verdict.equivalent;
      oracle_reason = verdict.reason;
    } else if (mutant.op == "reorder-branches" &&
               oracle::same_selection(compiled, mutant.document, layout.adaptables, m.domain)) {
      ++t.behaviour_preserving_deviations;
    }
    const auto result = conform::conform_tree(m, mutant.document);
    const bool caught = has_errors(result.findings);
    if (must_catch) {
      ++t.must_catch;
      t.caught += caught ? 1 : 0;
      EXPECT_TRUE(caught) << "not caught (" << oracle_reason << ")\n" << describe(result.findings);
      const auto& expected = expected_checks(mutant.op);
      EXPECT_TRUE(std::any_of(result.findings.begin(), result.findings.end(),
                              [&](const Finding& f) { return expected.count(f.check) > 0; }))
          << "caught, but not by the rule for this operator\n"
          << describe(result.findings);
    } else {
      ++t.must_accept;
      t.accepted += caught ? 0 : 1;
      EXPECT_FALSE(caught) << "equivalent but rejected\n" << describe(result.findings);
    }
  }
  print(c.name, tallies);
  int must_catch = 0, caught = 0, must_accept = 0, accepted = 0;
  for (const auto& [op, t] : tallies) {
    Tally& all = overall()[op];
    all.mutants += t.mutants;
    all.must_catch += t.must_catch;
    all.caught += t.caught;
    all.must_accept += t.must_accept;
    all.accepted += t.accepted;
    all.behaviour_preserving_deviations += t.behaviour_preserving_deviations;
    must_catch += t.must_catch;
    caught += t.caught;
    must_accept += t.must_accept;
    accepted += t.accepted;
  }
  RecordProperty("mutants", static_cast<int>(mutants.size()));
  for (const auto& [op, t] : tallies)
    RecordProperty(op, "killed " + rate(t.caught, t.must_catch) + ", accepted " +
                           rate(t.accepted, t.must_accept));
  RecordProperty("killed", rate(caught, must_catch));
  RecordProperty("accepted", rate(accepted, must_accept));
  EXPECT_EQ(caught, must_catch);
  EXPECT_EQ(accepted, must_accept);
  EXPECT_GT(must_catch, 0);
  EXPECT_GT(must_accept, 0);
}

INSTANTIATE_TEST_SUITE_P(
    Subjects, Mutation,
    ::testing::Values(
        Case{"msl_curiosity_sequence", Source::shipped, "msl_curiosity",
             compile::SelectionStyle::sequence},
        Case{"msl_curiosity_reactive", Source::shipped, "msl_curiosity",
             compile::SelectionStyle::reactive},
        Case{"msl_curiosity_paper_sequence", Source::shipped, "msl_curiosity_paper",
             compile::SelectionStyle::sequence},
        Case{"msl_curiosity_paper_reactive", Source::shipped, "msl_curiosity_paper",
             compile::SelectionStyle::reactive},
        Case{"exploration_sequence", Source::shipped, "exploration",
             compile::SelectionStyle::sequence},
        Case{"exploration_reactive", Source::shipped, "exploration",
             compile::SelectionStyle::reactive},
        Case{"replication_generated", Source::replication, "", compile::SelectionStyle::sequence},
        Case{"guarded_sequence", Source::guarded, "", compile::SelectionStyle::sequence},
        Case{"guarded_reactive", Source::guarded, "", compile::SelectionStyle::reactive}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace uabt::testing
