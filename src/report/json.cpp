#include <nlohmann/json.hpp>

#include "base/number_text.hpp"
#include "report/common.hpp"
#include "report/proof_timeline.hpp"
#include "report/reports.hpp"
#include "report/uplink_sections.hpp"

namespace uabt::report {

namespace {

using Json = nlohmann::ordered_json;

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
  out["requirements"] = Json(finding.requirements);
  out["alternatives"] = Json(finding.alternatives);
  out["witness"] = state_json(finding.witness);
  if (!finding.node_path.empty()) out["node_path"] = finding.node_path;
  if (!finding.notes.empty()) out["notes"] = Json(finding.notes);
  return out;
}

// An exact quantity as a JSON number (its nearest double, written as every number is: an
// integer as an integer); the exact rational goes beside it.
Json number_json(const verify::Exact& q) {
  return uabt::number_json(q.value);
}

Json region_json(const verify::Region& region) {
  Json constraints = Json::array();
  for (const auto& c : region.constraints) {
    Json j;
    switch (c.kind) {
      case verify::RegionConstraint::Kind::interval:
        j["variable"] = c.variable;
        j["interval"] =
            Json::array({uabt::number_json(c.lower_value), uabt::number_json(c.upper_value)});
        j["closed"] = Json::array({c.lower_closed, c.upper_closed});
        break;
      case verify::RegionConstraint::Kind::values:
        j["variable"] = c.variable;
        j["values"] = Json(c.values);
        break;
      case verify::RegionConstraint::Kind::linear: j["linear"] = c.text; break;
    }
    j["text"] = c.text;
    constraints.push_back(std::move(j));
  }
  Json out;
  out["text"] = region.text();
  out["constraints"] = std::move(constraints);
  out["requirements"] = Json(region.requirements);
  if (region.measured) {
    out["measure"] = number_json(region.measure);
    out["share"] = number_json(region.share);
    out["share_exact"] = region.share.text;
  } else {
    out["measure"] = nullptr;
    out["share"] = nullptr;
  }
  if (!region.exact) out["exact"] = false;
  return out;
}

Json regions_json(const std::vector<verify::Region>& regions, std::size_t omitted) {
  Json out = Json::array();
  for (const auto& r : regions) out.push_back(region_json(r));
  if (omitted > 0) out.push_back(Json{{"omitted", omitted}});
  return out;
}

// Shares: exact when measured; else null with certified bounds [lower, upper] when bounded.
void share_json(Json& out, const char* name, const verify::Coverage& coverage,
                const verify::Exact& share, const verify::Exact& lower,
                const verify::Exact& upper) {
  if (coverage.measured) {
    out[name] = number_json(share);
    out[std::string(name) + "_exact"] = share.text;
  } else {
    out[name] = nullptr;
    if (coverage.bounded)
      out[std::string(name) + "_bounds"] = Json::array({number_json(lower), number_json(upper)});
  }
}

Json coverage_json(const verify::Coverage& coverage) {
  Json out;
  out["adaptable"] = coverage.adaptable;
  out["states"] = coverage.states;
  out["counted"] = coverage.counted;
  if (!coverage.counted) out["not_counted_reason"] = coverage.not_counted_reason;
  out["measured"] = coverage.measured;
  if (!coverage.measured) out["not_measured_reason"] = coverage.not_measured_reason;
  if (coverage.measured || coverage.bounded) {
    out["measure"] = number_json(coverage.measure);
    out["measure_exact"] = coverage.measure.text;
  } else {
    out["measure"] = nullptr;
  }
  Json alternatives = Json::array();
  for (const auto& alternative : coverage.alternatives) {
    Json a{{"name", alternative.name},
           {"requirement", alternative.requirement},
           {"states", alternative.states},
           {"reachable", alternative.reachable}};
    if (coverage.measured)
      a["measure"] = number_json(alternative.measure);
    else
      a["measure"] = nullptr;
    share_json(a, "share", coverage, alternative.share, alternative.share_lower,
               alternative.share_upper);
    alternatives.push_back(std::move(a));
  }
  out["alternatives"] = std::move(alternatives);
  out["gap_states"] = coverage.gap_states;
  out["overlap_states"] = coverage.overlap_states;
  share_json(out, "gap_share", coverage, coverage.gap_share, coverage.gap_share_lower,
             coverage.gap_share_upper);
  share_json(out, "overlap_share", coverage, coverage.overlap_share, coverage.overlap_share_lower,
             coverage.overlap_share_upper);
  out["regions"] =
      Json{{"gap", regions_json(coverage.gap_regions, coverage.gap_regions_omitted)},
           {"overlap", regions_json(coverage.overlap_regions, coverage.overlap_regions_omitted)}};
  if (!coverage.gap_region.empty()) out["gap_region"] = Json(coverage.gap_region);
  return out;
}

}  // namespace

std::string to_json(const ReportInput& input) {
  Json out;
  out["tool"] = "uabt";
  out["version"] = input.tool_version;
  out["mission"] = input.mission_name;
  out["verdict"] = input.passed() ? "pass" : "fail";
  // What the banners say when it is more than the verdict: "pass with 1 guarantee retired"
  // (an uplink gave one up with uplink.json's consent).
  if (const std::string text = input.verdict_text(); text != out["verdict"])
    out["verdict_text"] = text;
  Json findings = Json::array();
  for (const auto& finding : input.findings) findings.push_back(finding_json(finding));
  out["findings"] = std::move(findings);
  Json coverage = Json::array();
  for (const auto& entry : input.coverage) coverage.push_back(coverage_json(entry));
  out["coverage"] = std::move(coverage);
  if (input.uplink) out["uplink"] = detail::uplink_json(*input.uplink);
  if (input.proofs && !input.proofs->answers.empty()) out["proofs"] = proofs_json(*input.proofs);
  // A message with invalid UTF-8 (from a broken input file) must not abort the report.
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace uabt::report
