#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

#include "base/number_text.hpp"
#include "report/common.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::report {

namespace {

using Json = nlohmann::ordered_json;

// The base of every artifact URI: the source root (--source-root, default the git work tree).
constexpr const char* kSourceRoot = "%SRCROOT%";

// SARIF's levels bear uabt's severity names: error, warning, note.
const char* sarif_level(Severity severity) {
  return severity_name(severity);
}

// RFC 3986: keep unreserved characters and '/', percent-encode every other byte, so that a
// file name with a space or '#' still names the file.
std::string uri_encode(const std::string& path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : path) {
    const bool keep = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
    if (keep) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(first, last - first + 1));
}

Json rule_json(const CheckInfo& check) {
  const std::string doc = trimmed(check.doc);
  Json rule;
  rule["id"] = check.id;
  rule["name"] = detail::camel_case(check.id);
  rule["shortDescription"] = Json{{"text", check.summary}};
  rule["fullDescription"] = Json{{"text", doc}, {"markdown", doc}};
  rule["help"] = Json{{"text", doc}, {"markdown", doc}};
  rule["defaultConfiguration"] = Json{{"level", check.severity}};
  rule["properties"] = Json{{"tags", Json::array({"uabt", check.stage})}};
  return rule;
}

// A finding of a check the catalogue does not know (a programming error elsewhere) still
// needs a rule, or the result would point nowhere.
Json undocumented_rule_json(const std::string& id, Severity severity) {
  Json rule;
  rule["id"] = id;
  rule["name"] = detail::camel_case(id);
  rule["shortDescription"] = Json{{"text", id + " (not documented in checks/)"}};
  rule["defaultConfiguration"] = Json{{"level", sarif_level(severity)}};
  return rule;
}

// A file of the mission: relative to the source root with %SRCROOT% (GitHub places it in the
// repository), or an absolute file URI when the mission lies outside the root.
Json artifact_location(const std::string& uri_prefix, const std::string& file) {
  std::string path = std::filesystem::path(uri_prefix + file).lexically_normal().generic_string();
  if (!path.empty() && path.front() == '/') return Json{{"uri", "file://" + uri_encode(path)}};
  return Json{{"uri", uri_encode(path)}, {"uriBaseId", kSourceRoot}};
}

Json physical_location(const std::string& uri_prefix, const SourceLocation& location,
                       const std::string& fallback_file) {
  Json physical;
  physical["artifactLocation"] =
      artifact_location(uri_prefix, location.file.empty() ? fallback_file : location.file);
  if (location.line > 0) {
    Json region;
    region["startLine"] = location.line;
    if (location.column > 0) region["startColumn"] = location.column;
    if (location.end_line > location.line) region["endLine"] = location.end_line;
    physical["region"] = std::move(region);
  }
  return physical;
}

}  // namespace

std::string to_sarif(const ReportInput& input) {
  // Rules: the whole catalogue sorted by id, then any undocumented check a finding uses.
  Json rules = Json::array();
  std::map<std::string, std::size_t> rule_index;
  for (const CheckInfo* check : detail::sorted_catalogue()) {
    rule_index.emplace(check->id, rules.size());
    rules.push_back(rule_json(*check));
  }
  std::map<std::string, Severity> undocumented;
  for (const auto& finding : input.findings)
    if (!rule_index.count(finding.check)) undocumented.emplace(finding.check, finding.severity);
  for (const auto& [id, severity] : undocumented) {
    rule_index.emplace(id, rules.size());
    rules.push_back(undocumented_rule_json(id, severity));
  }

  // GitHub rejects the whole file when one result has no location: a finding without a file
  // is anchored at the mission's tree file, without a region.
  std::string fallback_file = "mission.xml";
  if (input.mission != nullptr && !input.mission->tree.file.empty())
    fallback_file = input.mission->tree.file;

  Json results = Json::array();
  std::map<std::tuple<std::string, std::string, std::string>, int> occurrences;
  for (const auto& finding : input.findings) {
    Json result;
    result["ruleId"] = finding.check;
    result["ruleIndex"] = rule_index.at(finding.check);
    result["level"] = sarif_level(finding.severity);
    std::string text = finding.message;
    if (!finding.witness.empty()) text += " (witness: " + format_state(finding.witness) + ")";
    // Code scanning shows the message, not the properties: a counterexample's replay command
    // and tick-by-tick table go into it.
    if (finding.check == "prove-violated")
      for (const auto& note : finding.notes) text += "\n" + note;
    result["message"] = Json{{"text", text}};

    result["locations"] =
        Json::array({Json{{"physicalLocation",
                           physical_location(input.uri_prefix, finding.location, fallback_file)}}});
    if (!finding.related.empty()) {
      Json related = Json::array();
      for (std::size_t k = 0; k < finding.related.size(); ++k) {
        const auto& r = finding.related[k];
        related.push_back(Json{
            {"id", k},
            {"physicalLocation", physical_location(input.uri_prefix, r.location, fallback_file)},
            {"message", Json{{"text", r.message}}}});
      }
      result["relatedLocations"] = std::move(related);
    }

    // Identity of a finding across commits: check, file and message, not the line, so that an
    // edit above it does not make code scanning see a new alert. Identical findings are told
    // apart by their occurrence, as CodeQL's own fingerprints do.
    const int occurrence = ++occurrences[{finding.check, finding.location.file, finding.message}];
    const std::uint64_t hash = detail::fnv1a(
        finding.message,
        detail::fnv1a(finding.location.file + '\n', detail::fnv1a(finding.check + '\n')));
    result["partialFingerprints"] =
        Json{{"uabtFindingHash/v1", detail::hex64(hash) + ":" + std::to_string(occurrence)}};

    Json properties;
    properties["adaptable"] = finding.adaptable;
    properties["requirements"] = Json(finding.requirements);
    properties["alternatives"] = Json(finding.alternatives);
    properties["witness"] = state_json(finding.witness);
    if (!finding.node_path.empty()) properties["node_path"] = finding.node_path;
    if (!finding.notes.empty()) properties["notes"] = Json(finding.notes);
    result["properties"] = std::move(properties);
    results.push_back(std::move(result));
  }

  Json driver;
  driver["name"] = "uabt";
  driver["version"] = input.tool_version;
  driver["rules"] = std::move(rules);

  Json run;
  run["tool"] = Json{{"driver", std::move(driver)}};
  // Several missions of one repository upload as separate analyses.
  run["automationDetails"] = Json{{"id", "uabt/" + input.mission_name + "/"}};
  // The root is where the report is used, not where it was made: no absolute path here.
  run["originalUriBaseIds"] =
      Json{{kSourceRoot, Json{{"description", Json{{"text",
                                                    "The source root: the top of the git "
                                                    "work tree that holds the mission, or "
                                                    "--source-root."}}}}}};
  run["results"] = std::move(results);
  // The verdict in the reports' words ("pass with 1 guarantee retired"), for code scanning
  // integrations that show run properties.
  run["properties"] = Json{{"verdict", input.verdict_text()}};

  Json sarif;
  sarif["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  sarif["version"] = "2.1.0";
  sarif["runs"] = Json::array({std::move(run)});
  return sarif.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace uabt::report
