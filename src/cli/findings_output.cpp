#include "cli/findings_output.hpp"

#include <filesystem>
#include <iostream>

#include "cli/common.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::cli {

void add_findings_output_options(CLI::App& cmd, std::string& format, std::string& output) {
  cmd.add_option("--format", format, "findings format")
      ->check(CLI::IsMember({"text", "json", "sarif", "junit"}));
  cmd.add_option("-o,--output", output, "write the findings to FILE instead of standard output");
}

std::string uri_prefix_of(const std::string& mission_arg) {
  const std::filesystem::path p = std::filesystem::path(mission_arg).lexically_normal();
  if (p.is_absolute() || p.empty() || *p.begin() == "..") return {};
  std::string text = p.generic_string();
  while (!text.empty() && text.back() == '/') text.pop_back();
  if (text.empty() || text == ".") return {};
  return text + "/";
}

report::ReportInput report_input(const load::Mission& mission, std::vector<std::string> stages) {
  report::ReportInput input;
  input.tool_version = tool_version();
  input.mission_name = mission.name;
  input.mission = &mission;
  for (const auto& site : mission.adaptables) {
    bool seen = false;
    for (const auto& id : input.adaptables) seen |= id == site.id;
    if (!seen && !site.id.empty()) input.adaptables.push_back(site.id);
  }
  input.findings = mission.findings;
  input.stages = std::move(stages);
  return input;
}

int write_findings(const report::ReportInput& input, const std::string& format,
                   const std::string& output) {
  std::string text;
  if (format == "json") {
    text = report::to_json(input);
  } else if (format == "sarif") {
    text = report::to_sarif(input);
  } else if (format == "junit") {
    text = report::to_junit(input);
  } else {
    text = report::format_text(input.findings);
    text += input.mission_name + ": " + (input.passed() ? "pass" : "fail") + "\n";
    if (output.empty()) {
      std::cerr << text;
      return input.passed() ? kExitPass : kExitFail;
    }
  }
  emit(output, text);
  return input.passed() ? kExitPass : kExitFail;
}

}  // namespace uabt::cli
