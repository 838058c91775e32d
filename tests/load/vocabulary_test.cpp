#include <gtest/gtest.h>

#include "load/load_test_support.hpp"

namespace uabt::load {
namespace {

using namespace uabt::testing;

const std::string kTypo =
    "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
    "Req2: In navigation if OnRokcs Mission shall satisfy selected_alt = on_rocks\n";

TEST(Vocabulary, UndeclaredNameIsAnErrorWithDidYouMean) {
  TempMission dir(navigation_files(kTypo, "boolean OnDust, OnRocks\n"));
  Mission m = load_dir(dir.dir());
  const auto undeclared = with_check(m, "ref-undeclared");
  ASSERT_EQ(undeclared.size(), 1u) << format_text(m.findings);
  const Finding& f = *undeclared[0];
  EXPECT_EQ(f.severity, Severity::error);
  EXPECT_EQ(f.message, "'OnRokcs' in requirement Req2 is not declared in domain.fret");
  EXPECT_EQ(f.location.file, "requirements.fret");
  EXPECT_EQ(f.location.line, 2);
  EXPECT_EQ(f.location.column, 24);
  ASSERT_FALSE(f.notes.empty());
  EXPECT_EQ(f.notes[0], "did you mean 'OnRocks'?");
  // The typo never becomes a condition, and the node's guards are not checked.
  EXPECT_EQ(m.domain.find("OnRokcs"), nullptr);
  ASSERT_EQ(m.not_verified.count("navigation"), 1u);
  EXPECT_EQ(m.not_verified.at("navigation"), "requirement Req2 reads the undeclared 'OnRokcs'");
}

TEST(Vocabulary, DeclaredNamesPass) {
  TempMission dir(navigation_files(kTwoTerrains, "boolean OnDust, OnRocks\n"));
  Mission m = load_dir(dir.dir());
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
  EXPECT_TRUE(m.not_verified.empty());
}

TEST(Vocabulary, NodesXmlConditionsAreDeclaredBooleans) {
  auto files = navigation_files(kTypo);
  files["nodes.xml"] =
      "<root BTCPP_format=\"4\"><TreeNodesModel>\n"
      "  <Condition ID=\"OnDust\"/>\n  <Condition ID=\"OnRocks\"/>\n  <Action ID=\"Stop\"/>\n"
      "</TreeNodesModel></root>\n";
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  const auto undeclared = with_check(m, "ref-undeclared");
  ASSERT_EQ(undeclared.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(undeclared[0]->message, "'OnRokcs' in requirement Req2 is not declared in nodes.xml");
  EXPECT_EQ(undeclared[0]->notes[0], "did you mean 'OnRocks'?");
  EXPECT_TRUE(with_check(m, "ref-unknown-condition").empty()) << "one mistake, one finding";
  ASSERT_NE(m.domain.find("OnDust"), nullptr) << "a nodes.xml condition is a boolean";
}

TEST(Vocabulary, AssumptionWithUndeclaredNameStopsEveryNode) {
  TempMission dir(
      navigation_files(kTwoTerrains, "boolean OnDust, OnRocks\nassume one: !(OnDust & OnRoks)\n"));
  Mission m = load_dir(dir.dir());
  const auto undeclared = with_check(m, "ref-undeclared");
  ASSERT_EQ(undeclared.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(undeclared[0]->location.file, "domain.fret");
  EXPECT_EQ(undeclared[0]->location.line, 2);
  EXPECT_EQ(m.not_verified.at("navigation"), "assumption 'one' reads the undeclared 'OnRoks'");
  EXPECT_TRUE(m.domain.assumptions.empty()) << "a broken assumption leaves the domain";
}

// FRET's predefined FTP is not an undeclared name: a property reads it as FRET does; in a
// guard or an assumption (a condition of one state) it is refused by name, with or without a
// declared vocabulary, and never becomes a condition.
TEST(Vocabulary, FretsFirstTimePointIsFretsNotATypo) {
  const std::string requirements =
      "Req1: In navigation if OnDust & FTP Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
      "Start: the rover shall always satisfy FTP -> !OnDust\n";
  for (const std::string& domain :
       {std::string("boolean OnDust, OnRocks\nassume first: FTP -> !OnRocks\n"), std::string()}) {
    SCOPED_TRACE(domain);
    TempMission dir(domain.empty() ? navigation_files(requirements)
                                   : navigation_files(requirements, domain));
    Mission m = load_dir(dir.dir());
    EXPECT_TRUE(with_check(m, "ref-undeclared").empty()) << format_text(m.findings);
    EXPECT_TRUE(with_check(m, "ref-similar-name").empty()) << format_text(m.findings);
    const auto refused = with_check(m, "fretish-unsupported");
    ASSERT_EQ(refused.size(), domain.empty() ? 1u : 2u) << format_text(m.findings);
    EXPECT_EQ(format_text({*refused.back()}),
              "requirements.fret:1:33: error: FRET's first time point 'FTP' in requirement Req1 "
              "has no meaning here: a selection guard is a condition of the state the tree ticks "
              "in [fretish-unsupported]\n"
              "requirements.fret:1:33: note: state what holds at the first tick in a mission "
              "property, e.g. 'the rover shall always satisfy FTP -> battery = 100', which uabt "
              "monitor and uabt run check\n");
    if (!domain.empty()) {
      EXPECT_EQ(refused[0]->message,
                "FRET's first time point 'FTP' in assumption 'first' has no meaning here: an "
                "assumption holds in every state");
      EXPECT_EQ(refused[0]->location.file, "domain.fret");
      EXPECT_EQ(refused[0]->location.line, 2);
      EXPECT_TRUE(m.domain.assumptions.empty());
    }
    EXPECT_EQ(m.domain.find("FTP"), nullptr) << "FTP never becomes a condition";
    EXPECT_EQ(m.not_verified.count("navigation"), 1u);
  }
}

TEST(Vocabulary, UnusedDeclaredVariableIsAWarning) {
  TempMission dir(navigation_files(kTwoTerrains, "boolean OnDust, OnRocks, OnSand\n"));
  Mission m = load_dir(dir.dir());
  const auto unused = with_check(m, "domain-unused-variable");
  ASSERT_EQ(unused.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(unused[0]->severity, Severity::warning);
  EXPECT_EQ(unused[0]->message,
            "variable 'OnSand' is declared but no guard, assumption, requirement or tree reads it");
  EXPECT_EQ(unused[0]->location.line, 1);
  EXPECT_EQ(unused[0]->location.column, 26);
  EXPECT_FALSE(has_errors(m.findings));
}

TEST(Vocabulary, AVariableTheTreeReadsIsUsed) {
  auto files =
      navigation_files(kTwoTerrains, "boolean OnDust, OnRocks\ninteger battery in [0, 100]\n");
  files["mission.xml"] = mission_with(
      "    <Sequence>\n      <ScriptCondition code=\"battery &gt; 20\"/>\n"
      "      <Adaptable ID=\"navigation\"/>\n    </Sequence>");
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  EXPECT_TRUE(with_check(m, "domain-unused-variable").empty()) << format_text(m.findings);
}

TEST(Vocabulary, WithoutVocabularyANearNameIsAWarningNamingBoth) {
  TempMission dir(navigation_files(
      "Req1: In navigation if OnRocks Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRokcs & OnDust Mission shall satisfy selected_alt = on_rocks\n"
      "Req3: In navigation if OnRocks & !OnDust Mission shall satisfy selected_alt = on_rocks\n"));
  Mission m = load_dir(dir.dir());
  const auto similar = with_check(m, "ref-similar-name");
  ASSERT_EQ(similar.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(similar[0]->severity, Severity::warning);
  EXPECT_EQ(similar[0]->message,
            "'OnRokcs' in requirement Req2 is 1 edit away from 'OnRocks': without domain.fret or "
            "nodes.xml it becomes a new condition of its own");
  EXPECT_EQ(similar[0]->location.line, 2);
  EXPECT_EQ(similar[0]->location.column, 24);
  EXPECT_NE(m.domain.find("OnRokcs"), nullptr) << "still inferred: the mission declares nothing";
  EXPECT_TRUE(m.not_verified.empty());
}

TEST(Vocabulary, WithoutVocabularyDistinctNamesAreQuiet) {
  TempMission dir(navigation_files(kTwoTerrains));
  Mission m = load_dir(dir.dir());
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
}

TEST(Vocabulary, ShippedMissionsDeclareEverythingTheyUse) {
  for (const char* name : {"msl_curiosity", "msl_curiosity_paper", "exploration"}) {
    Mission m = load_dir(uabt::testing::mission_dir(name));
    EXPECT_TRUE(with_check(m, "ref-undeclared").empty()) << name << format_text(m.findings);
    EXPECT_TRUE(with_check(m, "ref-similar-name").empty()) << name << format_text(m.findings);
    EXPECT_TRUE(with_check(m, "domain-unused-variable").empty()) << name;
  }
}

TEST(Vocabulary, UplinkWithItsOwnDeclarationLoads) {
  std::string error;
  LoadOptions options;
  options.uplinks = {uabt::testing::mission_dir("msl_curiosity") / "uplinks/on_sand_ambiguous"};
  auto m = load_mission(uabt::testing::mission_dir("msl_curiosity"), options, error);
  ASSERT_TRUE(m.has_value()) << error;
  EXPECT_TRUE(with_check(*m, "ref-undeclared").empty()) << format_text(m->findings);
}

}  // namespace
}  // namespace uabt::load

namespace uabt::load {
namespace {

TEST(Vocabulary, NumberedSeriesAreNotTypos) {
  uabt::testing::TempMission dir(uabt::testing::navigation_files(
      "Req1: In navigation if Zone1 Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if Zone2 Mission shall satisfy selected_alt = on_rocks\n"));
  Mission m = uabt::testing::load_dir(dir.dir());
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
}

}  // namespace
}  // namespace uabt::load
