// What the reports show of `uabt prove`: the golden timeline of sample_drilling's broken
// alternative, no timeline for a proved mission, and the gate's report files.
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "prove_support.hpp"
#include "report/proofs.hpp"

namespace uabt::testing {
namespace {

report::Proofs proofs_of(const std::filesystem::path& dir, const std::string& name) {
  const prove::Result r = prove_dir(dir);
  std::map<std::string, std::string> written;
  for (const auto& a : r.answers)
    if (a.counterexample) written[a.requirement] = "cex/" + a.requirement + ".json";
  report::Proofs proofs = gate::report_proofs(r, written);
  proofs.mission_path = "missions/" + name;
  return proofs;
}

std::string proofs_page(const std::filesystem::path& dir, const std::string& name) {
  return report::proofs_page_html(proofs_of(dir, name), name, "test");
}

// Compares with tests/prove/golden/NAME byte for byte. To accept a deliberate change:
// UABT_UPDATE_GOLDEN=1 build/tests/test_prove --gtest_filter='ProofsReport.*Golden*'.
void expect_golden(const std::string& name, const std::string& text) {
  const auto golden = source_dir() / "tests/prove/golden" / name;
  if (std::getenv("UABT_UPDATE_GOLDEN") != nullptr) std::ofstream(golden, std::ios::binary) << text;
  EXPECT_EQ(text, read_all(golden)) << name;
}

TEST(ProofsReport, SampleDrillingGoldenPage) {
  const std::string page = proofs_page(mission_dir("sample_drilling"), "sample_drilling");
  expect_golden("sample_drilling_proofs.html", page);
  // The same input gives the same bytes.
  EXPECT_EQ(page, proofs_page(mission_dir("sample_drilling"), "sample_drilling"));
}

// summary.md's section, on a counterexample of two ticks.
TEST(ProofsReport, HotBitGoldenMarkdown) {
  TempMission m(hot_bit_after_a_drill());
  expect_golden("hot_bit_proofs.md", report::proofs_markdown(proofs_of(m.dir(), "hot_bit")));
}

TEST(ProofsReport, ProvedMissionShowsNoTimeline) {
  auto files = mission_files("sample_drilling");
  files["alternatives/drilling/rotary.xml"] = kFixedRotary;
  TempMission m(files);
  const std::string page = proofs_page(m.dir(), "m");
  EXPECT_NE(page.find("<div class=\"badge\">PASS</div>"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"verdict\">proved</td>"), std::string::npos);
  EXPECT_EQ(page.find("<table class=\"timeline\">"), std::string::npos);
  EXPECT_EQ(page.find("class=\"cex\""), std::string::npos);
  EXPECT_EQ(page.find("violated at"), std::string::npos);
}

// A later violation: the timeline shows two ticks, Drill running through the first.
TEST(ProofsReport, TimelineOfATwoTickCounterexample) {
  TempMission m(hot_bit_after_a_drill());
  const std::string page = proofs_page(m.dir(), "m");
  EXPECT_NE(page.find("<thead><tr><th>tick</th><th>1</th><th class=\"viol\">2</th></tr></thead>"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("<tr class=\"value\"><th><code>IsBitCool</code></th><td class=\"on\">true"
                      "</td><td class=\"off viol\">false</td></tr>"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("<tr class=\"action\"><th><code>Drill</code></th><td class=\"run\">started"
                      "</td><td class=\"run viol\">success, started</td></tr>"),
            std::string::npos)
      << page;
}

// A gate that fails before its proof step lists the guarantees as not checked.
TEST(ProofsReport, GateFailingBeforeProveListsGuaranteesNotChecked) {
  auto files = mission_files("sample_drilling");
  files["requirements.fret"] =
      "Hard: In drilling if HardRock Mission shall satisfy selected_alt = percussive\n"
      "CoolBit: Mission shall always satisfy Drill.running -> IsBitCool\n";
  TempMission m(files);
  std::string error;
  auto mission = load::load_mission(m.dir(), {}, error);
  ASSERT_TRUE(mission) << error;
  gate::Outcome outcome = gate::run_gate(std::move(*mission), {}, "test");
  ASSERT_FALSE(outcome.passed());
  ASSERT_TRUE(outcome.report.proofs);
  ASSERT_EQ(outcome.report.proofs->answers.size(), 1u);
  EXPECT_EQ(outcome.report.proofs->answers[0].verdict, "unsupported");
  const std::string html = report::proofs_html(*outcome.report.proofs);
  EXPECT_NE(html.find("uabt prove did not run: the gate failed before its proof step."),
            std::string::npos);
  EXPECT_NE(html.find("not checked"), std::string::npos);
}

}  // namespace
}  // namespace uabt::testing
