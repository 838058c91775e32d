// The uplink merge (ARCHITECTURE §11): the one function behind `gate --uplink`, `diff --uplink` and
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
  EXPECT_EQ(errors[1]->notes[0], "did you mean 'Req2'?");  // Req1 is two edits from a 5-letter name
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

// --- what a merge used to drop without a word (issue 23, point 4) -------------------------

// The base mission with two new requirements, A and B on nav, placed by `uplink_json`.
Mission merge_a_and_b(const std::string& uplink_json) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "A: In nav if W Mission shall satisfy selected_alt = a\n"
          "B: In nav if W & X Mission shall satisfy selected_alt = b\n");
  t.write("uplinks/u/uplink.json", uplink_json);
  return merge(t);
}

// The one finding of `check`; null (and the test fails) when there is not exactly one.
const Finding* only(const Mission& m, const std::string& check) {
  const auto found = of_check(m, check);
  EXPECT_EQ(found.size(), 1u) << format_text(m.findings);
  return found.size() == 1 ? found[0] : nullptr;
}

TEST(UplinkMerge, PlacementCyclesAreErrorsAtTheEntryThatClosesThem) {
  struct Case {
    std::string uplink_json;
    int line, column;         // the key of the entry that closes the cycle
    std::string circle, why;  // in the message
  };
  const std::vector<Case> cases = {
      // The key "B" on line 2, not the string "B" on line 1.
      {"{\"place\": {\"A\": {\"before\": \"B\"},\n           \"B\": {\"before\": \"A\"}}}\n", 2, 12,
       "(A before B, B before A)", "no order satisfies them all"},
      {"{\"place\": {\"A\": {\"after\": \"B\"}, \"B\": {\"after\": \"Req3\"},\n"
       "           \"Req3\": {\"after\": \"A\"}}}\n",
       2, 12, "(A after B, B after Req3, Req3 after A)", "no order satisfies them all"},
      // Before and after mixed: each holds with the other, but nothing ties them to the rest.
      {"{\"place\": {\"A\": {\"before\": \"B\"}, \"B\": {\"after\": \"A\"}}}", 1, 34,
       "(A before B, B after A)",
       "they place one another and nothing places them among the other requirements"}};
  for (const Case& c : cases) {
    const Mission m = merge_a_and_b(c.uplink_json);
    const Finding* error = only(m, "uplink-invalid");
    ASSERT_NE(error, nullptr) << c.uplink_json;
    EXPECT_EQ(error->location.file, "uplinks/u/uplink.json");
    EXPECT_EQ(error->location.line, c.line) << c.uplink_json;
    EXPECT_EQ(error->location.column, c.column) << c.uplink_json;
    EXPECT_NE(error->message.find("cycle of placements " + c.circle + ": " + c.why),
              std::string::npos)
        << error->message;
    // None is reported as placed.
    EXPECT_EQ(record(m, "A")->rule, "appended");
    EXPECT_EQ(record(m, "B")->rule, "appended");
  }
}

TEST(UplinkMerge, EveryPlacementHoldsAfterTheMerge) {
  // Applied one after the other in file order, "B before Req1" would move B in front of A,
  // and the record would still say "A: placed before B".
  const Mission m =
      merge_a_and_b("{\"place\": {\"A\": {\"before\": \"B\"}, \"B\": {\"before\": \"Req1\"}}}");
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  EXPECT_EQ(order(m), (std::vector<std::string>{"A", "B", "Req1", "Req2", "Req3", "Safe"}));
  EXPECT_EQ(record(m, "A")->rule, "placed");
  EXPECT_EQ(record(m, "A")->priority, 1);
  EXPECT_EQ(record(m, "B")->priority, 2);
}

const Finding* at_line(const std::vector<const Finding*>& findings, const std::string& file,
                       int line) {
  for (const auto* f : findings)
    if (f->location.file == file && f->location.line == line) return f;
  return nullptr;
}

// The base mission with a wind speed, a sky, a tick period and an assumption declared, and
// a package whose domain.fret is `package_domain`.
Mission merge_domain(const std::string& package_domain) {
  auto files = base_mission();
  files["domain.fret"] =
      "boolean X, Y, Z, W\ninteger wind in [0, 15]\nenum sky in {clear, dusty}\n"
      "tick 100 ms\nassume calm: wind < 10\n";
  files["requirements.fret"] +=
      "Windy: In nav if wind > 12 Mission shall satisfy selected_alt = b\n";
  TempMission t(files);
  t.write("uplinks/u/domain.fret", package_domain);
  return merge(t);
}

TEST(UplinkMerge, ADifferentRedeclarationIsAnErrorNamingBothDeclarations) {
  const Mission m = merge_domain(
      "integer wind in [0, 3]\nenum sky in {clear, dusty, red}\ntick 1 s\n"
      "assume calm: wind < 2\n");
  const auto errors = of_check(m, "domain-invalid");
  ASSERT_EQ(errors.size(), 4u) << format_text(m.findings);
  const Finding* wind = at_line(errors, "uplinks/u/domain.fret", 1);
  ASSERT_NE(wind, nullptr) << format_text(m.findings);
  EXPECT_EQ(wind->severity, Severity::error);
  EXPECT_EQ(wind->location.column, 9);
  EXPECT_NE(wind->message.find("declares integer wind in [0, 3], but the mission has integer "
                               "wind in [0, 15]"),
            std::string::npos)
      << wind->message;
  ASSERT_EQ(wind->related.size(), 1u);
  EXPECT_EQ(wind->related[0].location.file, "domain.fret");
  EXPECT_EQ(wind->related[0].location.line, 2);
  EXPECT_EQ(wind->related[0].location.column, 9);
  EXPECT_NE(at_line(errors, "uplinks/u/domain.fret", 2), nullptr) << "another enum set";
  EXPECT_NE(at_line(errors, "uplinks/u/domain.fret", 3), nullptr) << "another tick period";
  EXPECT_NE(at_line(errors, "uplinks/u/domain.fret", 4), nullptr) << "another assumption";
  // The mission's declaration stands.
  EXPECT_EQ(m.domain.find("wind")->upper, "15");
}

TEST(UplinkMerge, AnIdenticalRedeclarationIsFine) {
  // The same declarations, written otherwise: literals in another order, spacing.
  const Mission m = merge_domain(
      "boolean W\ninteger wind in [0,15]\nenum sky in {dusty, clear}\ntick 0.1 s\n"
      "assume calm: wind<10\n");
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  EXPECT_EQ(m.domain.assumptions.size(), 1u) << "one assumption, stated twice";
}

TEST(UplinkMerge, FilesThePackageMayNotCarryAreWarnedAbout) {
  TempMission t(base_mission());
  t.write("uplinks/u/requirements.fret",
          "Storm: In nav if W Mission shall satisfy selected_alt = b\n");
  t.write("uplinks/u/mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>"));
  t.write("uplinks/u/nodes.xml", "<root/>");
  t.write("uplinks/u/requirement.fret", "");
  t.write("uplinks/u/alternatives/stray.xml", uabt::testing::alternative_tree("stray"));
  t.write("uplinks/u/README.md", "what this package is for\n");
  t.write("uplinks/u/.hidden", "");
  Mission m = merge(t);
  EXPECT_FALSE(has_errors(m.findings)) << format_text(m.findings);
  const auto ignored = of_check(m, "load-ignored-file");
  std::vector<std::string> files;
  for (const auto* f : ignored) {
    EXPECT_EQ(f->severity, Severity::warning);
    files.push_back(f->location.file);
  }
  EXPECT_EQ(files,
            (std::vector<std::string>{"uplinks/u/alternatives/stray.xml", "uplinks/u/mission.xml",
                                      "uplinks/u/nodes.xml", "uplinks/u/requirement.fret"}))
      << format_text(m.findings);
  const Finding* mission = at_line(ignored, "uplinks/u/mission.xml", 0);
  ASSERT_NE(mission, nullptr);
  EXPECT_NE(mission->message.find("mission.xml is not part of an uplink package"),
            std::string::npos)
      << mission->message;
  const Finding* typo = at_line(ignored, "uplinks/u/requirement.fret", 0);
  ASSERT_NE(typo, nullptr);
  EXPECT_EQ(typo->notes, (std::vector<std::string>{"did you mean 'requirements.fret'?"}));
  // A package with only what the merge reads is not warned about.
  TempMission clean(base_mission());
  clean.write("uplinks/u/requirements.fret",
              "Storm: In nav if W Mission shall satisfy selected_alt = b\n");
  clean.write("uplinks/u/uplink.json", "{}");
  clean.write("uplinks/u/alternatives/nav/a.xml", uabt::testing::alternative_tree("a"));
  EXPECT_TRUE(of_check(merge(clean), "load-ignored-file").empty());
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
