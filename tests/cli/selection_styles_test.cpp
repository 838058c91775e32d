// Every observable means the same in every selection style (ARCHITECTURE §12): each mission's
// properties get the same verdicts from `uabt prove` and from `uabt run` on its scenarios
// whether a selection is compiled as Fig. 4 or as an optimized decision. `optimized` chooses
// the layout only; whether a selection is re-checked every tick is the node's own
// selection="reactive" (or --selection reactive), so each mission is compared twice: as a
// plain selection (`sequence` against `optimized`) and declared reactive (`reactive` against
// `optimized`).
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "cli_support.hpp"
#include "style_missions.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

using Verdicts = std::map<std::string, std::string>;  // property id -> verdict

Verdicts prove_verdicts(const std::string& dir, const std::string& style) {
  const CliRun r = run_uabt_in(dir, "prove . --format json --selection " + style);
  const auto json = nlohmann::json::parse(r.out, nullptr, false);
  EXPECT_FALSE(json.is_discarded()) << r.out;
  Verdicts out;
  if (!json.is_discarded())
    for (const auto& p : json["properties"]) out[p["id"]] = p["verdict"];
  return out;
}

// "property ID: held" / "assumption ID: held" lines of `uabt run`.
Verdicts run_verdicts(const std::string& dir, const std::string& scenario, const std::string& style,
                      std::string* output = nullptr) {
  const CliRun r = run_uabt_in(dir, "run . --scenario '" + scenario + "' --selection " + style);
  if (output) *output = r.out;
  Verdicts out;
  static const std::regex line(R"(^(property|assumption) (\S+): (\S+))");
  std::istringstream in(r.out);
  for (std::string text; std::getline(in, text);)
    if (std::smatch m; std::regex_search(text, m, line)) out[m[2]] = m[3];
  return out;
}

void expect_same_verdicts(std::map<std::string, std::string> files, const std::string& name) {
  for (const bool reactive : {false, true}) {
    const std::string fig4 = reactive ? "reactive" : "sequence";
    SCOPED_TRACE(name + (reactive ? ", declared reactive" : ", plain selection"));
    files["mission.xml"] = with_reactivity(files["mission.xml"], reactive);
    const TempMission t(files, name);
    const std::string dir = t.dir().string();
    const Verdicts proved = prove_verdicts(dir, fig4);
    EXPECT_FALSE(proved.empty()) << "the mission states no guarantee";
    EXPECT_EQ(prove_verdicts(dir, "optimized"), proved) << "uabt prove, " << fig4;
    for (const auto& [path, _] : files) {
      if (path.rfind("scenarios/", 0) != 0) continue;
      SCOPED_TRACE(path);
      const Verdicts ran = run_verdicts(dir, path, fig4);
      EXPECT_FALSE(ran.empty());
      EXPECT_EQ(run_verdicts(dir, path, "optimized"), ran) << "uabt run, " << fig4;
    }
  }
}

TEST(SelectionStyles, ShippedMissionsHaveTheSameVerdictsInEveryStyle) {
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "missions")) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    if (prove_verdicts(entry.path().string(), "sequence").empty()) continue;  // no guarantee
    expect_same_verdicts(mission_files(name), name);
    ++compared;
  }
  EXPECT_GE(compared, 2) << "msl_curiosity and sample_drilling state guarantees";
}

TEST(SelectionStyles, ADecisionStructureObservesTheSameSelections) {
  expect_same_verdicts(lunar_traverse(), "lunar");
  // `run` reports the decision structure's selections as it does Fig. 4's.
  const TempMission t(lunar_traverse(), "lunar");
  std::string out;
  const Verdicts ran = run_verdicts(t.dir().string(), "scenarios/shadow.json", "optimized", &out);
  EXPECT_NE(out.find("traverse selects wait_for_light (Dark)"), std::string::npos) << out;
  EXPECT_NE(out.find("traverse selects crawl (Steep)"), std::string::npos) << out;
  EXPECT_EQ(ran.at("WaitInShadow"), "held") << out;
  EXPECT_EQ(ran.at("CrawlSelected"), "held") << out;
  EXPECT_EQ(prove_verdicts(t.dir().string(), "optimized").at("CrawlSelected"), "proved");
}

}  // namespace
}  // namespace uabt::testing
