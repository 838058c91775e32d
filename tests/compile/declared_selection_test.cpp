// <Adaptable selection="sequence|reactive|optimized">: a mission declares how each adaptable
// node selects; an explicit --selection (Options::selection_forced) overrides it.
#include <gtest/gtest.h>

#include <string>

#include "base/diagnostics.hpp"
#include "compile/compile.hpp"
#include "load/mission.hpp"
#include "temp_mission.hpp"

namespace uabt::compile {
namespace {

using uabt::testing::TempMission;

TempMission two_nodes(const std::string& nav_attributes, const std::string& arm_attributes) {
  return TempMission(
      {{"mission.xml",
        uabt::testing::mission_with("<Sequence><Adaptable ID=\"nav\"" + nav_attributes +
                                    "/><Adaptable ID=\"arm\"" + arm_attributes + "/></Sequence>")},
       {"requirements.fret",
        "N1: In nav if Fast Mission shall satisfy selected_alt = a\n"
        "N2: In nav Mission shall satisfy selected_alt = b\n"
        "A: In arm Mission shall satisfy selected_alt = c\n"},
       {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
       {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")},
       {"alternatives/arm/c.xml", uabt::testing::alternative_tree("c")}});
}

load::Mission load_or_fail(const TempMission& t) {
  std::string error;
  auto m = load::load_mission(t.dir(), {}, error);
  EXPECT_TRUE(m) << error;
  return m ? std::move(*m) : load::Mission{};
}

const bt::TreeDef* tree(const Result& r, const std::string& id) {
  for (const auto& t : r.document.trees)
    if (t.id == id) return &t;
  return nullptr;
}

TEST(DeclaredSelection, EachNodeCompilesInTheStyleItDeclares) {
  const TempMission t = two_nodes(" selection=\"reactive\"", "");
  const load::Mission m = load_or_fail(t);
  const Result r = compile_mission(m, {});
  ASSERT_TRUE(r.ok) << format_text(r.findings);
  ASSERT_TRUE(tree(r, "nav") && tree(r, "arm"));
  EXPECT_EQ(tree(r, "nav")->root.tag, "ReactiveFallback");
  EXPECT_EQ(tree(r, "nav")->root.children.front().tag, "ReactiveSequence");
  EXPECT_EQ(tree(r, "arm")->root.tag, "Fallback") << "a node that declares nothing: the default";
  // The attribute never reaches the compiled tree.
  for (const auto& def : r.document.trees)
    for (const auto& c : def.root.children) EXPECT_EQ(c.attribute("selection"), nullptr);

  Options forced;
  forced.selection = SelectionStyle::sequence;
  forced.selection_forced = true;
  const Result sequence = compile_mission(m, forced);
  ASSERT_TRUE(sequence.ok);
  EXPECT_EQ(tree(sequence, "nav")->root.tag, "Fallback") << "an explicit style overrides it";

  Options reactive_default;
  reactive_default.selection = SelectionStyle::reactive;
  EXPECT_EQ(tree(compile_mission(m, reactive_default), "arm")->root.tag, "ReactiveFallback");
}

TEST(DeclaredSelection, ABadValueIsAFindingAtTheNode) {
  const TempMission t = two_nodes(" selection=\"lazy\"", "");
  const load::Mission m = load_or_fail(t);
  int found = 0;
  for (const auto& f : m.findings) {
    if (f.check != "bt-structure") continue;
    ++found;
    EXPECT_NE(f.message.find("selection=\"lazy\" is not a selection style"), std::string::npos)
        << f.message;
    EXPECT_EQ(f.location.line, 3) << "the <Adaptable> element's line";
  }
  EXPECT_EQ(found, 1) << format_text(m.findings);
}

TEST(DeclaredSelection, OneNodeHasOneStyle) {
  TempMission t({{"mission.xml", uabt::testing::mission_with(
                                     "<Sequence><Adaptable ID=\"nav\" selection=\"reactive\"/>"
                                     "<Adaptable ID=\"nav\"/></Sequence>")},
                 {"requirements.fret", "N: In nav Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")}});
  const load::Mission m = load_or_fail(t);
  int found = 0;
  for (const auto& f : m.findings)
    if (f.check == "bt-structure" &&
        f.message.find("one node has one selection style") != std::string::npos)
      ++found;
  EXPECT_EQ(found, 1) << format_text(m.findings);
}

}  // namespace
}  // namespace uabt::compile
