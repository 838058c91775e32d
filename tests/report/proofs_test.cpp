// The Proofs section of the reports: the verdict table and a counterexample's timeline.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report/proof_timeline.hpp"
#include "report/proofs.hpp"
#include "report/reports.hpp"

namespace uabt::testing {
namespace {

using report::detail::CellKind;

// Drill runs ticks 1-2 and ends, CoolDown starts and ends in tick 3, which violates the
// property; the requirement and a value hold characters HTML and Markdown must escape.
report::Proofs three_ticks() {
  report::ProofCounterexample cex;
  cex.tick = 3;
  cex.scenario = "{\"description\": \"<script>alert(1)</script>\"}\n";
  cex.scenario_file = "out dir/counterexamples/R<1>.json";
  cex.ticks = {
      {1,
       "RUNNING",
       {{"Drill.running", Value::of_bool(true)}, {"mode", Value::of_enum("a<b")}},
       {{"Drill", "started"}}},
      {2,
       "RUNNING",
       {{"Drill.running", Value::of_bool(true)}, {"mode", Value::of_enum("a<b")}},
       {{"Drill", "running"}}},
      {3,
       "SUCCESS",
       {{"Drill.running", Value::of_bool(false)}, {"mode", Value::of_enum("x|y")}},
       {{"Drill", "success"}, {"Cool Down", "started"}, {"Cool Down", "success"}}},
  };
  report::Proofs p;
  p.engine = "explicit";
  p.states = 7;
  p.transitions = 9;
  p.complete = true;
  p.mission_path = "missions/m";
  p.answers.push_back({"R<1>",
                       "Mission shall always satisfy x & <y>",
                       {"requirements.fret", 4, 10},
                       "violated",
                       "",
                       3,
                       std::nullopt,
                       cex,
                       ""});
  p.answers.push_back({"Fine",
                       "Mission shall always satisfy z",
                       {"requirements.fret", 5, 10},
                       "proved",
                       "",
                       3,
                       std::nullopt,
                       std::nullopt,
                       ""});
  return p;
}

TEST(ProofTimeline, RowsAndCells) {
  const report::Proofs p = three_ticks();
  const auto rows = report::detail::timeline_of(*p.answers[0].counterexample);
  ASSERT_EQ(rows.size(), 5u);  // root, 2 values, 2 actions
  EXPECT_EQ(rows[0].label, "root");
  EXPECT_EQ(rows[0].cells[2].text, "SUCCESS");
  EXPECT_EQ(rows[1].label, "Drill.running");
  EXPECT_EQ(rows[1].cells[0].kind, CellKind::on);
  EXPECT_EQ(rows[1].cells[2].kind, CellKind::off);
  EXPECT_EQ(rows[2].cells[0].kind, CellKind::text);
  EXPECT_EQ(rows[2].cells[0].text, "a<b");
  // Drill: started in 1, runs through 2, ends in 3.
  EXPECT_EQ(rows[3].label, "Drill");
  EXPECT_EQ(rows[3].cells[0].kind, CellKind::running);
  EXPECT_EQ(rows[3].cells[0].text, "started");
  EXPECT_EQ(rows[3].cells[1].kind, CellKind::running);
  EXPECT_EQ(rows[3].cells[1].text, "running");
  EXPECT_EQ(rows[3].cells[2].text, "success");
  // An action that starts and ends in one tick; idle before.
  EXPECT_EQ(rows[4].label, "Cool Down");
  EXPECT_EQ(rows[4].cells[0].kind, CellKind::idle);
  EXPECT_EQ(rows[4].cells[2].text, "started, success");
}

TEST(ProofTimeline, HtmlEscapesAndMarksTheViolatingTick) {
  const std::string html = report::proofs_html(three_ticks());
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<y>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;"), std::string::npos);
  EXPECT_NE(html.find("<code>R&lt;1&gt;</code> is violated at tick 3"), std::string::npos);
  EXPECT_NE(html.find("<th class=\"viol\">3</th>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"off viol\">false</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"on\">true</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"run viol\">started, success</td>"), std::string::npos);
  // The replay command quotes the path with a space and the angle brackets.
  EXPECT_NE(html.find("uabt run missions/m --scenario &#39;out dir/counterexamples/R&lt;1&gt;.json"
                      "&#39;"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<tr class=\"proved\"><td><code>Fine</code></td><td class=\"verdict\">"
                      "proved</td>"),
            std::string::npos);
}

TEST(ProofTimeline, MarkdownEscapesCells) {
  const std::string md = report::proofs_markdown(three_ticks());
  EXPECT_NE(md.find("| tick | 1 | 2 | **3 ✗** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `Drill.running` | ■ | ■ | □ |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `mode` | a\\<b | a\\<b | x\\|y |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `Drill` | started | ▬ | success |"), std::string::npos) << md;
  EXPECT_NE(md.find("| **violated at tick 3** |"), std::string::npos) << md;
}

TEST(ProofTimeline, NoAnswersNoSection) {
  EXPECT_EQ(report::proofs_html({}), "");
  EXPECT_EQ(report::proofs_markdown({}), "");
}

TEST(ProofTimeline, FileNamesAreSafe) {
  EXPECT_EQ(report::counterexample_file_name("LM-012"), "LM-012.json");
  EXPECT_EQ(report::counterexample_file_name("../a/b c"), "_.._a_b_c.json");
  EXPECT_EQ(report::counterexample_file_name(""), "_.json");
}

// The whole report: a nav link, the section, the CSS; JSON carries the verdicts and SARIF
// the table in the message of the prove-violated result.
TEST(ProofTimeline, ReportsCarryTheProofs) {
  report::ReportInput input;
  input.tool_version = "test";
  input.mission_name = "m";
  Finding f;
  f.check = "prove-violated";
  f.message = "guarantee 'R<1>' is violated at tick 3";
  f.location = {"requirements.fret", 4, 10};
  f.notes = {"tick  root", "3     SUCCESS"};
  input.findings.push_back(f);
  input.proofs = three_ticks();
  const std::string html = report::to_html(input);
  EXPECT_NE(html.find("<a href=\"#proofs\">Proofs</a>"), std::string::npos);
  EXPECT_NE(html.find("<section id=\"proofs\">"), std::string::npos);
  EXPECT_NE(html.find("table.timeline td.on"), std::string::npos);
  EXPECT_NE(report::to_markdown(input).find("### Proofs"), std::string::npos);
  const auto json = nlohmann::json::parse(report::to_json(input));
  EXPECT_EQ(json["proofs"]["properties"][0]["verdict"], "violated");
  EXPECT_EQ(json["proofs"]["properties"][0]["counterexample"]["tick"], 3);
  EXPECT_EQ(json["proofs"]["properties"][1]["verdict"], "proved");
  const auto sarif = nlohmann::json::parse(report::to_sarif(input));
  EXPECT_EQ(sarif["runs"][0]["results"][0]["message"]["text"],
            "guarantee 'R<1>' is violated at tick 3\ntick  root\n3     SUCCESS");
  // A report without proofs has neither the section nor the key.
  input.proofs.reset();
  EXPECT_EQ(report::to_html(input).find("id=\"proofs\""), std::string::npos);
  EXPECT_FALSE(nlohmann::json::parse(report::to_json(input)).contains("proofs"));
}

}  // namespace
}  // namespace uabt::testing
