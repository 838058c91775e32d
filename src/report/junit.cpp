#include <algorithm>
#include <map>
#include <set>

#include <tinyxml2.h>

#include "report/common.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::report {

namespace {

struct TestCase {
  std::string check;
  std::vector<const Finding*> findings;
  bool skipped = false;
  std::string skip_reason;
};

struct TestSuite {
  std::string name;
  std::vector<TestCase> cases;
};

std::string diagnostics(const std::vector<const Finding*>& findings, bool errors) {
  std::vector<Finding> chosen;
  for (const Finding* f : findings)
    if ((f->severity == Severity::error) == errors) chosen.push_back(*f);
  return format_text(chosen);
}

class Builder {
 public:
  explicit Builder(const ReportInput& input) : input_(input) {
    mission_ = input.mission_name.empty() ? "mission" : input.mission_name;
  }

  std::vector<TestSuite> suites() const {
    // Each finding lands in exactly one test case: its adaptable node's when the check is a
    // per-node check and the node exists, the mission's otherwise (an unknown node included).
    std::map<std::string, std::map<std::string, std::vector<const Finding*>>> by_suite;
    const std::set<std::string> known(input_.adaptables.begin(), input_.adaptables.end());
    for (const auto& finding : input_.findings) {
      const CheckInfo* info = find_check(finding.check);
      const bool per_node = info != nullptr && detail::is_per_adaptable_check(*info) &&
                            known.count(finding.adaptable) > 0;
      by_suite[per_node ? finding.adaptable : std::string()][finding.check].push_back(&finding);
    }

    const auto catalogue = detail::sorted_catalogue();
    std::vector<TestSuite> out;
    TestSuite mission_suite{mission_, {}};
    std::set<std::string> mission_checks;
    for (const CheckInfo* check : catalogue)
      if (!detail::is_per_adaptable_check(*check)) mission_checks.insert(check->id);
    for (const auto& [check, findings] : by_suite[std::string()]) mission_checks.insert(check);
    for (const auto& check : mission_checks)
      mission_suite.cases.push_back(make_case(check, by_suite[std::string()]));
    out.push_back(std::move(mission_suite));

    std::set<std::string> done;
    for (const auto& adaptable : input_.adaptables) {
      if (adaptable.empty() || !done.insert(adaptable).second) continue;
      TestSuite suite{mission_ + "." + adaptable, {}};
      for (const CheckInfo* check : catalogue)
        if (detail::is_per_adaptable_check(*check))
          suite.cases.push_back(make_case(check->id, by_suite[adaptable]));
      out.push_back(std::move(suite));
    }
    return out;
  }

 private:
  TestCase make_case(const std::string& check,
                     std::map<std::string, std::vector<const Finding*>>& findings) const {
    TestCase test{check, findings[check], false, {}};
    const CheckInfo* info = find_check(check);
    if (test.findings.empty() && info != nullptr && !input_.stages.empty()) {
      // A check of a stage that did not run has not passed: say so instead.
      const std::string stage = detail::pipeline_stage(info->stage);
      if (std::find(input_.stages.begin(), input_.stages.end(), stage) == input_.stages.end()) {
        test.skipped = true;
        test.skip_reason = "the " + stage + " stage did not run";
      }
    }
    return test;
  }

  const ReportInput& input_;
  std::string mission_;
};

bool has_error(const TestCase& test) {
  return std::any_of(test.findings.begin(), test.findings.end(),
                     [](const Finding* f) { return f->severity == Severity::error; });
}

}  // namespace

std::string to_junit(const ReportInput& input) {
  std::vector<JunitSuite> out;
  for (const auto& suite : Builder(input).suites()) {
    JunitSuite s{suite.name, {}};
    for (const auto& test : suite.cases) {
      JunitCase c;
      c.name = test.check;
      if (has_error(test)) {
        std::vector<const Finding*> errors;
        for (const Finding* f : test.findings)
          if (f->severity == Severity::error) errors.push_back(f);
        c.failure = errors.front()->message;
        if (errors.size() > 1) c.failure += " (and " + std::to_string(errors.size() - 1) + " more)";
        c.failure_type = test.check;
        c.failure_text = diagnostics(test.findings, true);
      } else if (test.skipped) {
        c.skipped = test.skip_reason;
      }
      c.system_out = diagnostics(test.findings, false);
      s.cases.push_back(std::move(c));
    }
    out.push_back(std::move(s));
  }
  return junit_xml(out);
}

std::string junit_xml(const std::vector<JunitSuite>& suites) {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  tinyxml2::XMLElement* root = doc.NewElement("testsuites");
  doc.InsertEndChild(root);
  root->SetAttribute("name", "uabt");

  std::size_t total_tests = 0, total_failures = 0, total_skipped = 0;
  for (const auto& suite : suites) {
    tinyxml2::XMLElement* suite_element = doc.NewElement("testsuite");
    root->InsertEndChild(suite_element);
    std::size_t failures = 0, skipped = 0;
    for (const auto& test : suite.cases) {
      failures += test.failure.empty() ? 0 : 1;
      skipped += test.failure.empty() && !test.skipped.empty() ? 1 : 0;
    }
    suite_element->SetAttribute("name", detail::clean_text(suite.name).c_str());
    suite_element->SetAttribute("tests", static_cast<std::uint64_t>(suite.cases.size()));
    suite_element->SetAttribute("failures", static_cast<std::uint64_t>(failures));
    suite_element->SetAttribute("errors", 0);
    suite_element->SetAttribute("skipped", static_cast<std::uint64_t>(skipped));
    total_tests += suite.cases.size();
    total_failures += failures;
    total_skipped += skipped;

    for (const auto& test : suite.cases) {
      tinyxml2::XMLElement* element = doc.NewElement("testcase");
      suite_element->InsertEndChild(element);
      element->SetAttribute("classname", detail::clean_text(suite.name).c_str());
      element->SetAttribute("name", detail::clean_text(test.name).c_str());
      if (!test.failure.empty()) {
        tinyxml2::XMLElement* failure = doc.NewElement("failure");
        element->InsertEndChild(failure);
        failure->SetAttribute("message", detail::clean_text(test.failure).c_str());
        failure->SetAttribute("type", detail::clean_text(test.failure_type).c_str());
        failure->SetText(detail::clean_text(test.failure_text).c_str());
      } else if (!test.skipped.empty()) {
        tinyxml2::XMLElement* skip = doc.NewElement("skipped");
        element->InsertEndChild(skip);
        skip->SetAttribute("message", test.skipped.c_str());
      }
      if (!test.system_out.empty()) {
        tinyxml2::XMLElement* out = doc.NewElement("system-out");
        element->InsertEndChild(out);
        out->SetText(detail::clean_text(test.system_out).c_str());
      }
    }
  }
  // The totals are known only now; tinyxml2 keeps attributes in the order they are set.
  root->SetAttribute("tests", static_cast<std::uint64_t>(total_tests));
  root->SetAttribute("failures", static_cast<std::uint64_t>(total_failures));
  root->SetAttribute("errors", 0);
  root->SetAttribute("skipped", static_cast<std::uint64_t>(total_skipped));

  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return std::string(printer.CStr());
}

}  // namespace uabt::report
