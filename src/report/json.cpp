#include <nlohmann/json.hpp>

#include "report/common.hpp"
#include "report/reports.hpp"
#include "report/uplink_sections.hpp"

namespace uabt::report {

namespace {

using Json = nlohmann::ordered_json;

Json strings_json(const std::vector<std::string>& items) {
  Json out = Json::array();
  for (const auto& item : items) out.push_back(item);
  return out;
}

Json finding_json(const Finding& finding) {
  Json out;
  out["check"] = finding.check;
  out["severity"] = severity_name(finding.severity);
  out["message"] = finding.message;
  out["location"] = Json{{"file", finding.location.file},
                         {"line", finding.location.line},
                         {"column", finding.location.column}};
  // Always present, empty when not applicable, so that scripts need no existence checks.
  out["adaptable"] = finding.adaptable;
  out["requirements"] = strings_json(finding.requirements);
  out["alternatives"] = strings_json(finding.alternatives);
  out["witness"] = detail::witness_json(finding.witness);
  if (!finding.node_path.empty()) out["node_path"] = finding.node_path;
  if (!finding.notes.empty()) out["notes"] = strings_json(finding.notes);
  return out;
}

Json coverage_json(const verify::Coverage& coverage) {
  Json out;
  out["adaptable"] = coverage.adaptable;
  out["states"] = coverage.states;
  out["counted"] = coverage.counted;
  if (!coverage.counted) out["not_counted_reason"] = coverage.not_counted_reason;
  Json alternatives = Json::array();
  for (const auto& alternative : coverage.alternatives) {
    alternatives.push_back(Json{{"name", alternative.name},
                                {"requirement", alternative.requirement},
                                {"states", alternative.states},
                                {"reachable", alternative.reachable}});
  }
  out["alternatives"] = std::move(alternatives);
  out["gap_states"] = coverage.gap_states;
  out["overlap_states"] = coverage.overlap_states;
  if (!coverage.gap_region.empty()) out["gap_region"] = strings_json(coverage.gap_region);
  return out;
}

}  // namespace

std::string to_json(const ReportInput& input) {
  Json out;
  out["tool"] = "uabt";
  out["version"] = input.tool_version;
  out["mission"] = input.mission_name;
  out["verdict"] = input.passed() ? "pass" : "fail";
  Json findings = Json::array();
  for (const auto& finding : input.findings) findings.push_back(finding_json(finding));
  out["findings"] = std::move(findings);
  Json coverage = Json::array();
  for (const auto& entry : input.coverage) coverage.push_back(coverage_json(entry));
  out["coverage"] = std::move(coverage);
  if (input.uplink) out["uplink"] = detail::uplink_json(*input.uplink);
  // A message with invalid UTF-8 (from a broken input file) must not abort the report.
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace uabt::report
