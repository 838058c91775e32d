#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "base/diagnostics.hpp"
#include "base/number_text.hpp"
#include "bt/xml_io.hpp"
#include "compile/compile.hpp"
#include "fretish/parse.hpp"
#include "load/mission.hpp"
#include "runtime/selection_probe.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::compile {
namespace {

using uabt::testing::TempMission;

load::Mission load(const std::filesystem::path& dir) {
  std::string error;
  auto m = load::load_mission(dir, {}, error);
  EXPECT_TRUE(m.has_value()) << error;
  EXPECT_FALSE(has_errors(m->findings)) << format_text(m->findings);
  return std::move(*m);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string compiled_text(const load::Mission& m, Options options = {}) {
  Result r = compile_mission(m, options);
  EXPECT_TRUE(r.ok) << format_text(r.findings);
  bt::WriteOptions w;
  w.format = options.bt_format;
  return bt::write_document(r.document, w);
}

// Golden files: tests/compile/golden/<name>.xml. Regenerate with UABT_UPDATE_GOLDEN=1 and
// review the diff: they are what flies.
void expect_golden(const std::string& name, const std::string& actual) {
  const auto path = uabt::testing::source_dir() / "tests/compile/golden" / (name + ".xml");
  if (std::getenv("UABT_UPDATE_GOLDEN") != nullptr) {
    std::ofstream(path, std::ios::binary) << actual;
  }
  EXPECT_EQ(read(path), actual) << "golden " << path.filename();
}

// The paper's Fig. 4 (an explicit --selection sequence overrides the mission's own style).
TEST(CompileGolden, Curiosity) {
  Options options;
  options.selection = SelectionStyle::sequence;
  options.selection_forced = true;
  expect_golden("msl_curiosity",
                compiled_text(load(uabt::testing::mission_dir("msl_curiosity")), options));
}

// msl_curiosity declares <Adaptable ID="navigation" selection="reactive">: without an explicit
// style it compiles to the reactive tree, byte for byte.
TEST(CompileGolden, CuriosityReactive) {
  const std::string declared = compiled_text(load(uabt::testing::mission_dir("msl_curiosity")));
  expect_golden("msl_curiosity_reactive", declared);
  Options options;
  options.selection = SelectionStyle::reactive;
  options.selection_forced = true;
  EXPECT_EQ(compiled_text(load(uabt::testing::mission_dir("msl_curiosity")), options), declared);
}

TEST(CompileGolden, Exploration) {
  expect_golden("exploration", compiled_text(load(uabt::testing::mission_dir("exploration"))));
}

TEST(CompileGolden, ReplicationPackageAsV3) {
  const auto dir = uabt::testing::replication_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "replication package not present";
  Options options;
  options.bt_format = 3;
  expect_golden("replication_v3", compiled_text(load(dir), options));
}

TEST(Compile, SameInputSameBytes) {
  load::Mission m = load(uabt::testing::mission_dir("exploration"));
  EXPECT_EQ(compiled_text(m), compiled_text(m));
}

TEST(Compile, SelectorFollowsPriorityWithDefaultLast) {
  TempMission t({{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
                 {"requirements.fret",
                  "Safe: In nav Mission shall satisfy selected_alt = c\n"
                  "First: In nav if A Mission shall satisfy selected_alt = a\n"
                  "Second: In nav unless A Mission shall satisfy selected_alt = b\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
                 {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")},
                 {"alternatives/nav/c.xml", uabt::testing::alternative_tree("c")}});
  Result r = compile_mission(load(t.dir()), {});
  ASSERT_TRUE(r.ok);
  const bt::TreeDef* main = r.document.find_tree("MainTree");
  ASSERT_NE(main, nullptr);
  EXPECT_EQ(main->root.tag, "SubTree");
  EXPECT_EQ(*main->root.attribute("ID"), "nav");
  EXPECT_EQ(*main->root.attribute("_autoremap"), "true");
  const bt::TreeDef* sel = r.document.find_tree("nav");
  ASSERT_NE(sel, nullptr);
  ASSERT_EQ(sel->root.tag, "Fallback");
  ASSERT_EQ(sel->root.children.size(), 3u);
  EXPECT_EQ(*sel->root.children[0].attribute("name"), "First");
  EXPECT_EQ(*sel->root.children[1].attribute("name"), "Second");
  EXPECT_EQ(*sel->root.children[2].attribute("name"), "Safe");
  EXPECT_EQ(sel->root.children[1].children[0].tag, "Inverter") << "unless A is !A";
  EXPECT_EQ(sel->root.children[2].children.size(), 1u) << "the default has no guard";
  for (const char* id : {"a", "b", "c"}) EXPECT_NE(r.document.find_tree(id), nullptr) << id;
}

// Algorithm 1 on single guards, written as the tree they must become.
struct GuardCase {
  const char* guard;
  const char* tree;  // compact rendering: Tag(children…), leaves by name
};

std::string render(const bt::Node& n) {
  std::string out = n.tag;
  if (const std::string* code = n.attribute("code")) out += "{" + *code + "}";
  if (n.children.empty()) return out;
  out += "(";
  for (std::size_t i = 0; i < n.children.size(); ++i) out += (i ? "," : "") + render(n.children[i]);
  return out + ")";
}

class GuardTree : public ::testing::TestWithParam<GuardCase> {};

TEST_P(GuardTree, BecomesTheExpectedConditionSubtree) {
  fretish::Domain domain;
  std::vector<Finding> findings;
  fretish::parse_domain_file(
      "integer battery in [0, 100]\nreal slope in [-45, 45]\nenum terrain in {sand, rocks}\n"
      "boolean A, B, C\n",
      "domain.fret", findings)
      .variables.swap(domain.variables);
  ASSERT_TRUE(findings.empty()) << format_text(findings);
  auto guard = fretish::parse_expression(GetParam().guard, {"g", 1, 1}, findings);
  ASSERT_NE(guard, nullptr) << format_text(findings);
  EXPECT_EQ(render(guard_to_tree(*guard, domain, SelectionStyle::sequence)), GetParam().tree)
      << GetParam().guard;
}

INSTANTIATE_TEST_SUITE_P(
    Algorithm1, GuardTree,
    ::testing::Values(
        GuardCase{"A", "A"}, GuardCase{"!A", "Inverter(A)"},
        GuardCase{"A & B & C", "Sequence(A,B,C)"}, GuardCase{"(A & B) & C", "Sequence(A,B,C)"},
        GuardCase{"A | !B", "Fallback(A,Inverter(B))"},
        GuardCase{"A & (B | C)", "Sequence(A,Fallback(B,C))"},
        GuardCase{"A -> B", "Fallback(Inverter(A),B)"},
        GuardCase{"A -> B -> C", "Fallback(Inverter(A),Inverter(B),C)"},
        GuardCase{"A xor B", "Fallback(Sequence(A,Inverter(B)),Sequence(Inverter(A),B))"},
        GuardCase{"A <-> B", "Fallback(Sequence(A,B),Sequence(Inverter(A),Inverter(B)))"},
        GuardCase{"A = false", "Inverter(A)"}, GuardCase{"true", "AlwaysSuccess"},
        GuardCase{"battery < 20", "ScriptCondition{battery < 20}"},
        GuardCase{"terrain = rocks", "ScriptCondition{terrain == 'rocks'}"},
        GuardCase{"!(slope >= -15.5)", "Inverter(ScriptCondition{slope >= -15.5})"},
        GuardCase{"battery - (10 - 2) > 0", "ScriptCondition{battery - (10 - 2) > 0}"},
        GuardCase{"A & battery * 2 >= 40 + 1",
                  "Sequence(A,ScriptCondition{battery * 2 >= 40 + 1})"},
        // BT.CPP's == holds within float epsilon: an equality of reals is two exact orderings.
        GuardCase{"slope = 0.5",
                  "Sequence(ScriptCondition{slope >= 0.5},ScriptCondition{slope <= 0.5})"},
        GuardCase{"slope != battery",
                  "Fallback(ScriptCondition{slope < battery},ScriptCondition{slope > battery})"},
        GuardCase{"battery = 3", "ScriptCondition{battery == 3}"},
        GuardCase{"slope / 2 > 1", "ScriptCondition{slope / 2 > 1}"}));

TEST(Compile, GuardsWithoutScriptEquivalentAreRefused) {
  TempMission t({{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
                 {"domain.fret", "integer battery in [0, 100]\n"},
                 {"requirements.fret",
                  "R: In nav if battery mod 2 = 0 Mission shall satisfy selected_alt = a\n"
                  "D: In nav Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")}});
  Result r = compile_mission(load(t.dir()), {});
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].check, "compile-unsupported");
  EXPECT_EQ(r.findings[0].location.line, 1);
}

// FRETISH divides integers truncating, a BT.CPP script divides them as doubles: no script
// means `battery / 2 > 1`, so the compiler refuses it rather than emit `battery / 2 > 1`,
// which holds at battery = 3 where the guard does not.
TEST(Compile, IntegerDivisionInAGuardIsRefused) {
  TempMission t({{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
                 {"domain.fret", "integer battery in [0, 100]\n"},
                 {"requirements.fret",
                  "R: In nav if battery / 2 > 1 Mission shall satisfy selected_alt = a\n"
                  "D: In nav Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")}});
  Result r = compile_mission(load(t.dir()), {});
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].check, "compile-unsupported");
  EXPECT_EQ(r.findings[0].message,
            "requirement R: 'battery / 2' divides integers, which FRETISH truncates (7 / 2 is 3) "
            "and a BehaviorTree.CPP script divides as doubles (7 / 2 is 3.5); write the guard "
            "without the division (x / 2 > 1 is x > 3 for x >= 0) or divide a real");
  EXPECT_EQ(r.findings[0].location.column, 11);  // the guard's `if`
}

// The compiled tree selects as the requirements say within float epsilon of a real constant,
// where BT.CPP's `slope == 0.5` would hold and the guard `slope = 0.5` does not.
TEST(Compile, AnEqualityOfRealsSelectsExactlyInTheEngine) {
  TempMission t({{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
                 {"domain.fret", "real slope in [-45, 45]\n"},
                 {"requirements.fret",
                  "Flat: In nav if slope = 0.5 Mission shall satisfy selected_alt = a\n"
                  "Other: In nav Mission shall satisfy selected_alt = b\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
                 {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")}});
  Result r = compile_mission(load(t.dir()), {});
  ASSERT_TRUE(r.ok) << format_text(r.findings);
  auto started = [&](double slope) {
    const State state{{"slope", Value::of_real(slope, number_text(slope))}};
    return runtime::probe_selection(r.document, "nav", state).first_call;
  };
  EXPECT_EQ(started(0.5), "a");
  EXPECT_EQ(started(0.5 + 1e-7), "b");
  EXPECT_EQ(started(0.5 - 1e-7), "b");
  EXPECT_EQ(started(3), "b");
}

TEST(Compile, V3RefusesScriptConditionGuards) {
  Options options;
  options.bt_format = 3;
  Result r = compile_mission(load(uabt::testing::mission_dir("exploration")), options);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.findings.empty());
  EXPECT_EQ(r.findings[0].check, "compile-unsupported");
  EXPECT_NE(r.findings[0].message.find("v3"), std::string::npos);
}

TEST(Compile, MissionWithErrorsIsNotCompiled) {
  TempMission t(
      {{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
       {"requirements.fret", "R: In nav if A Mission shall satisfy selected_alt = missing\n"}});
  std::string error;
  auto m = load::load_mission(t.dir(), {}, error);
  ASSERT_TRUE(m);
  EXPECT_TRUE(has_errors(m->findings));
  EXPECT_FALSE(compile_mission(*m, {}).ok);
}

TEST(Compile, TraceMapsGuardNodesToRequirementsAndLines) {
  Result r = compile_mission(load(uabt::testing::mission_dir("msl_curiosity")), {});
  ASSERT_TRUE(r.ok);
  bool found = false;
  for (const auto& e : r.trace) {
    if (e.node_path == "navigation/ReactiveFallback/ReactiveSequence[1]/OnRocks[0]") {
      found = true;
      EXPECT_EQ(e.requirement, "Req2");
      EXPECT_EQ(e.source.file, "requirements.fret");
      EXPECT_EQ(e.source.line, 4);
    }
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace uabt::compile
