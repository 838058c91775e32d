// The uplink merge (DESIGN §11): the one function behind `gate --uplink`, `diff --uplink` and
// `run`. Priority order after each rule, uplink.json's placements and removals, and its errors.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "load/mission.hpp"
#include "load/uplink.hpp"
#include "temp_mission.hpp"

namespace uabt::load {
namespace {

using uabt::testing::TempMission;

// Three guarded requirements and a default on node "nav", and a second node "arm".
std::map<std::string, std::string> base_mission() {
  return {
      {"mission.xml", uabt::testing::mission_with(
                          "<Sequence><Adaptable ID=\"nav\"/><Adaptable ID=\"arm\"/></Sequence>")},
      {"requirements.fret",
       "Req1: In nav if X Mission shall satisfy selected_alt = a\n"
       "Req2: In nav if Y Mission shall satisfy selected_alt = b\n"
       "Req3: In nav if Z Mission shall satisfy selected_alt = a\n"
       "Safe: In nav Mission shall satisfy selected_alt = b\n"
       "Arm1: In arm Mission shall satisfy selected_alt = c\n"},
      {"domain.fret", "boolean X, Y, Z, W\n"},
      {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
      {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")},
      {"alternatives/arm/c.xml", uabt::testing::alternative_tree("c")}};
}

Mission merge(const TempMission& t, const std::string& package = "uplinks/u") {
  std::string error;
  LoadOptions options;
  options.uplinks.push_back(t.dir() / package);
  auto m = load_mission(t.dir(), options, error);
  EXPECT_TRUE(m.has_value()) << error;
  return m ? std::move(*m) : Mission{};
}

std::vector<std::string> order(const Mission& m, const std::string& node = "nav") {
  std::vector<std::string> ids;
  for (const auto* s : m.selections_for(node)) ids.push_back(s->id);
  return ids;
}

std::vector<const Finding*> of_check(const Mission& m, const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : m.findings)
    if (f.check == check) out.push_back(&f);
  return out;
}

const UplinkMerge* record(const Mission& m, const std::string& id) {
  for (const auto& r : m.merges)
    if (r.requirement == id) return &r;
  return nullptr;
}

TEST(UplinkMerge, NewIdGoesLastBeforeTheDefaultAndSaysSo) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Storm: In nav if W Mission shall satisfy selected_alt = b\n");
  Mission m = merge(t);
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  EXPECT_EQ(order(m), (std::vector<std::string>{"Req1", "Req2", "Req3", "Storm", "Safe"}));
  const UplinkMerge* r = record(m, "Storm");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->rule, "appended");
  EXPECT_EQ(r->adaptable, "nav");
  EXPECT_EQ(r->priority, 4);
  EXPECT_EQ(r->of, 5);
  auto notes = of_check(m, "uplink-merge");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0]->severity, Severity::note);
  EXPECT_EQ(notes[0]->location.file, "uplinks/u/requirements.fret");
  EXPECT_EQ(notes[0]->location.line, 1);
  EXPECT_NE(notes[0]->message.find("goes last before the default (priority 4 of 5 in nav)"),
            std::string::npos)
      << notes[0]->message;
}

TEST(UplinkMerge, ExistingIdIsReplacedInPlace) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Req2: In nav if Y & !X Mission shall satisfy selected_alt = b\n");
  Mission m = merge(t);
  EXPECT_EQ(order(m), (std::vector<std::string>{"Req1", "Req2", "Req3", "Safe"}));
  EXPECT_EQ(fretish::to_fretish(*m.selections_for("nav")[1]->guard), "Y & !X");
  ASSERT_NE(record(m, "Req2"), nullptr);
  EXPECT_EQ(record(m, "Req2")->rule, "replaced");
  EXPECT_EQ(record(m, "Req2")->priority, 2);
}

TEST(UplinkMerge, PlacementBeforeAndAfterSetThePriority) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Storm: In nav if W Mission shall satisfy selected_alt = b\n"
          "Gust: In nav if W & X Mission shall satisfy selected_alt = a\n");
  t.write("uplinks/u/uplink.json",
          "{\"place\": {\"Storm\": {\"before\": \"Req2\"}, \"Gust\": {\"after\": \"Req1\"}}}\n");
  Mission m = merge(t);
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  // Storm before Req2 first, then Gust right after Req1 (so between Req1 and Storm).
  EXPECT_EQ(order(m), (std::vector<std::string>{"Req1", "Gust", "Storm", "Req2", "Req3", "Safe"}));
  const UplinkMerge* storm = record(m, "Storm");
  ASSERT_NE(storm, nullptr);
  EXPECT_EQ(storm->rule, "placed");
  EXPECT_EQ(storm->relation, "before");
  EXPECT_EQ(storm->anchor, "Req2");
  EXPECT_EQ(storm->priority, 3);
  EXPECT_EQ(record(m, "Gust")->priority, 2);
}

TEST(UplinkMerge, AMissionRequirementCanBeMoved) {
  TempMission t(base_mission());
  t.write("uplinks/u/uplink.json", "{\"place\": {\"Req3\": {\"before\": \"Req1\"}}}");
  Mission m = merge(t);
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  EXPECT_EQ(order(m), (std::vector<std::string>{"Req3", "Req1", "Req2", "Safe"}));
  ASSERT_NE(record(m, "Req3"), nullptr);
  EXPECT_EQ(record(m, "Req3")->rule, "placed");
  EXPECT_EQ(record(m, "Req3")->location.file, "uplinks/u/uplink.json");
}

TEST(UplinkMerge, RemovalTakesARequirementOut) {
  TempMission t(base_mission());
  t.write("uplinks/u/uplink.json", "{\n  \"remove\": [\"Req2\"]\n}\n");
  Mission m = merge(t);
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  EXPECT_EQ(order(m), (std::vector<std::string>{"Req1", "Req3", "Safe"}));
  const UplinkMerge* r = record(m, "Req2");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->rule, "removed");
  EXPECT_EQ(r->adaptable, "nav");
  EXPECT_EQ(r->location.line, 2);
  EXPECT_EQ(r->location.column, 14);
}

TEST(UplinkMerge, UnknownIdsAreErrorsWithDidYouMean) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Storm: In nav if W Mission shall satisfy selected_alt = b\n");
  t.write("uplinks/u/uplink.json",
          "{\"place\": {\"Strom\": {\"before\": \"Req1\"}, \"Storm\": {\"after\": \"Reqq2\"}},\n"
          " \"remove\": [\"Saf\"]}\n");
  Mission m = merge(t);
  auto errors = of_check(m, "uplink-invalid");
  ASSERT_EQ(errors.size(), 3u) << format_text(m.findings);
  for (const auto* e : errors) {
    EXPECT_EQ(e->severity, Severity::error);
    EXPECT_EQ(e->location.file, "uplinks/u/uplink.json");
    ASSERT_EQ(e->notes.size(), 1u) << e->message;
  }
  // Sorted by position: "Strom" (1:12), "Reqq2" (1:60), "Saf" (2:13).
  EXPECT_NE(errors[0]->message.find("places 'Strom'"), std::string::npos) << errors[0]->message;
  EXPECT_EQ(errors[0]->location.line, 1);
  EXPECT_EQ(errors[0]->location.column, 12);
  EXPECT_EQ(errors[0]->notes[0], "did you mean 'Storm'?");
  EXPECT_NE(errors[1]->message.find("after 'Reqq2'"), std::string::npos) << errors[1]->message;
  EXPECT_EQ(errors[1]->notes[0], "did you mean 'Req2', 'Req1', 'Req3'?");
  EXPECT_NE(errors[2]->message.find("removes 'Saf'"), std::string::npos);
  EXPECT_EQ(errors[2]->location.line, 2);
  EXPECT_EQ(errors[2]->notes[0], "did you mean 'Safe'?");
  // What failed changes nothing: Storm keeps the default rule.
  EXPECT_EQ(order(m), (std::vector<std::string>{"Req1", "Req2", "Req3", "Storm", "Safe"}));
}

TEST(UplinkMerge, MalformedUplinkJsonIsAnErrorWithItsPosition) {
  TempMission t(base_mission());
  t.write("uplinks/u/uplink.json", "{\"place\": {\"Req3\": {\"before\": \"Req1\"}\n");
  Mission m = merge(t);
  auto errors = of_check(m, "uplink-invalid");
  ASSERT_EQ(errors.size(), 1u) << format_text(m.findings);
  EXPECT_NE(errors[0]->message.find("uplink.json: invalid JSON"), std::string::npos);
  EXPECT_EQ(errors[0]->location.line, 2);
}

TEST(UplinkMerge, ShapeMistakesAreNamed) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Storm: In nav if W Mission shall satisfy selected_alt = b\n");
  t.write("uplinks/u/uplink.json",
          "{\"placement\": {},\n"
          " \"place\": {\"Storm\": {\"before\": \"Req1\", \"after\": \"Req2\"},\n"
          "           \"Req1\": {\"above\": \"Req2\"}},\n"
          " \"remove\": [\"Storm\", 3]}\n");
  Mission m = merge(t);
  std::string messages;
  for (const auto* e : of_check(m, "uplink-invalid")) messages += e->message + "\n";
  EXPECT_NE(messages.find("unknown key \"placement\""), std::string::npos) << messages;
  EXPECT_NE(messages.find("'Storm' needs exactly one of"), std::string::npos) << messages;
  EXPECT_NE(messages.find("found \"above\""), std::string::npos) << messages;
  EXPECT_NE(messages.find("removes 'Storm', which this package also uplinks"), std::string::npos)
      << messages;
  EXPECT_NE(messages.find("\"remove\" holds number"), std::string::npos) << messages;
  EXPECT_EQ(of_check(m, "uplink-invalid").size(), 5u) << messages;
}

TEST(UplinkMerge, PlacementAcrossAdaptableNodesIsRefused) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Storm: In nav if W Mission shall satisfy selected_alt = b\n");
  t.write("uplinks/u/uplink.json", "{\"place\": {\"Storm\": {\"before\": \"Arm1\"}}}");
  Mission m = merge(t);
  auto errors = of_check(m, "uplink-invalid");
  ASSERT_EQ(errors.size(), 1u) << format_text(m.findings);
  EXPECT_NE(errors[0]->message.find("priority orders the requirements of one node"),
            std::string::npos);
}

TEST(UplinkMerge, ClosestNamesAreNearAndOrdered) {
  EXPECT_EQ(closest_names("Req9", {"Req1", "Safe", "Req2"}),
            (std::vector<std::string>{"Req1", "Req2"}));
  EXPECT_TRUE(closest_names("navigation", {"Req1", "Safe"}).empty());
  EXPECT_EQ(closest_names("OnDsut", {"OnDust", "OnRocks"}), std::vector<std::string>{"OnDust"});
}

TEST(HitPolicy, PolicyIsReadAndABadValueIsAFinding) {
  TempMission t({{"mission.xml",
                  uabt::testing::mission_with("<Sequence><Adaptable ID=\"nav\" policy=\"first\"/>"
                                              "<Adaptable ID=\"arm\" policy=\"any\"/></Sequence>")},
                 {"requirements.fret",
                  "N: In nav Mission shall satisfy selected_alt = a\n"
                  "A: In arm Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
                 {"alternatives/arm/a.xml", uabt::testing::alternative_tree("a")}});
  std::string error;
  auto m = load_mission(t.dir(), {}, error);
  ASSERT_TRUE(m) << error;
  EXPECT_TRUE(m->first_hit("nav"));
  EXPECT_FALSE(m->first_hit("arm"));
  auto bad = of_check(*m, "bt-structure");
  ASSERT_EQ(bad.size(), 1u) << format_text(m->findings);
  EXPECT_NE(bad[0]->message.find("policy=\"any\" is not a hit policy"), std::string::npos);
}

TEST(HitPolicy, OneNodeHasOnePolicy) {
  TempMission t({{"mission.xml",
                  uabt::testing::mission_with("<Sequence><Adaptable ID=\"nav\" policy=\"first\"/>"
                                              "<Adaptable ID=\"nav\"/></Sequence>")},
                 {"requirements.fret", "N: In nav Mission shall satisfy selected_alt = a\n"},
                 {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")}});
  std::string error;
  auto m = load_mission(t.dir(), {}, error);
  ASSERT_TRUE(m) << error;
  auto bad = of_check(*m, "bt-structure");
  ASSERT_EQ(bad.size(), 1u) << format_text(m->findings);
  EXPECT_NE(bad[0]->message.find("one node has one hit policy"), std::string::npos);
}

}  // namespace
}  // namespace uabt::load
