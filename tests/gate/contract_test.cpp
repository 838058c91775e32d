// An uplink never weakens the mission's guarantees without saying so (ARCHITECTURE §11): the old
// statement of every guarantee a package restates or removes is proved on the merged mission.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/diagnostics.hpp"
#include "gate/load_support.hpp"
#include "gate/uplink.hpp"
#include "report/reports.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::gate {
namespace {

using uabt::testing::load_merged;
using uabt::testing::TempMission;

Outcome gate_uplink(const std::filesystem::path& dir, const std::string& package) {
  return run_uplink_gate(load_merged(dir), load_merged(dir, {dir / package}), {}, "test");
}

const Finding* only(const Outcome& o, const std::string& check) {
  const Finding* found = nullptr;
  for (const auto& f : o.report.findings)
    if (f.check == check) {
      EXPECT_EQ(found, nullptr) << "more than one " << check;
      found = &f;
    }
  return found;
}

const report::ContractChange* change(const Outcome& o, const std::string& id) {
  for (const auto& c : o.report.uplink->contract)
    if (c.requirement == id) return &c;
  return nullptr;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::filesystem::path kCuriosity = uabt::testing::mission_dir("msl_curiosity");

// on_mud restates HoldOnUnknown as "upon !OnDust & !OnRocks & !OnMud …". That is weaker, not
// implied: on mud (neither dust nor rocks) the old statement asks for hold_position within a
// tick, and the merged mission crawls with on_mud instead. The package says so in uplink.json
// ("weaken"), so the gate passes with a warning and says what was given up.
TEST(UplinkContract, ShippedMudPackageWeakensHoldOnUnknownWithConsent) {
  const Outcome o = gate_uplink(kCuriosity, "uplinks/on_mud");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  const Finding* weakened = only(o, "uplink-guarantee-weakened");
  ASSERT_NE(weakened, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(weakened->severity, Severity::warning);
  EXPECT_EQ(weakened->location.file, "uplinks/on_mud/requirements.fret");
  EXPECT_NE(weakened->message.find("(violated at tick 2)"), std::string::npos) << weakened->message;
  const report::ContractChange* c = change(o, "HoldOnUnknown");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->change, "weakened");
  EXPECT_EQ(c->before, "proved");
  EXPECT_EQ(c->old_after, "violated at tick 2");
  EXPECT_EQ(c->after, "proved");
  EXPECT_EQ(c->consent, "weaken");
  EXPECT_EQ(o.report.verdict_text(), "pass with 1 guarantee weakened");
  EXPECT_EQ(o.report.banner(), "PASS with 1 guarantee weakened");
}

// report.html draws the run of the merged mission that breaks the old statement as the Proofs
// section draws a violation (ticks as columns, the violating tick marked), and the finding links
// to it, instead of listing the ticks as bullet text.
TEST(UplinkContract, ReportDrawsTheRunThatBreaksTheOldStatementAsATimeline) {
  const Outcome o = gate_uplink(kCuriosity, "uplinks/on_mud");
  const report::ContractChange* c = change(o, "HoldOnUnknown");
  ASSERT_NE(c, nullptr);
  ASSERT_TRUE(c->old_on_merged && c->old_on_merged->counterexample);
  EXPECT_EQ(c->old_on_merged->counterexample->tick, 2u);
  const std::string html = report::to_html(o.report);
  const auto uplink = html.find("<section id=\"uplink\">");
  const auto article = html.find(
      "<article class=\"cex\" id=\"uplink-cex-0\">\n<h3>The merged mission breaks what "
      "<code>HoldOnUnknown</code> said before, at tick 2</h3>\n");
  ASSERT_NE(uplink, std::string::npos);
  ASSERT_NE(article, std::string::npos) << html;
  EXPECT_GT(article, uplink);
  EXPECT_LT(article, html.find("</section>", uplink));
  const std::string drawn = html.substr(article, html.find("</article>", article) - article);
  EXPECT_NE(drawn.find("<thead><tr><th>tick</th><th>1</th><th class=\"viol\">2</th></tr></thead>"),
            std::string::npos)
      << drawn;
  EXPECT_NE(drawn.find("<tr class=\"value\"><th><code>navigation.selected</code></th><td>on_mud"
                       "</td><td class=\"viol\">on_mud</td></tr>"),
            std::string::npos)
      << drawn;
  EXPECT_NE(html.find("<a href=\"#uplink-cex-0\">The counterexample as a timeline</a>"),
            std::string::npos);
  EXPECT_EQ(html.find("<li>tick  root"), std::string::npos) << "the ticks as bullet text";
}

// dust_storm restates it as "upon !OnDust & !OnRocks & !DustStorm …": in a storm on unknown
// ground the rover waits the storm out (and then drives on rocks), so the old statement fails
// on the merged mission too: weakened, with consent.
TEST(UplinkContract, ShippedStormPackageWeakensHoldOnUnknownWithConsent) {
  const Outcome o = gate_uplink(kCuriosity, "uplinks/dust_storm");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  ASSERT_NE(only(o, "uplink-guarantee-weakened"), nullptr) << format_text(o.report.findings);
  EXPECT_EQ(change(o, "HoldOnUnknown")->change, "weakened");
}

// The same package without its uplink.json consent fails the gate, with the old statement's
// counterexample on the merged mission.
TEST(UplinkContract, WeakeningWithoutConsentFails) {
  TempMission m({}, "work");
  std::filesystem::copy(kCuriosity, m.dir() / "msl", std::filesystem::copy_options::recursive);
  std::filesystem::remove(m.dir() / "msl/uplinks/on_mud/uplink.json");
  const Outcome o = gate_uplink(m.dir() / "msl", "uplinks/on_mud");
  EXPECT_FALSE(o.passed());
  const Finding* weakened = only(o, "uplink-guarantee-weakened");
  ASSERT_NE(weakened, nullptr);
  EXPECT_EQ(weakened->severity, Severity::error);
  bool table = false;
  for (const auto& n : weakened->notes) table |= n.rfind("tick  root", 0) == 0;
  EXPECT_TRUE(table) << "the counterexample of the old statement";
  EXPECT_EQ(o.report.verdict_text(), "fail");
}

// A small mission to vary the contract: nav drives (MoveForward, 1 or 2 ticks in world.json,
// TurnLeft the same); Arrive promises the drive ends within a tick of the start, Straight that
// the rover is always driving.
std::map<std::string, std::string> drive_mission() {
  return {{"mission.xml", uabt::testing::mission_with("    <Adaptable ID=\"nav\"/>")},
          {"alternatives/nav/go.xml", uabt::testing::alternative_tree("go", "<MoveForward/>")},
          {"requirements.fret",
           "Go: In nav Mission shall satisfy selected_alt = go\n"
           "Arrive: the rover shall within 1 tick satisfy MoveForward.success\n"
           "Straight: the rover shall always satisfy MoveForward.running | MoveForward.success\n"},
          {"world.json",
           R"({"actions": {"MoveForward": {"ticks": [1, 2], "results": ["success"]},
                           "TurnLeft": {"ticks": [1, 2], "results": ["success"]}}})"}};
}

// A package that turns before it drives and restates Arrive with a looser bound: the old bound
// no longer holds on the merged mission. The new one is proved, so only the contract check
// catches it. Straight, restated to allow the turn, is weakened too, with consent.
TEST(UplinkContract, ALooserTimingBoundIsAWeakening) {
  TempMission m(drive_mission());
  m.write("uplinks/turn/alternatives/nav/go.xml",
          uabt::testing::alternative_tree("go", "<Sequence><TurnLeft/><MoveForward/></Sequence>"));
  m.write("uplinks/turn/requirements.fret",
          "Arrive: the rover shall within 3 ticks satisfy MoveForward.success\n"
          "Straight: the rover shall always satisfy MoveForward.running | MoveForward.success | "
          "TurnLeft.running\n");
  m.write("uplinks/turn/uplink.json", R"({"weaken": {"Straight": "the rover turns first"}})");
  const Outcome o = gate_uplink(m.dir(), "uplinks/turn");
  EXPECT_FALSE(o.passed()) << format_text(o.report.findings);
  const Finding* weakened = nullptr;
  for (const auto& f : o.report.findings)
    if (f.check == "uplink-guarantee-weakened" && f.requirements[0] == "Arrive") weakened = &f;
  ASSERT_NE(weakened, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(weakened->severity, Severity::error);
  EXPECT_EQ(change(o, "Arrive")->after, "proved") << "the restated bound itself holds";
  EXPECT_EQ(change(o, "Straight")->change, "weakened");
  EXPECT_EQ(change(o, "Straight")->consent, "weaken");
  for (const auto& f : o.report.findings) {
    if (f.requirements == std::vector<std::string>{"Straight"} &&
        f.check == "uplink-guarantee-weakened") {
      EXPECT_EQ(f.severity, Severity::warning);
    }
  }
  EXPECT_EQ(o.report.verdict_text(), "fail");
}

// Restated in a stronger form: a note, and a "weaken" consent for it is not needed.
TEST(UplinkContract, AStrongerRestatementIsANoteAndItsConsentIsNotNeeded) {
  TempMission m(drive_mission());
  m.write(
      "uplinks/tight/requirements.fret",
      "Arrive: the rover shall within 1 tick satisfy MoveForward.success & !MoveForward.failure\n");
  m.write("uplinks/tight/uplink.json", R"({"weaken": {"Arrive": "in case"}})");
  const Outcome o = gate_uplink(m.dir(), "uplinks/tight");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  const Finding* restated = only(o, "uplink-guarantee-restated");
  ASSERT_NE(restated, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(restated->severity, Severity::note);
  const Finding* unneeded = only(o, "uplink-consent-unneeded");
  ASSERT_NE(unneeded, nullptr);
  EXPECT_EQ(unneeded->location.file, "uplinks/tight/uplink.json");
  EXPECT_EQ(change(o, "Arrive")->change, "restated");
  EXPECT_EQ(o.report.verdict_text(), "pass");
}

// Removing a guarantee the merged mission no longer keeps: an error, a warning with "retire".
TEST(UplinkContract, RetiringAGuaranteeNeedsConsent) {
  TempMission m(drive_mission());
  m.write("uplinks/turn/alternatives/nav/go.xml",
          uabt::testing::alternative_tree("go", "<Sequence><TurnLeft/><MoveForward/></Sequence>"));
  m.write("uplinks/turn/requirements.fret",
          "Arrive: the rover shall within 3 ticks satisfy MoveForward.success\n");
  m.write("uplinks/turn/uplink.json",
          R"({"remove": ["Straight"], "weaken": {"Arrive": "turning first takes longer"}})");
  Outcome o = gate_uplink(m.dir(), "uplinks/turn");
  EXPECT_FALSE(o.passed()) << format_text(o.report.findings);
  const Finding* removed = only(o, "uplink-guarantee-removed");
  ASSERT_NE(removed, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(removed->severity, Severity::error);
  EXPECT_EQ(removed->location.file, "uplinks/turn/uplink.json") << "where the removal is said";

  m.write("uplinks/turn/uplink.json",
          R"({"remove": ["Straight"], "weaken": {"Arrive": "turning first takes longer"},
              "retire": {"Straight": "the rover must turn on this ground"}})");
  o = gate_uplink(m.dir(), "uplinks/turn");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  // "weaken" agrees to a weaker statement, not to dropping the guarantee.
  m.write("uplinks/turn/uplink.json",
          R"({"remove": ["Straight"], "weaken": {"Arrive": "turning first takes longer",
                                                  "Straight": "the rover must turn"}})");
  o = gate_uplink(m.dir(), "uplinks/turn");
  EXPECT_FALSE(o.passed()) << format_text(o.report.findings);
  removed = only(o, "uplink-guarantee-removed");
  ASSERT_NE(removed, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(removed->severity, Severity::error);
  EXPECT_TRUE(std::any_of(removed->notes.begin(), removed->notes.end(), [](const auto& n) {
    return n.find("may weaken it, but the package removes it") != std::string::npos;
  })) << format_text(o.report.findings);

  // "retire" gives it up altogether, which covers a weaker restatement too.
  m.write("uplinks/turn/uplink.json",
          R"({"remove": ["Straight"], "retire": {"Arrive": "turning first takes longer",
                                                  "Straight": "the rover must turn on this ground"}})");
  o = gate_uplink(m.dir(), "uplinks/turn");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  EXPECT_EQ(change(o, "Arrive")->change, "weakened");
  EXPECT_EQ(change(o, "Arrive")->consent, "retire");

  m.write("uplinks/turn/uplink.json",
          R"({"remove": ["Straight"], "weaken": {"Arrive": "turning first takes longer"},
              "retire": {"Straight": "the rover must turn on this ground"}})");
  o = gate_uplink(m.dir(), "uplinks/turn");
  EXPECT_EQ(only(o, "uplink-guarantee-removed")->severity, Severity::warning);
  EXPECT_EQ(o.report.verdict_text(), "pass with 1 guarantee retired and 1 weakened");
  // Contract changes first in the uplink section, in every format.
  TempMission out({});
  report::write_reports(o.report, out.dir(), o.compiled_xml);
  const std::string md = read(out.dir() / "summary.md");
  EXPECT_NE(md.find("**Verdict: PASS with 1 guarantee retired and 1 weakened**"),
            std::string::npos);
  EXPECT_LT(md.find("Guarantees the uplink changes"), md.find("Where the merge put"));
  EXPECT_NE(md.find("| `Straight` | removed (uplink.json retires it: the rover must turn on this "
                    "ground) | proved | violated at tick 1 | - |"),
            std::string::npos)
      << md;
  EXPECT_NE(read(out.dir() / "report.html").find("PASS with 1 guarantee retired and 1 weakened"),
            std::string::npos);
  const auto json = nlohmann::json::parse(read(out.dir() / "findings.json"));
  EXPECT_EQ(json["verdict"], "pass");
  EXPECT_EQ(json["verdict_text"], "pass with 1 guarantee retired and 1 weakened");
  EXPECT_EQ(json["uplink"]["contract"][1]["change"], "removed");
  const auto sarif = nlohmann::json::parse(read(out.dir() / "findings.sarif"));
  EXPECT_EQ(sarif["runs"][0]["properties"]["verdict"],
            "pass with 1 guarantee retired and 1 weakened");
}

// A removed guarantee that still holds costs nothing: a note. A consent naming no guarantee of
// the mission is an error with a suggestion.
TEST(UplinkContract, RemovalThatStillHoldsAndConsentForNothing) {
  TempMission m(drive_mission());
  m.write("uplinks/tidy/uplink.json", R"({"remove": ["Straight"], "retire": {"Arive": "typo"}})");
  const Outcome o = gate_uplink(m.dir(), "uplinks/tidy");
  const Finding* removed = only(o, "uplink-guarantee-removed");
  ASSERT_NE(removed, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(removed->severity, Severity::note);
  EXPECT_TRUE(change(o, "Straight")->old_holds);
  const Finding* invalid = only(o, "uplink-invalid");
  ASSERT_NE(invalid, nullptr) << format_text(o.report.findings);
  EXPECT_NE(invalid->message.find("'Arive', which is not a guarantee"), std::string::npos);
  ASSERT_FALSE(invalid->notes.empty());
  EXPECT_EQ(invalid->notes[0], "did you mean 'Arrive'?");
  EXPECT_FALSE(o.passed());
}

// sample_drilling's CoolBit is already violated on board: the finding says so, so that the
// uplink is not read as what broke it.
TEST(UplinkContract, AGuaranteeBrokenOnBoardIsSaidToBe) {
  TempMission m(uabt::testing::mission_files("sample_drilling"));
  m.write("uplinks/p/requirements.fret",
          "CoolBit: Mission shall always satisfy Drill.running -> IsBitCool | HardRock\n");
  const Outcome o = gate_uplink(m.dir(), "uplinks/p");
  const Finding* weakened = only(o, "uplink-guarantee-weakened");
  ASSERT_NE(weakened, nullptr) << format_text(o.report.findings);
  EXPECT_EQ(change(o, "CoolBit")->before, "violated at tick 1");
  EXPECT_NE(std::find(weakened->notes.begin(), weakened->notes.end(),
                      "the version on board does not satisfy it either (violated at tick 1)"),
            weakened->notes.end());
}

}  // namespace
}  // namespace uabt::gate
