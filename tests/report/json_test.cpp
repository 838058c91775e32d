#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "report/reports.hpp"
#include "report_fixtures.hpp"

namespace uabt::report {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

const json* find_by(const json& array, const std::string& key, const std::string& value) {
  for (const auto& item : array)
    if (item.at(key) == value) return &item;
  return nullptr;
}

TEST(JsonReport, TopLevelKeysInDesignOrder) {
  const std::string text = to_json(testing::failing_input());
  const ordered_json doc = ordered_json::parse(text);
  std::vector<std::string> keys;
  for (const auto& [key, value] : doc.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"tool", "version", "mission", "verdict", "findings",
                                            "coverage"}));
  EXPECT_EQ(doc["tool"], "uabt");
  EXPECT_EQ(doc["version"], "0.1.0");
  EXPECT_EQ(doc["mission"], "msl_curiosity_paper");
  EXPECT_EQ(doc["verdict"], "fail");
}

TEST(JsonReport, TwoSpaceIndentAndTrailingNewline) {
  const std::string text = to_json(testing::failing_input());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.substr(0, 18), "{\n  \"tool\": \"uabt\"");
}

TEST(JsonReport, FindingFields) {
  const json doc = json::parse(to_json(testing::failing_input()));
  ASSERT_EQ(doc["findings"].size(), 5u);
  const json* overlap =
      find_by(doc["findings"], "message", "the guards of Req1 and Req2 both hold in some state");
  ASSERT_NE(overlap, nullptr);
  EXPECT_EQ((*overlap)["check"], "guard-overlap");
  EXPECT_EQ((*overlap)["severity"], "error");
  EXPECT_EQ((*overlap)["location"],
            (json{{"file", "requirements.fret"}, {"line", 2}, {"column", 1}}));
  EXPECT_EQ((*overlap)["adaptable"], "navigation");
  EXPECT_EQ((*overlap)["requirements"], (json{"Req1", "Req2"}));
  EXPECT_EQ((*overlap)["alternatives"], (json{"on_dust", "on_rocks"}));
  EXPECT_TRUE((*overlap)["witness"]["OnDust"].is_boolean());
  EXPECT_EQ((*overlap)["witness"], (json{{"OnDust", true}, {"OnRocks", true}}));
  // Optional keys appear only when they have content.
  EXPECT_FALSE(overlap->contains("node_path"));
  EXPECT_FALSE(overlap->contains("notes"));

  const json* orphan = find_by(doc["findings"], "check", "ref-orphan-alternative");
  ASSERT_NE(orphan, nullptr);
  EXPECT_EQ((*orphan)["severity"], "warning");
  EXPECT_EQ((*orphan)["node_path"], "spare/Sequence[0]");
  EXPECT_EQ((*orphan)["location"]["line"], 0);
  EXPECT_TRUE((*orphan)["witness"].is_object());
  EXPECT_TRUE((*orphan)["witness"].empty());

  const json* gap = find_by(doc["findings"], "check", "guard-gap");
  ASSERT_NE(gap, nullptr);
  EXPECT_EQ((*gap)["notes"], (json{"uncovered: !OnDust & !OnRocks"}));

  const json* syntax = find_by(doc["findings"], "check", "fretish-syntax");
  ASSERT_NE(syntax, nullptr);
  EXPECT_EQ((*syntax)["adaptable"], "");
  EXPECT_EQ((*syntax)["message"], "expected 'shall' after <Adaptable> | here");
}

TEST(JsonReport, WitnessValuesKeepTheirTypes) {
  const json doc = json::parse(to_json(testing::failing_input()));
  const json* arm = find_by(doc["findings"], "adaptable", "arm");
  ASSERT_NE(arm, nullptr);
  const json& witness = (*arm)["witness"];
  EXPECT_TRUE(witness["battery"].is_number_integer());
  EXPECT_EQ(witness["battery"], 20);
  EXPECT_TRUE(witness["slope"].is_string()) << "1/3 has no exact decimal";
  EXPECT_EQ(witness["slope"], "1/3");
  EXPECT_TRUE(witness["speed"].is_number_float());
  EXPECT_EQ(witness["speed"].get<double>(), 0.5);
  EXPECT_TRUE(witness["load"].is_number_float()) << "1/4 is exactly 0.25";
  EXPECT_EQ(witness["load"].get<double>(), 0.25);
  EXPECT_EQ(witness["terrain"], "rocks");
  // Declaration order is kept.
  const ordered_json ordered = ordered_json::parse(to_json(testing::failing_input()));
  std::vector<std::string> names;
  for (const auto& f : ordered["findings"])
    if (f["adaptable"] == "arm")
      for (const auto& [key, value] : f["witness"].items()) names.push_back(key);
  EXPECT_EQ(names, (std::vector<std::string>{"battery", "slope", "speed", "load", "terrain"}));
}

TEST(JsonReport, RealsThatADoubleCannotHoldStayExactStrings) {
  report::ReportInput input = testing::passing_input();
  Finding f = testing::finding("guard-gap", Severity::error, "gap", {"requirements.fret", 1, 1});
  f.witness = {{"a", Value::of_real(0.1, "0.1")},
               {"b", Value::of_real(0.1, "0.12345678901234567891")},
               {"c", Value::of_real(-1.5, "-3/2")},
               {"d", Value::of_real(1.41, "1.414213562373?")},
               {"e", Value::of_real(0, "1/3000000000000000000")},
               {"f", Value::of_real(-2, "-2")}};
  input.findings = {f};
  const json witness = json::parse(to_json(input))["findings"][0]["witness"];
  EXPECT_EQ(witness["a"].get<double>(), 0.1);
  EXPECT_EQ(witness["b"], "0.12345678901234567891");
  EXPECT_EQ(witness["c"].get<double>(), -1.5);
  EXPECT_EQ(witness["d"], "1.414213562373?");
  EXPECT_EQ(witness["e"], "1/3000000000000000000");
  // A whole real is written as an integer: readers type it by its variable's declaration.
  EXPECT_TRUE(witness["f"].is_number_integer()) << witness;
  EXPECT_EQ(witness["f"].get<std::int64_t>(), -2);
}

TEST(JsonReport, CoverageFields) {
  const ordered_json doc = ordered_json::parse(to_json(testing::failing_input()));
  ASSERT_EQ(doc["coverage"].size(), 2u);
  const auto& navigation = doc["coverage"][0];
  std::vector<std::string> keys;
  for (const auto& [key, value] : navigation.items()) keys.push_back(key);
  EXPECT_EQ(keys,
            (std::vector<std::string>{
                "adaptable", "states", "counted", "measured", "measure", "measure_exact",
                "alternatives", "gap_states", "overlap_states", "gap_share", "gap_share_exact",
                "overlap_share", "overlap_share_exact", "regions", "gap_region"}));
  EXPECT_EQ(navigation["adaptable"], "navigation");
  EXPECT_EQ(navigation["states"], 4);
  EXPECT_EQ(navigation["counted"], true);
  EXPECT_EQ(navigation["measured"], true);
  // Written as people write numbers: the measure 4, not 4.0 (README, "Numbers").
  EXPECT_TRUE(navigation["measure"].is_number_integer()) << navigation["measure"];
  EXPECT_EQ(navigation["measure"], 4);
  EXPECT_TRUE(navigation["alternatives"][0]["measure"].is_number_integer());
  EXPECT_TRUE(navigation["gap_share"].is_number_float());  // 1/4 stays a real
  EXPECT_EQ(navigation["alternatives"][0], (ordered_json{{"name", "on_dust"},
                                                         {"requirement", "Req1"},
                                                         {"states", 2},
                                                         {"reachable", true},
                                                         {"measure", 2.0},
                                                         {"share", 0.5},
                                                         {"share_exact", "1/2"}}));
  EXPECT_EQ(navigation["gap_share"], 0.25);
  EXPECT_EQ(navigation["overlap_share_exact"], "1/4");
  const auto& gap = navigation["regions"]["gap"];
  ASSERT_EQ(gap.size(), 1u);
  EXPECT_EQ(gap[0]["text"], "!OnDust & !OnRocks");
  EXPECT_EQ(gap[0]["requirements"], (ordered_json{"Req1", "Req2"}));
  EXPECT_EQ(gap[0]["constraints"][0],
            (ordered_json{{"variable", "OnDust"}, {"values", {"false"}}, {"text", "!OnDust"}}));
  EXPECT_EQ(gap[0]["share_exact"], "1/4");
  EXPECT_EQ(navigation["regions"]["overlap"][0]["text"], "OnDust & OnRocks");
  EXPECT_EQ(navigation["gap_states"], 1);
  EXPECT_EQ(navigation["overlap_states"], 1);
  EXPECT_EQ(navigation["gap_region"], (ordered_json{"!OnDust & !OnRocks"}));

  const auto& arm = doc["coverage"][1];
  EXPECT_EQ(arm["counted"], false);
  EXPECT_EQ(arm["not_counted_reason"], "slope is a real variable");
  EXPECT_EQ(arm["alternatives"][1]["reachable"], false);
  // Not measured and not bounded: no share at all, rather than a wrong one.
  EXPECT_EQ(arm["measured"], false);
  EXPECT_TRUE(arm["alternatives"][0]["share"].is_null());
  EXPECT_TRUE(arm["gap_share"].is_null());
  EXPECT_FALSE(arm.contains("gap_share_bounds"));
  EXPECT_TRUE(arm["regions"]["gap"].empty());
  EXPECT_FALSE(arm.contains("gap_region"));
}

TEST(JsonReport, PassingVerdictAndEmptyArrays) {
  report::ReportInput input = testing::passing_input();
  input.coverage.clear();
  const json doc = json::parse(to_json(input));
  EXPECT_EQ(doc["verdict"], "pass");
  EXPECT_TRUE(doc["findings"].is_array());
  EXPECT_TRUE(doc["findings"].empty());
  EXPECT_TRUE(doc["coverage"].is_array());

  // A warning alone does not fail the gate.
  input.findings = {testing::finding("ref-orphan-alternative", Severity::warning, "orphan",
                                     {"alternatives/navigation/spare.xml", 0, 0})};
  EXPECT_EQ(json::parse(to_json(input))["verdict"], "pass");
}

TEST(JsonReport, InvalidUtf8InAMessageDoesNotAbort) {
  report::ReportInput input = testing::passing_input();
  input.findings = {testing::finding("fretish-syntax", Severity::error, "bad byte \xff here",
                                     {"requirements.fret", 1, 1})};
  const std::string text = to_json(input);
  EXPECT_NO_THROW({ const json parsed = json::parse(text); });
}

TEST(JsonReport, Deterministic) {
  EXPECT_EQ(to_json(testing::failing_input()), to_json(testing::failing_input()));
}

}  // namespace
}  // namespace uabt::report
