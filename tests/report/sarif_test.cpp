#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <nlohmann/json.hpp>

#include "base/catalogue.hpp"
#include "report/reports.hpp"
#include "report_fixtures.hpp"

namespace uabt::report {
namespace {

using nlohmann::json;

json sarif_of(const ReportInput& input) {
  return json::parse(to_sarif(input));
}

const json& result_with_message(const json& doc, const std::string& message) {
  for (const auto& result : doc["runs"][0]["results"])
    if (result["message"]["text"].get<std::string>().rfind(message, 0) == 0) return result;
  throw std::runtime_error("no result with message " + message);
}

TEST(SarifReport, HeaderAndDriver) {
  const json doc = sarif_of(testing::failing_input());
  EXPECT_EQ(doc["$schema"], "https://json.schemastore.org/sarif-2.1.0.json");
  EXPECT_EQ(doc["version"], "2.1.0");
  ASSERT_EQ(doc["runs"].size(), 1u);
  const json& run = doc["runs"][0];
  EXPECT_EQ(run["tool"]["driver"]["name"], "uabt");
  EXPECT_EQ(run["tool"]["driver"]["version"], "0.1.0");
  EXPECT_TRUE(run["originalUriBaseIds"].contains("%SRCROOT%"));
  EXPECT_FALSE(run["originalUriBaseIds"]["%SRCROOT%"].contains("uri")) << "no machine path";
  EXPECT_EQ(run["automationDetails"]["id"], "uabt/msl_curiosity_paper/");
}

TEST(SarifReport, EveryCatalogueCheckIsARuleSortedById) {
  const json doc = sarif_of(testing::passing_input());
  const json& rules = doc["runs"][0]["tool"]["driver"]["rules"];
  const auto& catalogue = check_catalogue();
  ASSERT_EQ(rules.size(), catalogue.size());
  for (std::size_t i = 1; i < rules.size(); ++i)
    EXPECT_LT(rules[i - 1]["id"].get<std::string>(), rules[i]["id"].get<std::string>());
  for (const auto& check : catalogue) {
    const auto rule = std::find_if(rules.begin(), rules.end(),
                                   [&](const json& r) { return r["id"] == check.id; });
    ASSERT_NE(rule, rules.end()) << check.id;
    EXPECT_EQ((*rule)["shortDescription"]["text"], check.summary);
    EXPECT_EQ((*rule)["defaultConfiguration"]["level"], check.severity);
    EXPECT_FALSE((*rule)["help"]["markdown"].get<std::string>().empty());
    EXPECT_EQ((*rule)["help"]["markdown"], (*rule)["fullDescription"]["markdown"]);
    const std::string name = (*rule)["name"];
    EXPECT_TRUE(std::isupper(static_cast<unsigned char>(name[0]))) << name;
    EXPECT_EQ(name.find('-'), std::string::npos) << name;
  }
}

TEST(SarifReport, RuleNamesAreCamelCase) {
  const json doc = sarif_of(testing::failing_input());
  for (const auto& rule : doc["runs"][0]["tool"]["driver"]["rules"]) {
    if (rule["id"] == "ref-orphan-alternative") {
      EXPECT_EQ(rule["name"], "RefOrphanAlternative");
    } else if (rule["id"] == "guard-overlap") {
      EXPECT_EQ(rule["name"], "GuardOverlap");
    }
  }
}

TEST(SarifReport, ResultsPointAtTheirRulesAndLines) {
  const ReportInput input = testing::failing_input();
  const json doc = sarif_of(input);
  const json& run = doc["runs"][0];
  const json& rules = run["tool"]["driver"]["rules"];
  ASSERT_EQ(run["results"].size(), input.findings.size());
  for (std::size_t i = 0; i < input.findings.size(); ++i) {
    const Finding& finding = input.findings[i];
    const json& result = run["results"][i];
    EXPECT_EQ(result["ruleId"], finding.check);
    const std::size_t index = result["ruleIndex"];
    ASSERT_LT(index, rules.size());
    EXPECT_EQ(rules[index]["id"], finding.check) << "ruleIndex must name the same rule";
    EXPECT_EQ(result["level"], severity_name(finding.severity));
    ASSERT_EQ(result["locations"].size(), 1u) << "GitHub rejects results without a location";
    const json& physical = result["locations"][0]["physicalLocation"];
    EXPECT_EQ(physical["artifactLocation"]["uri"], input.uri_prefix + finding.location.file);
    EXPECT_EQ(physical["artifactLocation"]["uriBaseId"], "%SRCROOT%");
    if (finding.location.line > 0) {
      EXPECT_EQ(physical["region"]["startLine"], finding.location.line);
      EXPECT_EQ(physical["region"]["startColumn"], finding.location.column);
      if (finding.location.end_line > finding.location.line) {
        EXPECT_EQ(physical["region"]["endLine"], finding.location.end_line);
      }
    } else {
      EXPECT_FALSE(physical.contains("region")) << finding.message;
    }
    EXPECT_EQ(result["properties"]["adaptable"], finding.adaptable);
  }
}

TEST(SarifReport, MessageCarriesTheWitnessInWords) {
  const json doc = sarif_of(testing::failing_input());
  const json& overlap = result_with_message(doc, "the guards of Req1 and Req2");
  EXPECT_EQ(overlap["message"]["text"],
            "the guards of Req1 and Req2 both hold in some state "
            "(witness: OnDust=true, OnRocks=true)");
  EXPECT_EQ(overlap["properties"]["witness"], (json{{"OnDust", true}, {"OnRocks", true}}));
  EXPECT_EQ(overlap["properties"]["requirements"], (json{"Req1", "Req2"}));
  EXPECT_EQ(overlap["properties"]["alternatives"], (json{"on_dust", "on_rocks"}));
}

TEST(SarifReport, FingerprintIgnoresTheLineButNotTheMessage) {
  ReportInput input = testing::failing_input();
  auto fingerprint = [](const ReportInput& in, std::size_t i) {
    return json::parse(to_sarif(in))["runs"][0]["results"][i]["partialFingerprints"]
        .begin()
        .value()
        .get<std::string>();
  };
  const std::string before = fingerprint(input, 2);
  ReportInput moved = input;
  moved.findings[2].location.line += 7;
  moved.findings[2].location.column = 3;
  EXPECT_EQ(fingerprint(moved, 2), before);
  ReportInput reworded = input;
  reworded.findings[2].message += " (reworded)";
  EXPECT_NE(fingerprint(reworded, 2), before);
  ReportInput other_file = input;
  other_file.findings[2].location.file = "uplinks/on_mud/requirements.fret";
  EXPECT_NE(fingerprint(other_file, 2), before);

  // Every result has its own fingerprint, also two identical findings.
  ReportInput twice = input;
  twice.findings.push_back(twice.findings[2]);
  const json results = json::parse(to_sarif(twice))["runs"][0]["results"];
  std::set<std::string> seen;
  for (const auto& result : results)
    EXPECT_TRUE(seen.insert(result["partialFingerprints"].begin().value()).second);
}

TEST(SarifReport, FindingWithoutAFileIsAnchoredAtTheMission) {
  ReportInput input = testing::passing_input();
  input.uri_prefix = "missions/m/";
  input.findings = {testing::finding("load-file", Severity::error, "cannot read", {"", 0, 0})};
  const json result = sarif_of(input)["runs"][0]["results"][0];
  ASSERT_EQ(result["locations"].size(), 1u);
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
            "missions/m/mission.xml");
}

TEST(SarifReport, RelatedLocationsRegionsAndMissionsOutsideTheRoot) {
  ReportInput input = testing::passing_input();
  input.uri_prefix = "missions/m/";
  Finding overlap =
      testing::finding("guard-overlap", Severity::error, "both", {"requirements.fret", 5, 7});
  overlap.related.push_back({{"requirements.fret", 4, 7}, "the other requirement, Req1 (a)"});
  Finding gap = testing::finding("guard-gap", Severity::error, "none", {"requirements.fret", 4, 7});
  gap.location.end_line = 5;
  Finding outside = testing::finding("bt-xml", Severity::error, "bad", {"../out/c.xml", 1, 1});
  input.findings = {overlap, gap, outside};
  const json results = sarif_of(input)["runs"][0]["results"];
  const json& related = results[0]["relatedLocations"];
  ASSERT_EQ(related.size(), 1u);
  EXPECT_EQ(related[0]["message"]["text"], "the other requirement, Req1 (a)");
  EXPECT_EQ(related[0]["physicalLocation"]["artifactLocation"]["uri"],
            "missions/m/requirements.fret");
  EXPECT_EQ(related[0]["physicalLocation"]["region"]["startLine"], 4);
  EXPECT_EQ(results[1]["locations"][0]["physicalLocation"]["region"]["endLine"], 5);
  EXPECT_FALSE(results[0]["locations"][0]["physicalLocation"]["region"].contains("endLine"));
  EXPECT_EQ(results[2]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
            "missions/out/c.xml")
      << "a file beside the mission is normalised, not left with '..'";
  // A mission outside the source root: an absolute file URI, without a base.
  input.uri_prefix = "/srv/m/";
  const json far = sarif_of(input)["runs"][0]["results"][0]["locations"][0]["physicalLocation"];
  EXPECT_EQ(far["artifactLocation"]["uri"], "file:///srv/m/requirements.fret");
  EXPECT_FALSE(far["artifactLocation"].contains("uriBaseId"));
}

TEST(SarifReport, UrisArePercentEncoded) {
  ReportInput input = testing::passing_input();
  input.findings = {
      testing::finding("bt-xml", Severity::error, "bad", {"alternatives/nav/on dust#1.xml", 3, 2})};
  const json result = sarif_of(input)["runs"][0]["results"][0];
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
            "alternatives/nav/on%20dust%231.xml");
}

TEST(SarifReport, UndocumentedCheckStillGetsARule) {
  ReportInput input = testing::passing_input();
  input.findings = {testing::finding("zz-not-a-check", Severity::warning, "odd", {"a.xml", 1, 1})};
  const json run = sarif_of(input)["runs"][0];
  const std::size_t index = run["results"][0]["ruleIndex"];
  EXPECT_EQ(run["tool"]["driver"]["rules"][index]["id"], "zz-not-a-check");
  EXPECT_EQ(run["tool"]["driver"]["rules"].size(), check_catalogue().size() + 1);
}

TEST(SarifReport, Deterministic) {
  EXPECT_EQ(to_sarif(testing::failing_input()), to_sarif(testing::failing_input()));
}

}  // namespace
}  // namespace uabt::report
