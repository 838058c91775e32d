// `uabt coverage --format html`: the page a flight team opens after a testbed session, compared
// with tests/cli/golden/coverage_msl_curiosity.html. To accept a deliberate change:
// UABT_UPDATE_GOLDEN=1 build/tests/test_cli --gtest_filter='CoverageHtml.*'.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "cli/cli_support.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using uabt::testing::CliRun;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Three of msl_curiosity's shipped scenarios: they visit OnDust and OnRocks, never the state
// where neither holds, and miss what only that state reaches.
const std::string kRuns =
    "msl_curiosity/scenarios/dusty_start.json msl_curiosity/scenarios/rocks_mid_drive.json "
    "msl_curiosity/scenarios/short_drive.json";

CliRun coverage(const std::string& args) {
  return uabt::testing::run_shell("cd '" + (uabt::testing::source_dir() / "missions").string() +
                                  "' && '" + UABT_BINARY + "' coverage msl_curiosity " + args +
                                  " 2>/dev/null");
}

TEST(CoverageHtml, MslCuriosityGolden) {
  const CliRun page = coverage(kRuns + " --format html");
  EXPECT_EQ(page.exit_code, 1);  // targets are missed
  const fs::path golden =
      uabt::testing::source_dir() / "tests/cli/golden/coverage_msl_curiosity.html";
  if (std::getenv("UABT_UPDATE_GOLDEN") != nullptr)
    std::ofstream(golden, std::ios::binary) << page.out;
  EXPECT_EQ(page.out, read(golden));
  // The same runs give the same bytes; --output writes them to a file.
  EXPECT_EQ(coverage(kRuns + " --format html").out, page.out);
  uabt::testing::TempMission scratch({});
  const fs::path file = scratch.dir() / "coverage.html";
  const CliRun written = coverage(kRuns + " --format html -o '" + file.string() + "'");
  EXPECT_EQ(written.exit_code, 1);
  EXPECT_EQ(written.out, "");
  EXPECT_EQ(read(file), page.out);
}

TEST(CoverageHtml, EveryMissIsListedWithWhatCoversItAsTheTextSays) {
  const std::string text = coverage(kRuns).out;
  const std::string page = coverage(kRuns + " --format html").out;
  std::istringstream lines(text);
  std::size_t misses = 0;
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("missed: ")) continue;
    ++misses;
    const std::string cover = line.substr(line.find("; covered by ") + 13);
    std::string escaped;
    for (char c : cover) escaped += c == '"' ? std::string("&quot;") : std::string(1, c);
    EXPECT_NE(page.find("<code>" + escaped + "</code>"), std::string::npos) << cover;
  }
  EXPECT_EQ(misses, 7u) << text;
  std::size_t rows = 0;
  for (std::size_t at = page.find("<tr class=\"missed\">"); at != std::string::npos;
       at = page.find("<tr class=\"missed\">", at + 1))
    ++rows;
  EXPECT_EQ(rows, misses);
}

// A node over one integer x in [0, MAX], selecting low below 5, and a scenario at x = 3.
std::map<std::string, std::string> one_integer(const std::string& max) {
  return {
      {"mission.xml", uabt::testing::mission_with("    <Adaptable ID=\"node\"/>")},
      {"domain.fret", "integer x in [0, " + max + "]\n"},
      {"requirements.fret",
       "Low: In node if x < 5 Mission shall satisfy selected_alt = low\n"
       "Other: In node Mission shall satisfy selected_alt = other\n"},
      {"alternatives/node/low.xml", uabt::testing::alternative_tree("low", "<AlwaysSuccess/>")},
      {"alternatives/node/other.xml", uabt::testing::alternative_tree("other", "<AlwaysSuccess/>")},
      {"scenarios/one.json", "{\"max_ticks\": 1, \"initial\": {\"x\": 3}}\n"}};
}

TEST(CoverageHtml, ANodeWithoutAMapSaysWhy) {
  // An integer range too large to enumerate: its targets are solved one by one, and it has no
  // measured share and no map, each with the reason the text gives.
  uabt::testing::TempMission m(one_integer("100000000000"));
  const CliRun text = uabt::testing::run_shell("cd '" + m.dir().string() + "' && '" + UABT_BINARY +
                                               "' coverage . scenarios 2>&1");
  const std::string said = "node: 1 states visited, share not computed: ";
  const auto at = text.out.find(said);
  ASSERT_NE(at, std::string::npos) << text.out;
  const std::string reason =
      text.out.substr(at + said.size(), text.out.find('\n', at) - at - said.size());
  EXPECT_EQ(reason, "the guards range over more than 2^24 states");
  const CliRun page = uabt::testing::run_shell("cd '" + m.dir().string() + "' && '" + UABT_BINARY +
                                               "' coverage . scenarios --format html 2>&1");
  EXPECT_NE(
      page.out.find("<p>1 states visited, share not computed: " + reason +
                    ".</p>\n<p class=\"callout info\">No coverage map of <code>node</code>: " +
                    reason + ".</p>"),
      std::string::npos)
      << page.out;
}

TEST(CoverageHtml, ANodeTooLargeToDrawGetsItsTargetsAndSaysWhyItHasNoMap) {
  // 3,000,001 values of x and two alternatives: enumerated for the targets, too many to draw.
  uabt::testing::TempMission m(one_integer("3000000"));
  const CliRun page = uabt::testing::run_shell("cd '" + m.dir().string() + "' && '" + UABT_BINARY +
                                               "' coverage . scenarios --format html 2>&1");
  EXPECT_NE(page.out.find("<p>1 of 3000001 states visited, &lt;0.1% (1/3000001) of the "
                          "space.</p>\n<p class=\"callout info\">No coverage map of "
                          "<code>node</code>: too many cells to draw (3000001 cells, 2 "
                          "alternatives; the map draws at most 4194304 cells times "
                          "alternatives).</p>"),
            std::string::npos)
      << page.out;
  EXPECT_NE(page.out.find("<tr class=\"covered\"><td>node selects low (Low)</td>"),
            std::string::npos)
      << page.out;
}

}  // namespace
