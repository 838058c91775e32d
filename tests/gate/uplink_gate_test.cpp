// `gate --uplink` (ARCHITECTURE §11): the merged mission gated, the behaviour change beside the
// verdict (state counts checked against brute force), the per-node hit policy, and the merged
// mission written out gating to the same bytes.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <random>

#include "base/diagnostics.hpp"
#include "gate/load_support.hpp"
#include "gate/uplink.hpp"
#include "report/impact.hpp"
#include "report/reports.hpp"
#include "smt/evaluate.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"
#include "verify/impact.hpp"

namespace uabt::gate {
namespace {

using uabt::testing::TempMission;

using uabt::testing::load_merged;

Outcome gate_uplink(const std::filesystem::path& dir, const std::string& package,
                    const Options& options = {}) {
  return run_uplink_gate(load_merged(dir), load_merged(dir, {dir / package}), options, "test");
}

std::vector<const Finding*> of_check(const Outcome& o, const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : o.report.findings)
    if (f.check == check) out.push_back(&f);
  return out;
}

const verify::SelectionChange* change(const verify::NodeImpact& n, const std::string& from,
                                      const std::string& to) {
  for (const auto& c : n.changes)
    if (c.from == from && c.to == to) return &c;
  return nullptr;
}

const load::UplinkMerge* merge_of(const Outcome& o, const std::string& id) {
  for (const auto& m : o.report.uplink->merges)
    if (m.requirement == id) return &m;
  return nullptr;
}

const std::filesystem::path kCuriosity = uabt::testing::mission_dir("msl_curiosity");

TEST(UplinkGate, MudUplinkPassesAndReportsItsBehaviourChange) {
  Outcome o = gate_uplink(kCuriosity, "uplinks/on_mud");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  ASSERT_TRUE(o.report.uplink.has_value());
  EXPECT_EQ(o.report.uplink->package, "uplinks/on_mud");
  const auto* req3 = merge_of(o, "Req3");
  ASSERT_NE(req3, nullptr);
  EXPECT_EQ(req3->rule, "appended");
  EXPECT_EQ(req3->priority, 3);
  EXPECT_EQ(req3->of, 4);
  ASSERT_EQ(o.report.uplink->impact.nodes.size(), 1u);
  const auto& node = o.report.uplink->impact.nodes[0];
  EXPECT_EQ(node.states, 4u);
  EXPECT_EQ(node.changed_states, 1u);
  auto notes = of_check(o, "uplink-behaviour-change");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0]->severity, Severity::note);
  EXPECT_EQ(notes[0]->message, "navigation: 1 of 4 states (1/4) change their alternative");
  EXPECT_EQ(notes[0]->location.file, "mission.xml");
  ASSERT_EQ(notes[0]->notes.size(), 1u);
  EXPECT_EQ(notes[0]->notes[0],
            "hold_position (Safe) -> on_mud (Req3): 1 state (1/4), e.g. OnDust=false, "
            "OnRocks=false, OnMud=true");
}

TEST(UplinkGate, DustStormIsPlacedFirstAndMovesOnlyStormStates) {
  Outcome o = gate_uplink(kCuriosity, "uplinks/dust_storm");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  const auto order = o.mission->selections_for("navigation");
  ASSERT_EQ(order.size(), 4u);
  EXPECT_EQ(order[0]->id, "Storm");
  EXPECT_EQ(order[1]->id, "Req1");
  const auto* storm = merge_of(o, "Storm");
  ASSERT_NE(storm, nullptr);
  EXPECT_EQ(storm->rule, "placed");
  EXPECT_EQ(storm->anchor, "Req1");
  EXPECT_EQ(storm->priority, 1);
  const auto& node = o.report.uplink->impact.nodes.at(0);
  ASSERT_EQ(node.changes.size(), 1u);
  const auto* c = change(node, "hold_position", "wait_out_storm");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->states, 1u);
  EXPECT_EQ(node.states, 4u);
}

TEST(UplinkGate, RemovalMovesRocksToTheDefault) {
  Outcome o = gate_uplink(kCuriosity, "uplinks/retire_rocks");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  EXPECT_EQ(of_check(o, "ref-orphan-alternative").size(), 1u) << "on_rocks stays on board, unused";
  const auto* req2 = merge_of(o, "Req2");
  ASSERT_NE(req2, nullptr);
  EXPECT_EQ(req2->rule, "removed");
  const auto& node = o.report.uplink->impact.nodes.at(0);
  EXPECT_EQ(node.states, 3u);
  EXPECT_EQ(node.changed_states, 1u);
  ASSERT_NE(change(node, "on_rocks", "hold_position"), nullptr);
}

TEST(UplinkGate, AmbiguousUplinkIsRejected) {
  Outcome o = gate_uplink(kCuriosity, "uplinks/on_sand_ambiguous");
  EXPECT_FALSE(o.passed());
  auto overlaps = of_check(o, "guard-overlap");
  ASSERT_EQ(overlaps.size(), 1u) << format_text(o.report.findings);
  EXPECT_EQ(overlaps[0]->severity, Severity::error);
  EXPECT_EQ(overlaps[0]->requirements, (std::vector<std::string>{"Req2", "Req4"}));
  // The behaviour change is still reported: it says what the rejected package would do.
  ASSERT_TRUE(o.report.uplink.has_value());
  EXPECT_NE(change(o.report.uplink->impact.nodes.at(0), "hold_position", "on_sand"), nullptr);
}

TEST(UplinkGate, AnUplinkThatChangesNoSelectionHasNoBehaviourChangeNote) {
  // Req1 sent again as it is: replaced in place, no state moves.
  TempMission package(std::map<std::string, std::string>{
      {"requirements.fret",
       "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"}});
  Outcome o = run_uplink_gate(load_merged(kCuriosity), load_merged(kCuriosity, {package.dir()}), {},
                              "test");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  EXPECT_TRUE(of_check(o, "uplink-behaviour-change").empty()) << format_text(o.report.findings);
  ASSERT_EQ(o.report.uplink->impact.nodes.size(), 1u);
  EXPECT_EQ(o.report.uplink->impact.nodes[0].status, "unchanged");
  EXPECT_EQ(o.report.uplink->impact.nodes[0].changed_states, 0u);
  ASSERT_NE(merge_of(o, "Req1"), nullptr);
  EXPECT_EQ(merge_of(o, "Req1")->rule, "replaced");
}

TEST(UplinkGate, EveryReportFormatCarriesTheUplink) {
  Outcome o = gate_uplink(kCuriosity, "uplinks/on_mud");
  const std::string json = report::to_json(o.report);
  EXPECT_NE(json.find("\"uplink\": {"), std::string::npos);
  EXPECT_NE(json.find("\"rule\": \"appended\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"changed_states\": 1,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"share\": 0.25,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"share_exact\": \"1/4\""), std::string::npos) << json;
  const std::string md = report::to_markdown(o.report);
  EXPECT_NE(md.find("### Uplink `uplinks/on_mud`"), std::string::npos) << md;
  EXPECT_NE(md.find("| `Req3` | `navigation` | new id: last before the default | 3 of 4 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `hold_position` | `on_mud` | 1 (1/4, 25.0%) |"), std::string::npos) << md;
  const std::string html = report::to_html(o.report);
  EXPECT_NE(html.find("<section id=\"uplink\">"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"#uplink\">Uplink</a>"), std::string::npos);
  const std::string sarif = report::to_sarif(o.report);
  EXPECT_NE(sarif.find("\"ruleId\": \"uplink-behaviour-change\""), std::string::npos);
  EXPECT_NE(sarif.find("\"ruleId\": \"uplink-merge\""), std::string::npos);
  const std::string text = format_text(o.report.findings);
  EXPECT_NE(text.find("note: navigation: 1 of 4 states (1/4) change their alternative "
                      "[uplink-behaviour-change]"),
            std::string::npos)
      << text;
}

TEST(UplinkGate, MergedMissionGatesToTheSameCompiledTree) {
  for (const char* package : {"uplinks/on_mud", "uplinks/dust_storm", "uplinks/retire_rocks"}) {
    Outcome o = gate_uplink(kCuriosity, package);
    ASSERT_TRUE(o.passed()) << package;
    TempMission out({});
    write_merged_mission(*o.mission, out.dir() / "merged");
    load::Mission again = load_merged(out.dir() / "merged");
    Outcome regated = run_gate(std::move(again), {}, "test");
    EXPECT_TRUE(regated.passed()) << package << "\n" << format_text(regated.report.findings);
    EXPECT_EQ(regated.compiled_xml, o.compiled_xml) << package;
  }
}

// --- the hit policy --------------------------------------------------------------------------

std::map<std::string, std::string> overlapping(const std::string& policy_attribute) {
  return {{"mission.xml",
           uabt::testing::mission_with("<Adaptable ID=\"nav\"" + policy_attribute + "/>")},
          {"domain.fret", "boolean A, B\n"},
          {"requirements.fret",
           "RA: In nav if A Mission shall satisfy selected_alt = a\n"
           "RB: In nav if B Mission shall satisfy selected_alt = b\n"
           "D: In nav Mission shall satisfy selected_alt = b\n"},
          {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
          {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")}};
}

Severity overlap_severity(const Outcome& o) {
  auto overlaps = of_check(o, "guard-overlap");
  EXPECT_EQ(overlaps.size(), 1u) << format_text(o.report.findings);
  return overlaps.empty() ? Severity::error : overlaps[0]->severity;
}

TEST(HitPolicy, FirstMakesTheOverlapANoteAndPriorityDecides) {
  TempMission t(overlapping(" policy=\"first\""));
  Outcome o = run_gate(load_merged(t.dir()), {}, "test");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  EXPECT_EQ(overlap_severity(o), Severity::note);
  EXPECT_EQ(o.compiled_xml.find("policy"), std::string::npos)
      << "BT.CPP refuses an unknown attribute on a SubTree";
  ASSERT_EQ(o.report.coverage.size(), 1u);
  EXPECT_EQ(o.report.coverage[0].overlap_states, 1u) << "the coverage shows the overlap anyway";
}

TEST(HitPolicy, UniqueIsTheDefaultAndAllowOverlapStaysGlobal) {
  for (const char* attribute : {"", " policy=\"unique\""}) {
    TempMission t(overlapping(attribute));
    Outcome o = run_gate(load_merged(t.dir()), {}, "test");
    EXPECT_FALSE(o.passed());
    EXPECT_EQ(overlap_severity(o), Severity::error);
    EXPECT_EQ(o.report.coverage.at(0).overlap_states, 1u);
    Options allow;
    allow.verify.allow_overlap = true;
    Outcome allowed = run_gate(load_merged(t.dir()), allow, "test");
    EXPECT_TRUE(allowed.passed()) << format_text(allowed.report.findings);
    EXPECT_EQ(overlap_severity(allowed), Severity::warning);
  }
}

// --- state counts against brute force --------------------------------------------------------

// The alternative the node selects in `state` (first enabled in priority order), "" for none.
std::string brute_select(const load::Mission& m, const std::string& node, const State& state) {
  for (const auto* s : m.selections_for(node))
    if (!s->guard || smt::evaluate(*s->guard, m.domain, state)) return s->alternative;
  return "";
}

TEST(UplinkImpact, CountsEqualBruteForceOnSmallDomains) {
  const std::vector<std::string> guards = {"x < 2",     "x >= 4", "t = a",          "t = b | p",
                                           "p & x = 3", "!p",     "x > 1 & t != c", "t = c"};
  const std::vector<std::string> alternatives = {"a", "b", "c"};
  std::mt19937 random(14);
  int rounds_changed = 0, rounds_with_several_moves = 0;
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(random() % n); };
  for (int round = 0; round < 24; ++round) {
    std::string reqs, uplink_reqs;
    for (int i = 1; i <= 3; ++i)
      reqs += "R" + std::to_string(i) + ": In nav if " + guards[pick(guards.size())] +
              " Mission shall satisfy selected_alt = " + alternatives[pick(3)] + "\n";
    reqs += "D: In nav Mission shall satisfy selected_alt = " + alternatives[pick(3)] + "\n";
    uplink_reqs = "U: In nav if " + guards[pick(guards.size())] +
                  " Mission shall satisfy selected_alt = " + alternatives[pick(3)] + "\n";
    if (round % 3 == 1)
      uplink_reqs += "R2: In nav if " + guards[pick(guards.size())] +
                     " Mission shall satisfy selected_alt = " + alternatives[pick(3)] + "\n";
    const std::string anchor = "R" + std::to_string(1 + pick(3));
    std::string plan = "{\"place\": {\"U\": {\"" + std::string(round % 2 ? "after" : "before") +
                       "\": \"" + anchor + "\"}}";
    if (round % 4 == 3 && anchor != "R3") plan += ", \"remove\": [\"R3\"]";
    plan += "}";
    TempMission t(
        {{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\" policy=\"first\"/>")},
         {"domain.fret",
          "integer x in [0, 5]\nenum t in {a, b, c}\nboolean p\nassume no_c_when_p: !(p & t = "
          "c)\n"},
         {"requirements.fret", reqs},
         {"alternatives/nav/a.xml", uabt::testing::alternative_tree("a")},
         {"alternatives/nav/b.xml", uabt::testing::alternative_tree("b")},
         {"alternatives/nav/c.xml", uabt::testing::alternative_tree("c")},
         {"uplinks/u/requirements.fret", uplink_reqs},
         {"uplinks/u/uplink.json", plan}});
    const load::Mission before = load_merged(t.dir());
    const load::Mission after = load_merged(t.dir(), {t.dir() / "uplinks" / "u"});
    ASSERT_FALSE(has_errors(after.findings))
        << reqs << uplink_reqs << plan << format_text(after.findings);
    verify::Impact impact = verify::selection_impact(before, after, {});
    ASSERT_TRUE(impact.findings.empty()) << format_text(impact.findings);

    std::uint64_t states = 0, changed = 0;
    std::map<std::pair<std::string, std::string>, std::uint64_t> moves;
    for (long long x = 0; x <= 5; ++x)
      for (const char* tv : {"a", "b", "c"})
        for (bool p : {false, true}) {
          const State state = {
              {"x", Value::of_int(x)}, {"t", Value::of_enum(tv)}, {"p", Value::of_bool(p)}};
          if (!smt::satisfies_domain(after.domain, state)) continue;
          ++states;
          const std::string from = brute_select(before, "nav", state);
          const std::string to = brute_select(after, "nav", state);
          if (from != to) {
            ++changed;
            ++moves[{from, to}];
          }
        }
    const std::string context = reqs + uplink_reqs + plan + "\n" + report::impact_text(impact);
    ASSERT_EQ(impact.nodes.size(), 1u) << context;
    const auto& node = impact.nodes[0];
    ASSERT_TRUE(node.counted) << context;
    EXPECT_EQ(states, 30u) << "6 x 3 x 2 states, 6 of them p with t = c";
    EXPECT_EQ(node.states, states) << context;
    EXPECT_EQ(node.changed_states, changed) << context;
    EXPECT_EQ(node.status, changed == 0 ? "unchanged" : "changed") << context;
    ASSERT_EQ(node.changes.size(), moves.size()) << context;
    rounds_changed += changed > 0 ? 1 : 0;
    rounds_with_several_moves += moves.size() > 1 ? 1 : 0;
    for (const auto& c : node.changes) {
      EXPECT_EQ(c.states, (moves[{c.from, c.to}])) << context;
      // The example is a real state of the move.
      EXPECT_TRUE(smt::satisfies_domain(after.domain, c.example)) << context;
      EXPECT_EQ(brute_select(before, "nav", c.example), c.from) << context;
      EXPECT_EQ(brute_select(after, "nav", c.example), c.to) << context;
    }
  }
  // The random cases must exercise the counting, not only agree on "nothing changes".
  EXPECT_GE(rounds_changed, 12);
  EXPECT_GE(rounds_with_several_moves, 4);
}

TEST(UplinkImpact, ARealSpaceIsMeasuredNotCountedInJson) {
  const auto dir = uabt::testing::mission_dir("exploration");
  TempMission t(std::map<std::string, std::string>{
      {"uplinks/steeper/requirements.fret",
       "Sand: In exploration if terrain = sand & slope <= 20 & slope >= -20 & battery "
       ">= 40 Mission shall satisfy selected_alt = sand_alternative\n"}});
  const verify::Impact impact = verify::selection_impact(
      load_merged(dir), load_merged(dir, {t.dir() / "uplinks" / "steeper"}), {});
  const auto json = nlohmann::json::parse(report::impact_json(impact));
  const auto& node = json["nodes"][0];
  EXPECT_EQ(node["counted"], false);
  EXPECT_TRUE(node["states"].is_null());
  EXPECT_TRUE(node["changed_states"].is_null());
  // Sand (1 of 3 terrains), battery 40..100 (61 of 101 values), slope in [-20, -15) or
  // (15, 20] (10 of 90): 610 of 27270.
  EXPECT_EQ(node["changed_share_exact"], "61/2727") << node.dump();
  EXPECT_DOUBLE_EQ(node["changed_share"].get<double>(), 61.0 / 2727);
  EXPECT_EQ(node["status"], "changed");
  ASSERT_EQ(node["changes"].size(), 1u) << node.dump();
  EXPECT_EQ(node["changes"][0]["from"], "rocks_alternative");
  EXPECT_EQ(node["changes"][0]["to"], "sand_alternative");
  EXPECT_EQ(node["changes"][0]["share_exact"], "61/2727");
  EXPECT_TRUE(node["changes"][0]["states"].is_null());
  const auto& example = node["changes"][0]["example"];
  EXPECT_TRUE(example["slope"].is_number()) << example.dump();
  EXPECT_TRUE(example["battery"].is_number_integer()) << example.dump();
}

}  // namespace
}  // namespace uabt::gate
