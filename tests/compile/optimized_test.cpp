// --selection optimized: what it emits, what it costs (checked by ticking the engine), and that
// it never costs more than Algorithm 1's layout.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>

#include "base/diagnostics.hpp"
#include "bt/xml_io.hpp"
#include "compile/compile.hpp"
#include "conform/conform.hpp"
#include "load/mission.hpp"
#include "selection_check.hpp"
#include "selection_missions.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::compile {
namespace {

using uabt::testing::TempMission;

load::Mission load_clean(const std::filesystem::path& dir) {
  std::string error;
  auto m = load::load_mission(dir, {}, error);
  EXPECT_TRUE(m.has_value()) << error;
  EXPECT_FALSE(has_errors(m->findings)) << format_text(m->findings);
  return std::move(*m);
}

Result compile_with(const load::Mission& m, SelectionStyle style) {
  Options options;
  options.selection = style;
  options.selection_forced = true;
  Result r = compile_mission(m, options);
  EXPECT_TRUE(r.ok) << format_text(r.findings);
  return r;
}

const bt::Node& selection_root(const Result& r, const std::string& adaptable) {
  const bt::TreeDef* t = r.document.find_tree(adaptable);
  EXPECT_NE(t, nullptr);
  return t->root;
}

int count_nodes(const bt::Node& n, const std::function<bool(const bt::Node&)>& pred) {
  int k = pred(n) ? 1 : 0;
  for (const auto& c : n.children) k += count_nodes(c, pred);
  return k;
}

// The compiler's own count equals the engine's, for both layouts, and both start the
// required alternative in every cell.
void expect_counts_match_engine(const load::Mission& m, const std::string& adaptable) {
  const Result fig4 = compile_with(m, SelectionStyle::sequence);
  const Result opt = compile_with(m, SelectionStyle::optimized);
  ASSERT_EQ(opt.selection_stats.size(), 1u);
  const SelectionStats& s = opt.selection_stats.front();
  const auto by_engine_fig4 = testing::engine_count(m, fig4.document, adaptable);
  const auto by_engine_opt = testing::engine_count(m, opt.document, adaptable);
  EXPECT_EQ(by_engine_fig4.mismatch, "");
  EXPECT_EQ(by_engine_opt.mismatch, "");
  EXPECT_NEAR(by_engine_fig4.cost.average, s.algorithm1.average, 1e-9);
  EXPECT_EQ(by_engine_fig4.cost.worst, s.algorithm1.worst);
  EXPECT_NEAR(by_engine_opt.cost.average, s.optimized.average, 1e-9);
  EXPECT_EQ(by_engine_opt.cost.worst, s.optimized.worst);
  // Never more than Algorithm 1's layout.
  EXPECT_LE(s.optimized.average, s.algorithm1.average + 1e-9);
}

TEST(OptimizedSelection, BatteryLadderIsABinarySearch) {
  TempMission t(testing::battery_ladder_files(16));
  const load::Mission m = load_clean(t.dir());
  const Result r = compile_with(m, SelectionStyle::optimized);
  ASSERT_EQ(r.selection_stats.size(), 1u);
  const SelectionStats& s = r.selection_stats.front();
  EXPECT_TRUE(s.optimized_used) << s.reason;
  // The figure: Fig. 4 ticks about 17 conditions on average over the battery reading;
  // the decision structure at most half of that, and 5 at most (16 bands and what lies above).
  EXPECT_GT(s.algorithm1.average, 15.0);
  EXPECT_LE(s.optimized.average, s.algorithm1.average / 2);
  EXPECT_LE(s.optimized.worst, 6);
  EXPECT_EQ(selection_root(r, "power").tag, "IfThenElse");
  expect_counts_match_engine(m, "power");
}

TEST(OptimizedSelection, EnumTestsHalvesOfTheLiterals) {
  TempMission t(testing::terrain_enum_files(16));
  const load::Mission m = load_clean(t.dir());
  const Result r = compile_with(m, SelectionStyle::optimized);
  const SelectionStats& s = r.selection_stats.front();
  EXPECT_TRUE(s.optimized_used) << s.reason;
  EXPECT_DOUBLE_EQ(s.optimized.average, 4.0);  // 16 literals, 4 halvings: the optimum
  EXPECT_EQ(s.optimized.worst, 4);
  EXPECT_DOUBLE_EQ(s.algorithm1.average, 135.0 / 16);  // 1 + 2 + ... + 15, and 15 for the default
  EXPECT_LE(s.optimized.average, s.algorithm1.average / 2);
  // A half is one ScriptCondition: "terrain == 't0' || terrain == 't1' || ...".
  EXPECT_GT(count_nodes(selection_root(r, "drive"),
                        [](const bt::Node& n) {
                          const std::string* code = n.attribute("code");
                          return code && code->find("||") != std::string::npos;
                        }),
            0);
  expect_counts_match_engine(m, "drive");
}

TEST(OptimizedSelection, LargeEnumTestsNameAtMost32Literals) {
  TempMission t(testing::terrain_enum_files(100));
  const load::Mission m = load_clean(t.dir());
  const Result r = compile_with(m, SelectionStyle::optimized);
  const SelectionStats& s = r.selection_stats.front();
  EXPECT_TRUE(s.optimized_used) << s.reason;
  EXPECT_LE(s.optimized.average, s.algorithm1.average / 2);
  std::size_t most = 0;
  count_nodes(selection_root(r, "drive"), [&](const bt::Node& n) {
    if (const std::string* code = n.attribute("code")) {
      std::size_t literals = 1, at = 0;
      while ((at = code->find("||", at)) != std::string::npos) ++literals, at += 2;
      most = std::max(most, literals);
    }
    return false;
  });
  EXPECT_GT(most, 1u);
  EXPECT_LE(most, 32u);
  expect_counts_match_engine(m, "drive");
}

TEST(OptimizedSelection, AssumptionsDropChecks) {
  TempMission t(testing::assumed_cover_files());
  const load::Mission m = load_clean(t.dir());
  const Result r = compile_with(m, SelectionStyle::optimized);
  const SelectionStats& s = r.selection_stats.front();
  EXPECT_TRUE(s.optimized_used) << s.reason;
  // OnDust | OnRocks always holds: when OnDust fails, OnRocks need not be ticked.
  EXPECT_EQ(
      count_nodes(selection_root(r, "nav"), [](const bt::Node& n) { return n.tag == "OnRocks"; }),
      0);
  EXPECT_DOUBLE_EQ(s.optimized.average, 1.0);
  EXPECT_EQ(s.optimized.worst, 1);
  expect_counts_match_engine(m, "nav");
}

TEST(OptimizedSelection, ShippedMissionsNeverCostMore) {
  for (const char* name : {"msl_curiosity", "msl_curiosity_paper", "exploration"}) {
    SCOPED_TRACE(name);
    const load::Mission m = load_clean(testing::mission_dir(name));
    for (const auto& site : m.adaptables) expect_counts_match_engine(m, site.id);
  }
}

TEST(OptimizedSelection, EveryLeafNamesItsRequirementInTreeAndTrace) {
  const load::Mission m = load_clean(testing::mission_dir("exploration"));
  const Result r = compile_with(m, SelectionStyle::optimized);
  ASSERT_TRUE(r.selection_stats.front().optimized_used);
  int leaves = 0;
  std::function<void(const bt::Node&, const std::string&)> visit = [&](const bt::Node& n,
                                                                       const std::string& path) {
    if (n.tag == "SubTree") {
      ++leaves;
      const auto it = std::find_if(r.trace.begin(), r.trace.end(),
                                   [&](const TraceEntry& e) { return e.node_path == path; });
      ASSERT_NE(it, r.trace.end()) << path;
      EXPECT_FALSE(it->requirement.empty()) << path;
      EXPECT_EQ(it->atom.rfind("selected_alt = ", 0), 0u) << it->atom;
    }
    for (std::size_t i = 0; i < n.children.size(); ++i)
      visit(n.children[i], path + "/" + n.children[i].tag + "[" + std::to_string(i) + "]");
  };
  const bt::Node& root = selection_root(r, "exploration");
  visit(root, "exploration/" + root.tag);
  EXPECT_GE(leaves, 3);
  // Each leaf is wrapped in a Sequence named after its requirement.
  EXPECT_GT(count_nodes(root,
                        [](const bt::Node& n) {
                          const std::string* name = n.attribute("name");
                          return n.tag == "Sequence" && name && *name == "Sand";
                        }),
            0);
}

TEST(OptimizedSelection, SameBytesEveryTime) {
  const load::Mission m = load_clean(testing::mission_dir("exploration"));
  const Result a = compile_with(m, SelectionStyle::optimized);
  const Result b = compile_with(m, SelectionStyle::optimized);
  EXPECT_EQ(bt::write_document(a.document, {}), bt::write_document(b.document, {}));
}

// Optimized chooses the layout, not the reactivity: a node that declares selection="reactive"
// gets a decision that is re-checked every tick (WhileDoElse), which still selects the
// required alternative in every cell and conforms by meaning.
TEST(OptimizedSelection, KeepsADeclaredReactiveSelection) {
  auto files = testing::mission_files("exploration");
  const std::string declared = "<Adaptable ID=\"exploration\"/>";
  auto& xml = files["mission.xml"];
  ASSERT_NE(xml.find(declared), std::string::npos);
  xml.replace(xml.find(declared), declared.size(),
              "<Adaptable ID=\"exploration\" selection=\"reactive\"/>");
  const TempMission t(files, "exploration");
  const load::Mission m = load_clean(t.dir());
  const Result r = compile_with(m, SelectionStyle::optimized);
  ASSERT_TRUE(r.selection_stats.front().optimized_used);
  const bt::Node& root = selection_root(r, "exploration");
  EXPECT_EQ(root.tag, "WhileDoElse");
  EXPECT_EQ(count_nodes(root, [](const bt::Node& n) { return n.tag == "IfThenElse"; }), 0);
  EXPECT_GT(count_nodes(root, [](const bt::Node& n) { return n.tag == "WhileDoElse"; }), 1);
  EXPECT_EQ(testing::engine_count(m, r.document, "exploration").mismatch, "");
  const conform::Result c = conform::conform_tree(m, r.document, {});
  EXPECT_FALSE(has_errors(c.findings)) << format_text(c.findings);

  // Without the declaration the same command keeps the tick-once IfThenElse.
  const load::Mission plain = load_clean(testing::mission_dir("exploration"));
  EXPECT_EQ(selection_root(compile_with(plain, SelectionStyle::optimized), "exploration").tag,
            "IfThenElse");
}

// One requirement that holds in every state, beside one that holds in none (R1's guard is
// unsatisfiable) or alone (its guard always true): the decision structure tests nothing and
// runs that requirement's alternative, named after it below a selector named after the node.
std::map<std::string, std::string> one_requirement_holds_files(bool beside_unsatisfiable) {
  std::map<std::string, std::string> files;
  files["mission.xml"] = testing::mission_with("    <Adaptable ID=\"navigation\"/>");
  files["alternatives/navigation/a.xml"] = testing::alternative_tree("a");
  files["alternatives/navigation/b.xml"] = testing::alternative_tree("b");
  if (beside_unsatisfiable) {
    files["domain.fret"] = "integer battery in [0, 100]\n";
    files["requirements.fret"] =
        "R1: In navigation if battery > 80 & battery < 20 Mission shall satisfy selected_alt = "
        "a\n"
        "R2: In navigation Mission shall satisfy selected_alt = b\n";
  } else {
    files["domain.fret"] = "integer x in [-3, 0]\n";
    files["requirements.fret"] =
        "R2: In navigation if !(x = 1) Mission shall satisfy selected_alt = b\n";
  }
  return files;
}

TEST(OptimizedSelection, ARequirementThatHoldsEverywhereIsSelectedWithoutATest) {
  for (const bool beside_unsatisfiable : {true, false})
    for (const bool reactive : {false, true}) {
      SCOPED_TRACE(std::string(beside_unsatisfiable ? "beside R1" : "alone") +
                   (reactive ? ", declared reactive" : ""));
      auto files = one_requirement_holds_files(beside_unsatisfiable);
      if (reactive)
        files["mission.xml"] =
            testing::mission_with("    <Adaptable ID=\"navigation\" selection=\"reactive\"/>");
      const TempMission t(files);
      std::string error;
      const auto m = load::load_mission(t.dir(), {}, error);
      ASSERT_TRUE(m.has_value()) << error;
      const Result r = compile_with(*m, SelectionStyle::optimized);
      ASSERT_EQ(r.selection_stats.size(), 1u);
      EXPECT_TRUE(r.selection_stats.front().optimized_used) << r.selection_stats.front().reason;
      EXPECT_EQ(r.selection_stats.front().optimized.worst, 0);
      const bt::Node& root = selection_root(r, "navigation");
      ASSERT_EQ(root.tag, "Sequence");
      ASSERT_NE(root.attribute("name"), nullptr);
      EXPECT_EQ(*root.attribute("name"), "navigation");
      ASSERT_EQ(root.children.size(), 1u);
      const bt::Node& leaf = root.children.front();
      ASSERT_NE(leaf.attribute("name"), nullptr);
      EXPECT_EQ(*leaf.attribute("name"), "R2");
      // The trace names R2 at its leaf and at the call of its alternative.
      const std::string call_path = "navigation/Sequence/Sequence[0]/SubTree[0]";
      const auto call = std::find_if(r.trace.begin(), r.trace.end(),
                                     [&](const TraceEntry& e) { return e.node_path == call_path; });
      ASSERT_NE(call, r.trace.end());
      EXPECT_EQ(call->requirement, "R2");
      EXPECT_EQ(call->atom, "selected_alt = b");
      // The engine starts b in every state, ticking no condition; the tree conforms.
      const auto by_engine = testing::engine_count(*m, r.document, "navigation");
      EXPECT_EQ(by_engine.mismatch, "");
      EXPECT_EQ(by_engine.cost.worst, 0);
      const conform::Result c = conform::conform_tree(*m, r.document, {});
      EXPECT_FALSE(has_errors(c.findings)) << format_text(c.findings);
    }
}

}  // namespace
}  // namespace uabt::compile
