// One mistake, one finding: what a broken input makes unknowable is not reported as known.
#include <gtest/gtest.h>

#include "load/load_test_support.hpp"

namespace uabt::load {
namespace {

using namespace uabt::testing;

std::vector<std::string> checks_of(const Mission& m) {
  std::vector<std::string> ids;
  for (const auto& f : m.findings) ids.push_back(f.check);
  return ids;
}

TEST(Cascade, ASyntaxErrorIsTheOnlyFinding) {
  TempMission dir(navigation_files(
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shal satisfy selected_alt = on_rocks\n"));
  Mission m = load_dir(dir.dir());
  EXPECT_EQ(checks_of(m), std::vector<std::string>{"fretish-syntax"}) << format_text(m.findings);
  EXPECT_EQ(m.not_verified.at("navigation"),
            "the requirement at requirements.fret:2 does not parse");
}

TEST(Cascade, AnUnparsedLineNamingNoNodeStopsEveryNode) {
  TempMission dir(
      navigation_files("Req1: In navigaton if OnDust Mission shal satisfy x\n"
                       "Req2: In navigation if OnRocks Mission shall satisfy "
                       "selected_alt = on_rocks\n"));
  Mission m = load_dir(dir.dir());
  EXPECT_EQ(checks_of(m), std::vector<std::string>{"fretish-syntax"}) << format_text(m.findings);
  EXPECT_EQ(m.not_verified.count("navigation"), 1u);
}

TEST(Cascade, MalformedAlternativeIsNotAMissingOne) {
  auto files = navigation_files(kTwoTerrains);
  files["alternatives/navigation/on_rocks.xml"] =
      "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"on_rocks\">\n";
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  EXPECT_EQ(checks_of(m), std::vector<std::string>{"bt-xml"}) << format_text(m.findings);
}

TEST(Cascade, UnknownAlternativeNamesThePathAndTheClosestName) {
  TempMission dir(navigation_files(
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dsut\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
      "Req3: In navigation Mission shall satisfy selected_alt = on_dust\n"));
  Mission m = load_dir(dir.dir());
  const auto unknown = with_check(m, "ref-unknown-alternative");
  ASSERT_EQ(unknown.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(unknown[0]->message,
            "requirement Req1 selects 'on_dsut', but there is no file "
            "alternatives/navigation/on_dsut.xml");
  EXPECT_EQ(unknown[0]->notes, std::vector<std::string>{"did you mean 'on_dust'?"});
}

TEST(Cascade, UnknownScopeSuggestsTheNode) {
  TempMission dir(navigation_files(
      kTwoTerrains + "Req3: In navigaton Mission shall satisfy selected_alt = on_dust\n"));
  Mission m = load_dir(dir.dir());
  const auto unknown = with_check(m, "ref-unknown-adaptable");
  ASSERT_EQ(unknown.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(unknown[0]->notes, std::vector<std::string>{"did you mean 'navigation'?"});
}

TEST(Cascade, LowercaseIdIsOneFindingThatSaysSo) {
  auto files = navigation_files(kTwoTerrains);
  files["mission.xml"] = mission_with(
      "    <Sequence>\n      <Adaptable id=\"navigation\"/>\n      <Stop/>\n    </Sequence>");
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  ASSERT_EQ(checks_of(m), std::vector<std::string>{"bt-structure"}) << format_text(m.findings);
  EXPECT_EQ(m.findings[0].message,
            "<Adaptable> needs an ID: attribute names are case-sensitive, write "
            "ID=\"navigation\" instead of id=\"navigation\"");
}

TEST(Cascade, EmptyRangeStopsTheNodesThatReadIt) {
  auto files = navigation_files(
      "Req1: In navigation if y > 3 Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if y < 3 Mission shall satisfy selected_alt = on_rocks\n",
      "integer y in [4, 2]\n");
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  EXPECT_EQ(checks_of(m), std::vector<std::string>{"domain-invalid"}) << format_text(m.findings);
  EXPECT_EQ(m.not_verified.at("navigation"),
            "the declaration of 'y' is invalid (domain.fret:1: range of 'y' is empty: lower "
            "bound 4 exceeds upper bound 2)");
}

TEST(Cascade, AnInvalidVariableTiedByAnAssumptionStopsTheNodeToo) {
  auto files = navigation_files(
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n",
      "boolean OnDust, OnRocks\ninteger y in [4, 2]\nassume tie: OnDust -> y > 3\n");
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  EXPECT_EQ(m.not_verified.count("navigation"), 1u) << format_text(m.findings);
}

TEST(Cascade, StrayAlternativeAndSecondRequirementsFileAreReported) {
  auto files = navigation_files(kTwoTerrains);
  files["alternatives/on_mud.xml"] = alternative_tree("on_mud");
  files["requirements.json"] = "[]";
  TempMission dir(files);
  Mission m = load_dir(dir.dir());
  const auto ignored = with_check(m, "load-ignored-file");
  ASSERT_EQ(ignored.size(), 2u) << format_text(m.findings);
  EXPECT_EQ(ignored[0]->location.file, "alternatives/on_mud.xml");
  EXPECT_EQ(ignored[0]->notes,
            std::vector<std::string>{"move it to alternatives/navigation/on_mud.xml"});
  EXPECT_EQ(ignored[1]->message,
            "both requirements.fret and requirements.json exist: uabt reads requirements.fret "
            "and ignores requirements.json");
  EXPECT_FALSE(has_errors(m.findings));
}

}  // namespace
}  // namespace uabt::load

namespace uabt::load {
namespace {

TEST(Cascade, ABrokenDomainLineIsNotFollowedByUndeclaredNames) {
  uabt::testing::TempMission dir(uabt::testing::navigation_files(
      uabt::testing::kTwoTerrains, "boolean OnDust,\nbolean OnRocks\n"));
  Mission m = uabt::testing::load_dir(dir.dir());
  EXPECT_TRUE(uabt::testing::with_check(m, "ref-undeclared").empty()) << format_text(m.findings);
  EXPECT_FALSE(uabt::testing::with_check(m, "fretish-syntax").empty());
  EXPECT_EQ(m.not_verified.count("navigation"), 1u);
}

}  // namespace
}  // namespace uabt::load
