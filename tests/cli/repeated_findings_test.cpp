// One mistake repeated many times: every format lists the first 20 findings of a check in a
// file and counts the rest, so a guard naming thousands of undeclared variables, or a file of
// random bytes, gives a short report that still says how many there were.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"

namespace {

using uabt::testing::run_shell;
using uabt::testing::TempMission;

const char* kCountNote =
    "and 480 more like it in this file, not listed: uabt lists the first 20 findings of a check "
    "in a file";

// A guard that reads 500 names the domain does not declare.
TempMission undeclared_mission() {
  std::string guard = "A0";
  for (int k = 1; k < 500; ++k) guard += " & A" + std::to_string(k);
  return TempMission(
      {{"mission.xml", uabt::testing::mission_with("<Adaptable ID=\"nav\"/>")},
       {"alternatives/nav/fast.xml",
        "<root BTCPP_format=\"4\"><BehaviorTree ID=\"fast\"><Drive/></BehaviorTree></root>\n"},
       {"alternatives/nav/slow.xml",
        "<root BTCPP_format=\"4\"><BehaviorTree ID=\"slow\"><Creep/></BehaviorTree></root>\n"},
       {"domain.fret", "boolean Calm\n"},
       {"requirements.fret", "R1: In nav if Calm & " + guard +
                                 " Mission shall satisfy selected_alt = fast\n"
                                 "R2: In nav Mission shall satisfy selected_alt = slow\n"}});
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(RepeatedFindings, TextListsTwentyAndCountsTheRest) {
  const TempMission m = undeclared_mission();
  const auto run = run_shell("'" UABT_BINARY "' verify '" + m.dir().string() + "' 2>&1");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(count_of(run.out, "[ref-undeclared]"), 20u) << run.out;
  EXPECT_EQ(count_of(run.out, kCountNote), 1u) << run.out;
  EXPECT_NE(run.out.find("'A19' in requirement R1"), std::string::npos);
  EXPECT_EQ(run.out.find("'A20' in requirement R1"), std::string::npos);
}

TEST(RepeatedFindings, JsonAndSarifCarryTheSameCount) {
  const TempMission m = undeclared_mission();
  const auto json =
      run_shell("'" UABT_BINARY "' verify '" + m.dir().string() + "' --format json 2>/dev/null");
  const auto doc = nlohmann::json::parse(json.out);
  std::size_t undeclared = 0, notes_with_count = 0;
  for (const auto& f : doc.at("findings")) {
    undeclared += f.at("check") == "ref-undeclared";
    for (const auto& note : f.value("notes", nlohmann::json::array()))
      notes_with_count += note == kCountNote;
  }
  EXPECT_EQ(undeclared, 20u);
  EXPECT_EQ(notes_with_count, 1u);

  const auto sarif =
      run_shell("'" UABT_BINARY "' verify '" + m.dir().string() + "' --format sarif 2>/dev/null");
  const auto log = nlohmann::json::parse(sarif.out);
  std::size_t results = 0;
  for (const auto& r : log.at("runs").at(0).at("results"))
    results += r.at("ruleId") == "ref-undeclared";
  EXPECT_EQ(results, 20u);
  EXPECT_NE(sarif.out.find("and 480 more like it"), std::string::npos);
}

TEST(RepeatedFindings, TheGateReportsCountEveryFindingAndListTwenty) {
  const TempMission m = undeclared_mission();
  const auto out = m.dir().parent_path() / "out";
  const auto run = run_shell("'" UABT_BINARY "' gate '" + m.dir().string() + "' --out '" +
                             out.string() + "' 2>&1");
  EXPECT_EQ(run.exit_code, 1);
  for (const char* file : {"summary.md", "report.html", "junit.xml", "findings.txt"}) {
    const std::string text = uabt::testing::read_all(out / file);
    EXPECT_EQ(count_of(text, "and 480 more like it in this file"), 1u) << file;
  }
  EXPECT_NE(uabt::testing::read_all(out / "summary.md").find("500 errors"), std::string::npos);
}

TEST(RepeatedFindings, ARequirementsFileOfNoiseGivesAShortReport) {
  TempMission m = undeclared_mission();
  std::string noise;
  for (int k = 0; k < 3000; ++k) noise += "!{<" + std::to_string(k) + "\n";
  m.write("requirements.fret", noise);
  const auto run = run_shell("'" UABT_BINARY "' verify '" + m.dir().string() + "' 2>&1");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(count_of(run.out, "[fretish-syntax]"), 20u) << run.out;
  EXPECT_NE(run.out.find("and 2,980 more like it in this file"), std::string::npos) << run.out;
}

}  // namespace
