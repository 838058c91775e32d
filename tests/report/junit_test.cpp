#include <gtest/gtest.h>

#include <map>
#include <string>

#include <tinyxml2.h>

#include "base/catalogue.hpp"
#include "report/reports.hpp"
#include "report_fixtures.hpp"

namespace uabt::report {
namespace {

// The rule of the brief, restated independently of the writer: per adaptable node the verify,
// conform and compile checks and the ref-* load checks; per mission everything else.
bool per_node(const CheckInfo& check) {
  const std::string stage = check.stage, id = check.id;
  return stage == "verify" || stage == "conform" || stage == "compile" ||
         (stage == "load" && id.rfind("ref-", 0) == 0);
}

struct Parsed {
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* root = nullptr;

  explicit Parsed(const std::string& xml) {
    if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS)
      throw std::runtime_error(std::string("JUnit does not parse: ") + doc.ErrorStr());
    root = doc.RootElement();
  }
  const tinyxml2::XMLElement* suite(const std::string& name) const {
    for (auto* s = root->FirstChildElement("testsuite"); s; s = s->NextSiblingElement("testsuite"))
      if (name == s->Attribute("name")) return s;
    return nullptr;
  }
  static const tinyxml2::XMLElement* test(const tinyxml2::XMLElement* suite,
                                          const std::string& check) {
    for (auto* t = suite->FirstChildElement("testcase"); t; t = t->NextSiblingElement("testcase"))
      if (check == t->Attribute("name")) return t;
    return nullptr;
  }
};

// Findings of checks that exist in checks/ today, so that the placement rule is testable.
ReportInput junit_input() {
  ReportInput input = testing::passing_input();
  input.mission_name = "msl";
  input.adaptables = {"navigation", "arm"};
  input.stages = {"load", "verify"};
  input.findings = {
      testing::finding("ref-unknown-alternative", Severity::error,
                       "Req9 selects 'on_ice', which has no file", {"requirements.fret", 3, 40},
                       "navigation"),
      testing::finding("ref-unknown-alternative", Severity::error,
                       "Req8 selects 'on_snow', which has no file", {"requirements.fret", 4, 40},
                       "navigation"),
      testing::finding("ref-orphan-alternative", Severity::warning,
                       "alternative 'spare' is named by no requirement",
                       {"alternatives/arm/spare.xml", 0, 0}, "arm"),
      testing::finding("fretish-syntax", Severity::error, "expected 'shall' <here> & \"there\"",
                       {"requirements.fret", 5, 10}),
  };
  return input;
}

TEST(JunitReport, OneSuitePerAdaptableNodeAndOneForTheMission) {
  const Parsed parsed(to_junit(junit_input()));
  ASSERT_NE(parsed.root, nullptr);
  EXPECT_STREQ(parsed.root->Name(), "testsuites");
  EXPECT_STREQ(parsed.root->Attribute("name"), "uabt");
  ASSERT_NE(parsed.suite("msl"), nullptr);
  ASSERT_NE(parsed.suite("msl.navigation"), nullptr);
  ASSERT_NE(parsed.suite("msl.arm"), nullptr);

  std::size_t node_checks = 0, mission_checks = 0;
  for (const auto& check : check_catalogue()) (per_node(check) ? node_checks : mission_checks)++;
  int suites = 0;
  for (auto* s = parsed.root->FirstChildElement("testsuite"); s;
       s = s->NextSiblingElement("testsuite"))
    ++suites;
  EXPECT_EQ(suites, 3);
  EXPECT_EQ(parsed.suite("msl.navigation")->UnsignedAttribute("tests"), node_checks);
  EXPECT_EQ(parsed.suite("msl")->UnsignedAttribute("tests"), mission_checks);

  // Every test case's classname is its suite's name, its name a check id of the catalogue.
  for (auto* s = parsed.root->FirstChildElement("testsuite"); s;
       s = s->NextSiblingElement("testsuite")) {
    for (auto* t = s->FirstChildElement("testcase"); t; t = t->NextSiblingElement("testcase")) {
      EXPECT_STREQ(t->Attribute("classname"), s->Attribute("name"));
      const CheckInfo* info = find_check(t->Attribute("name"));
      ASSERT_NE(info, nullptr) << t->Attribute("name");
      EXPECT_EQ(per_node(*info), std::string(s->Attribute("name")) != "msl");
      EXPECT_EQ(t->Attribute("time"), nullptr) << "no timing: reports are deterministic";
    }
  }
}

TEST(JunitReport, CountsMatchTheTestCases) {
  const Parsed parsed(to_junit(junit_input()));
  unsigned tests = 0, failures = 0, skipped = 0;
  for (auto* s = parsed.root->FirstChildElement("testsuite"); s;
       s = s->NextSiblingElement("testsuite")) {
    unsigned suite_tests = 0, suite_failures = 0, suite_skipped = 0;
    for (auto* t = s->FirstChildElement("testcase"); t; t = t->NextSiblingElement("testcase")) {
      ++suite_tests;
      if (t->FirstChildElement("failure")) ++suite_failures;
      if (t->FirstChildElement("skipped")) ++suite_skipped;
    }
    EXPECT_EQ(s->UnsignedAttribute("tests"), suite_tests);
    EXPECT_EQ(s->UnsignedAttribute("failures"), suite_failures);
    EXPECT_EQ(s->UnsignedAttribute("skipped"), suite_skipped);
    tests += suite_tests;
    failures += suite_failures;
    skipped += suite_skipped;
  }
  EXPECT_EQ(parsed.root->UnsignedAttribute("tests"), tests);
  EXPECT_EQ(parsed.root->UnsignedAttribute("failures"), failures);
  EXPECT_EQ(parsed.root->UnsignedAttribute("skipped"), skipped);
  EXPECT_EQ(failures, 2u) << "ref-unknown-alternative on navigation and fretish-syntax";
}

TEST(JunitReport, ErrorFindingIsAFailureOfItsCheckAndNode) {
  const Parsed parsed(to_junit(junit_input()));
  const auto* test = Parsed::test(parsed.suite("msl.navigation"), "ref-unknown-alternative");
  ASSERT_NE(test, nullptr);
  const auto* failure = test->FirstChildElement("failure");
  ASSERT_NE(failure, nullptr);
  EXPECT_STREQ(failure->Attribute("type"), "ref-unknown-alternative");
  EXPECT_STREQ(failure->Attribute("message"),
               "Req9 selects 'on_ice', which has no file (and 1 more)");
  const std::string body = failure->GetText();
  EXPECT_NE(body.find("requirements.fret:3:40: error: Req9 selects 'on_ice'"), std::string::npos);
  EXPECT_NE(body.find("requirements.fret:4:40: error: Req8 selects 'on_snow'"), std::string::npos);
  // The other node passes the same check.
  const auto* arm_test = Parsed::test(parsed.suite("msl.arm"), "ref-unknown-alternative");
  ASSERT_NE(arm_test, nullptr);
  EXPECT_EQ(arm_test->FirstChildElement("failure"), nullptr);

  const auto* syntax = Parsed::test(parsed.suite("msl"), "fretish-syntax");
  ASSERT_NE(syntax, nullptr);
  ASSERT_NE(syntax->FirstChildElement("failure"), nullptr);
  EXPECT_STREQ(syntax->FirstChildElement("failure")->Attribute("message"),
               "expected 'shall' <here> & \"there\"");
}

TEST(JunitReport, WarningsGoToSystemOut) {
  const Parsed parsed(to_junit(junit_input()));
  const auto* test = Parsed::test(parsed.suite("msl.arm"), "ref-orphan-alternative");
  ASSERT_NE(test, nullptr);
  EXPECT_EQ(test->FirstChildElement("failure"), nullptr);
  const auto* out = test->FirstChildElement("system-out");
  ASSERT_NE(out, nullptr);
  EXPECT_NE(std::string(out->GetText()).find("warning: alternative 'spare'"), std::string::npos);
}

TEST(JunitReport, ChecksOfStagesThatDidNotRunAreSkipped) {
  const Parsed parsed(to_junit(junit_input()));  // stages: load, verify
  bool saw_compile_check = false;
  for (const auto& check : check_catalogue()) {
    if (std::string(check.stage) != "compile") continue;
    saw_compile_check = true;
    const auto* test = Parsed::test(parsed.suite("msl.navigation"), check.id);
    ASSERT_NE(test, nullptr);
    EXPECT_NE(test->FirstChildElement("skipped"), nullptr) << check.id;
  }
  if (!saw_compile_check) GTEST_SKIP() << "no compile-stage check in checks/ yet";
  ReportInput all = junit_input();
  all.stages = {"load", "verify", "compile", "conform"};
  const Parsed ran(to_junit(all));
  for (const auto& check : check_catalogue())
    if (std::string(check.stage) == "compile") {
      EXPECT_EQ(Parsed::test(ran.suite("msl.navigation"), check.id)->FirstChildElement("skipped"),
                nullptr);
    }
}

TEST(JunitReport, FindingOfAnUnknownNodeOrCheckLandsInTheMissionSuite) {
  ReportInput input = junit_input();
  input.findings.push_back(testing::finding("ref-unknown-alternative", Severity::error,
                                            "requirement names node 'navigaton'",
                                            {"requirements.fret", 9, 4}, "navigaton"));
  input.findings.push_back(
      testing::finding("zz-undocumented", Severity::error, "odd", {"mission.xml", 1, 1}));
  const Parsed parsed(to_junit(input));
  EXPECT_EQ(parsed.suite("msl.navigaton"), nullptr);
  const auto* test = Parsed::test(parsed.suite("msl"), "ref-unknown-alternative");
  ASSERT_NE(test, nullptr);
  EXPECT_NE(test->FirstChildElement("failure"), nullptr);
  const auto* odd = Parsed::test(parsed.suite("msl"), "zz-undocumented");
  ASSERT_NE(odd, nullptr);
  EXPECT_NE(odd->FirstChildElement("failure"), nullptr);
  EXPECT_EQ(parsed.root->UnsignedAttribute("failures"), 4u);
}

TEST(JunitReport, GuardFindingsBelongToTheirNode) {
  if (find_check("guard-overlap") == nullptr) GTEST_SKIP() << "checks/guard-overlap.md not yet";
  const Parsed parsed(to_junit(testing::failing_input()));
  const auto* test = Parsed::test(parsed.suite("msl_curiosity_paper.navigation"), "guard-overlap");
  ASSERT_NE(test, nullptr);
  EXPECT_NE(test->FirstChildElement("failure"), nullptr);
}

TEST(JunitReport, MissionWithoutAdaptableNodesHasOneSuite) {
  ReportInput input = junit_input();
  input.adaptables.clear();
  const Parsed parsed(to_junit(input));
  EXPECT_EQ(parsed.root->FirstChildElement("testsuite"),
            parsed.root->LastChildElement("testsuite"));
  // Its per-node findings are not lost.
  const auto* test = Parsed::test(parsed.suite("msl"), "ref-unknown-alternative");
  ASSERT_NE(test, nullptr);
  EXPECT_NE(test->FirstChildElement("failure"), nullptr);
}

TEST(JunitReport, Deterministic) {
  EXPECT_EQ(to_junit(junit_input()), to_junit(junit_input()));
}

}  // namespace
}  // namespace uabt::report
