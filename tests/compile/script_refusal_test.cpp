// A script BehaviorTree.CPP would not parse is refused when the mission loads (so by compile and
// verify), at the attribute that holds it, in the words the engine uses when it builds the tree;
// and what the checks accept, the engine builds.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "bt/script/load_check.hpp"
#include "load/load_test_support.hpp"
#include "runtime/engine.hpp"
#include "runtime/runtime_test_support.hpp"

namespace uabt::compile {
namespace {

using namespace uabt::testing;

const std::string kRequirements =
    "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
    "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n";

std::string engine_refusal(const load::Mission& m, const std::string& alternative) {
  for (const auto& alt : m.alternatives) {
    if (alt.name != alternative) continue;
    runtime::testing::ScriptedWorld world;
    try {
      runtime::Engine::build(alt.document, alt.tree_id, world);
    } catch (const runtime::LoadError& e) {
      return e.what();
    }
    return "";
  }
  return "no alternative " + alternative;
}

// A script too deeply nested to parse, 2,000 disjuncts long, is refused in one readable line:
// the part of the script around the column where parsing stopped, not 30,000 characters.
TEST(ScriptRefusal, ALongScriptIsQuotedAroundWhereItFails) {
  std::string code;
  for (int k = 0; k < 2000; ++k) code += (k ? " || depth == " : "depth == ") + std::to_string(k);
  const auto why = bt::script::script_refusal("ScriptCondition", code, true);
  ASSERT_TRUE(why.has_value());
  EXPECT_EQ(*why,
            "ScriptCondition: the script `… == 124 || depth == 125 || depth == 126 || depth == "
            "127 || depth == 128 || depth…` does not parse: expression nested deeper than 128 "
            "levels (column 1920)");
  // A short script is quoted whole; an excerpt never cuts a character in two.
  EXPECT_EQ(*bt::script::script_refusal("Script", "x := (1", false),
            "Script: the script `x := (1` does not parse: expected ')', found end of script "
            "(column 8)");
  const std::string wide = "é := " + std::string(60, '1') + " + ((((" + std::string(60, '2');
  const auto cut = bt::script::script_refusal("Script", "ééééééééééééééééééééééééé" + wide, false);
  ASSERT_TRUE(cut.has_value());
  for (std::size_t i = 0; i + 1 < cut->size(); ++i) {
    if ((static_cast<unsigned char>((*cut)[i]) & 0xE0) == 0xC0) {
      EXPECT_EQ(static_cast<unsigned char>((*cut)[i + 1]) & 0xC0, 0x80) << *cut;
    }
  }
  // The character the parser stops at is quoted whole, or named by its value.
  EXPECT_EQ(*bt::script::script_refusal("Script", "x := é", false),
            "Script: the script `x := é` does not parse: unexpected character 'é' (column 6)");
  EXPECT_TRUE(bt::script::script_refusal("Script", "x := \xC3", false)
                  ->ends_with("does not parse: unexpected byte 0xC3 (column 6)"));
}

TEST(ScriptRefusal, AnAlternativesBrokenScriptIsRefusedWhereTheEngineRefusesIt) {
  auto files = navigation_files(kRequirements, "boolean OnDust, OnRocks\n");
  files["alternatives/navigation/on_dust.xml"] =
      alternative_tree("on_dust",
                       "<Sequence>\n      <Stop _skipIf=\"OnDust &amp;&amp;\"/>\n"
                       "      <Script code=\"speed := (1\"/>\n    </Sequence>");
  files["alternatives/navigation/on_rocks.xml"] = alternative_tree(
      "on_rocks", "<Sequence>\n      <ScriptCondition code=\"\"/>\n      <Stop/>\n    </Sequence>");
  TempMission dir(files);
  const load::Mission m = load_dir(dir.dir());
  std::vector<Finding> refused;
  for (const Finding& f : m.findings)
    if (f.check == "bt-structure") refused.push_back(f);
  EXPECT_EQ(format_text(refused),
            "alternatives/navigation/on_dust.xml:4:13: error: Stop _skipIf: the script "
            "`OnDust &&` does not parse: expected an operand, found end of script (column 10) "
            "[bt-structure]\n"
            "alternatives/navigation/on_dust.xml:5:15: error: Script: the script `speed := (1` "
            "does not parse: expected ')', found end of script (column 12) [bt-structure]\n"
            "alternatives/navigation/on_rocks.xml:4:24: error: ScriptCondition with an empty "
            "script has no result [bt-structure]\n");
  // The engine refuses the first of them, at the same place, in the same words.
  EXPECT_EQ(engine_refusal(m, "on_dust"),
            "alternatives/navigation/on_dust.xml:4:13: Stop _skipIf: the script `OnDust &&` does "
            "not parse: expected an operand, found end of script (column 10)");
  EXPECT_EQ(engine_refusal(m, "on_rocks"),
            "alternatives/navigation/on_rocks.xml:4:24: ScriptCondition with an empty script has "
            "no result");
}

TEST(ScriptRefusal, ScriptsTheChecksAcceptTheEngineBuilds) {
  auto files = navigation_files(kRequirements, "boolean OnDust, OnRocks\n");
  files["alternatives/navigation/on_dust.xml"] = alternative_tree(
      "on_dust",
      "<Sequence _onSuccess=\"done := true\">\n      <Script code=\"\"/>\n"
      "      <Script code=\"a := b := 3; c = 'x' .. 'y'\"/>\n"
      "      <Stop _skipIf=\"OnDust &amp;&amp; !OnRocks\" _post=\"n := 1\"/>\n    </Sequence>");
  TempMission dir(files);
  const load::Mission m = load_dir(dir.dir());
  for (const Finding& f : m.findings) EXPECT_NE(f.check, "bt-structure") << format_text({f});
  EXPECT_EQ(engine_refusal(m, "on_dust"), "");
}

}  // namespace
}  // namespace uabt::compile
