#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "load/mission.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::load {
namespace {

using uabt::testing::TempMission;

Mission load_ok(const std::filesystem::path& dir) {
  std::string error;
  auto m = load_mission(dir, {}, error);
  EXPECT_TRUE(m.has_value()) << error;
  return m ? std::move(*m) : Mission{};
}

std::vector<std::string> checks_of(const Mission& m) {
  std::vector<std::string> ids;
  for (const auto& f : m.findings) ids.push_back(f.check);
  return ids;
}

TEST(LoadMission, CuriosityLoadsWithoutFindings) {
  Mission m = load_ok(uabt::testing::mission_dir("msl_curiosity"));
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
  EXPECT_EQ(m.layout, "uabt");
  ASSERT_EQ(m.adaptables.size(), 1u);
  EXPECT_EQ(m.adaptables[0].id, "navigation");
  EXPECT_EQ(m.adaptables[0].location.file, "mission.xml");
  EXPECT_GT(m.adaptables[0].location.line, 0);
  auto selections = m.selections_for("navigation");
  ASSERT_EQ(selections.size(), 3u);
  EXPECT_EQ(selections[0]->alternative, "on_dust");
  EXPECT_EQ(selections[1]->alternative, "on_rocks");
  EXPECT_EQ(selections[2]->alternative, "hold_position");
  EXPECT_EQ(selections[2]->guard, nullptr);
  EXPECT_EQ(m.alternatives.size(), 3u);
  ASSERT_NE(m.domain.find("OnDust"), nullptr);
  EXPECT_TRUE(m.domain.find("OnDust")->declared);
  EXPECT_EQ(m.domain.assumptions.size(), 1u);
}

TEST(LoadMission, PaperMissionInfersItsConditionsAsBooleans) {
  Mission m = load_ok(uabt::testing::mission_dir("msl_curiosity_paper"));
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
  const fretish::Variable* dust = m.domain.find("OnDust");
  ASSERT_NE(dust, nullptr);
  EXPECT_EQ(dust->type, fretish::VarType::boolean);
  EXPECT_FALSE(dust->declared);
  EXPECT_EQ(dust->location.file, "requirements.fret");
}

TEST(LoadMission, ExplorationHasNumericAndEnumDomain) {
  Mission m = load_ok(uabt::testing::mission_dir("exploration"));
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
  ASSERT_NE(m.domain.find("battery"), nullptr);
  EXPECT_EQ(m.domain.find("battery")->type, fretish::VarType::integer);
  EXPECT_EQ(m.domain.find("slope")->type, fretish::VarType::real);
  EXPECT_EQ(m.domain.find("terrain")->type, fretish::VarType::enumeration);
  EXPECT_EQ(m.domain.find("sand"), nullptr) << "an enum literal is not a variable";
  EXPECT_EQ(m.selections_for("exploration").size(), 3u);
}

TEST(LoadMission, ReplicationPackageLoadsAsItIs) {
  const auto dir = uabt::testing::replication_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "replication package not present";
  Mission m = load_ok(dir);
  EXPECT_EQ(m.layout, "replication");
  EXPECT_TRUE(m.findings.empty()) << format_text(m.findings);
  ASSERT_EQ(m.alternatives.size(), 2u) << "the generator's *_conditions.xml are not alternatives";
  const Alternative* alt1 = m.find_alternative("navigation", "alt1");
  ASSERT_NE(alt1, nullptr);
  EXPECT_EQ(alt1->tree_id, "dust_terrain");
  EXPECT_EQ(m.find_alternative("navigation", "alt2")->tree_id, "rock_terrain");
  auto selections = m.selections_for("navigation");
  ASSERT_EQ(selections.size(), 2u);
  EXPECT_EQ(selections[0]->alternative, "alt1");
  EXPECT_EQ(fretish::to_fretish(*selections[0]->guard), "OnDust");
  EXPECT_EQ(fretish::to_fretish(*selections[1]->guard), "OnRock");
  EXPECT_NE(selections[0]->id, selections[1]->id) << "empty FRET reqids get distinct ids";
}

TEST(LoadMission, NotADirectoryIsAnError) {
  std::string error;
  EXPECT_FALSE(load_mission("/nonexistent/mission", {}, error).has_value());
  EXPECT_FALSE(error.empty());
}

const char* kNav = "    <Sequence><Adaptable ID=\"navigation\"/></Sequence>";

TEST(References, UnknownAdaptableAndAlternative) {
  TempMission t(
      {{"mission.xml", uabt::testing::mission_with(kNav)},
       {"requirements.fret",
        "Req1: In navigaton if OnDust Mission shall satisfy selected_alt = on_dust\n"
        "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rock\n"
        "Safe: In navigation Mission shall satisfy selected_alt = on_dust\n"},
       {"alternatives/navigation/on_dust.xml", uabt::testing::alternative_tree("on_dust")}});
  Mission m = load_ok(t.dir());
  ASSERT_EQ(m.findings.size(), 2u) << format_text(m.findings);
  EXPECT_EQ(m.findings[0].check, "ref-unknown-adaptable");
  EXPECT_EQ(m.findings[0].location.line, 1);
  EXPECT_EQ(m.findings[1].check, "ref-unknown-alternative");
  EXPECT_EQ(m.findings[1].location.line, 2);
  EXPECT_EQ(m.findings[1].location.column, 69) << "points at the alternative's name";
}

TEST(References, UnresolvedAdaptableOrphanAndMultipleDefaults) {
  TempMission t(
      {{"mission.xml",
        uabt::testing::mission_with(
            "    <Sequence><Adaptable ID=\"navigation\"/><Adaptable ID=\"sampling\"/></Sequence>")},
       {"requirements.fret",
        "A: In navigation Mission shall satisfy selected_alt = on_dust\n"
        "B: In navigation Mission shall satisfy selected_alt = on_dust\n"},
       {"alternatives/navigation/on_dust.xml", uabt::testing::alternative_tree("on_dust")},
       {"alternatives/navigation/spare.xml", uabt::testing::alternative_tree("spare")}});
  Mission m = load_ok(t.dir());
  auto ids = checks_of(m);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "ref-adaptable-unresolved"), 1);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "ref-orphan-alternative"), 1);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "ref-multiple-defaults"), 1);
  for (const auto& f : m.findings)
    if (f.check == "ref-orphan-alternative") {
      EXPECT_EQ(f.severity, Severity::warning);
    }
  EXPECT_EQ(m.selections_for("navigation").size(), 1u) << "only the first default counts";
}

TEST(References, DuplicateRequirementAndTreeIds) {
  TempMission t(
      {{"mission.xml", uabt::testing::mission_with(kNav)},
       {"requirements.fret",
        "Req1: In navigation if OnDust Mission shall satisfy selected_alt = a\n"
        "Req1: In navigation Mission shall satisfy selected_alt = b\n"},
       {"alternatives/navigation/a.xml", uabt::testing::alternative_tree("Shared", "<Stop/>")},
       {"alternatives/navigation/b.xml", uabt::testing::alternative_tree("Shared", "<Drill/>")}});
  Mission m = load_ok(t.dir());
  auto ids = checks_of(m);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "ref-duplicate-id"), 2) << format_text(m.findings);
}

TEST(References, ConditionsMustBeRobotNodesWhenNodesXmlIsGiven) {
  TempMission t({{"mission.xml", uabt::testing::mission_with(kNav)},
                 {"requirements.fret",
                  "Req1: In navigation if OnDust & !OnMud Mission shall satisfy selected_alt = a\n"
                  "Safe: In navigation Mission shall satisfy selected_alt = a\n"},
                 // OnMud is declared (a blackboard value), but the robot has no such condition.
                 {"domain.fret", "boolean OnDust, OnMud\n"},
                 {"nodes.xml",
                  "<root BTCPP_format=\"4\"><TreeNodesModel><Condition ID=\"OnDust\"/>"
                  "<Action ID=\"Stop\"/></TreeNodesModel></root>\n"},
                 {"alternatives/navigation/a.xml", uabt::testing::alternative_tree("a")}});
  Mission m = load_ok(t.dir());
  ASSERT_EQ(m.findings.size(), 1u) << format_text(m.findings);
  EXPECT_EQ(m.findings[0].check, "ref-unknown-condition");
  EXPECT_NE(m.findings[0].message.find("OnMud"), std::string::npos);
  EXPECT_EQ(m.findings[0].location.column, 34);
}

TEST(References, MissingRequirementsFileIsAFinding) {
  TempMission t({{"mission.xml", uabt::testing::mission_with(kNav)}});
  Mission m = load_ok(t.dir());
  auto ids = checks_of(m);
  EXPECT_NE(std::find(ids.begin(), ids.end(), "load-file"), ids.end());
}

}  // namespace
}  // namespace uabt::load

namespace uabt::load {
namespace {

TEST(Uplink, MudUplinkIsMergedAboveTheDefault) {
  std::string error;
  LoadOptions options;
  const auto dir = uabt::testing::mission_dir("msl_curiosity");
  options.uplinks.push_back(dir / "uplinks" / "on_mud");
  auto m = load_mission(dir, options, error);
  ASSERT_TRUE(m) << error;
  // The merge says where Req3 went, and that HoldOnUnknown (restated for mud) replaced the
  // mission's property of the same id.
  ASSERT_EQ(m->findings.size(), 2u) << format_text(m->findings);
  EXPECT_EQ(m->findings[0].check, "uplink-merge");
  EXPECT_NE(m->findings[0].message.find("Req3"), std::string::npos);
  EXPECT_EQ(m->findings[1].check, "uplink-merge");
  EXPECT_NE(m->findings[1].message.find("HoldOnUnknown: replaces"), std::string::npos);
  bool restated = false;
  for (const auto& p : m->properties)
    restated |= p.id == "HoldOnUnknown" && p.location.file == "uplinks/on_mud/requirements.fret";
  EXPECT_TRUE(restated);
  auto selections = m->selections_for("navigation");
  ASSERT_EQ(selections.size(), 4u);
  EXPECT_EQ(selections[2]->id, "Req3");
  EXPECT_EQ(selections[2]->location.file, "uplinks/on_mud/requirements.fret");
  EXPECT_EQ(selections[3]->alternative, "hold_position") << "the default stays last";
  ASSERT_NE(m->find_alternative("navigation", "on_mud"), nullptr);
  EXPECT_EQ(m->find_alternative("navigation", "on_mud")->file,
            "uplinks/on_mud/alternatives/navigation/on_mud.xml");
  EXPECT_NE(m->domain.find("OnMud"), nullptr);
  EXPECT_EQ(m->domain.assumptions.size(), 2u);
  EXPECT_EQ(m->uplinks, std::vector<std::string>{"uplinks/on_mud"});
}

TEST(Uplink, SameIdReplacesARequirementInPlace) {
  TempMission t({{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
                 {"requirements.fret",
                  "A: In nav if X Mission shall satisfy selected_alt = a\n"
                  "B: In nav if Y Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
                 {"uplinks/fix/requirements.fret",
                  "A: In nav if X & !Y Mission shall satisfy selected_alt = a\n"}});
  std::string error;
  LoadOptions options;
  options.uplinks.push_back(t.dir() / "uplinks" / "fix");
  auto m = load_mission(t.dir(), options, error);
  ASSERT_TRUE(m) << error;
  auto selections = m->selections_for("nav");
  ASSERT_EQ(selections.size(), 2u);
  EXPECT_EQ(selections[0]->id, "A");
  EXPECT_EQ(fretish::to_fretish(*selections[0]->guard), "X & !Y");
}

TEST(Uplink, EmptyOrMissingPackageIsAFinding) {
  TempMission t({{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
                 {"requirements.fret", "A: In nav Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
                 {"uplinks/empty/README", "nothing here\n"}});
  std::string error;
  LoadOptions options;
  options.uplinks = {t.dir() / "uplinks" / "empty", t.dir() / "uplinks" / "missing"};
  auto m = load_mission(t.dir(), options, error);
  ASSERT_TRUE(m) << error;
  ASSERT_EQ(m->findings.size(), 2u) << format_text(m->findings);
  EXPECT_EQ(m->findings[0].check, "load-file");
  EXPECT_EQ(m->findings[1].check, "load-file");
}

}  // namespace
}  // namespace uabt::load
