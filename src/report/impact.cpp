#include "report/impact.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"
#include "base/number_text.hpp"
#include "base/text.hpp"
#include "report/common.hpp"
#include "report/coverage_view.hpp"

namespace uabt::report {

namespace {

using detail::alternative_text;

using Json = nlohmann::ordered_json;

Json name_or_null(const std::string& name) {
  return name.empty() ? Json(nullptr) : Json(name);
}

// A share as JSON: from the counts as before (null over an empty domain), the measured one's
// number as number_json writes it, null when neither.
Json share_json(const verify::NodeImpact& node, const verify::Exact& share) {
  if (node.counted) return node.states == 0 ? Json(nullptr) : Json(share.value);
  return node.measured ? uabt::number_json(share.value) : Json(nullptr);
}
Json share_exact_json(const verify::NodeImpact& node, const verify::Exact& share) {
  return node.measured ? Json(share.text) : Json(nullptr);
}

// "hold_position (Safe) -> on_mud (Req3)"
std::string move_text(const verify::SelectionChange& c) {
  auto side = [](const std::string& alt, const std::string& req) {
    return alternative_text(alt) + (req.empty() ? "" : " (" + req + ")");
  };
  return side(c.from, c.from_requirement) + " -> " + side(c.to, c.to_requirement);
}

// Measured but not counted: how much of the space changes, in the coverage section's words.
bool shares_only(const verify::NodeImpact& node) {
  return node.measured && !node.counted;
}

}  // namespace

std::string space_share(const verify::Exact& share) {
  return detail::share_text({share.value, share.text}) + " of the space";
}

std::string impact_text(const verify::Impact& impact) {
  std::string out;
  for (const auto& node : impact.nodes) {
    out += node.adaptable + ": " + node.status;
    if (node.counted)
      out += " (" + std::to_string(node.changed_states) + " of " + std::to_string(node.states) +
             " states, " + node.changed_share.text + ", change their alternative)";
    else if (shares_only(node))
      out += " (" + space_share(node.changed_share) + " changes its alternative)";
    else if (!node.not_counted_reason.empty() && node.status == "changed")
      out += " (states not counted: " + node.not_counted_reason + ")";
    out += "\n";
    for (const auto& c : node.changes) {
      out += "  " + move_text(c);
      if (node.counted)
        out += ": " + count_text(c.states, "state") + " (" + c.share.text + ")";
      else if (shares_only(node))
        out += ": " + space_share(c.share);
      out += "\n    e.g. " + format_state(c.example) + "\n";
    }
  }
  if (!impact.findings.empty()) out += format_text(impact.findings);
  return out;
}

Json impact_nodes_json(const verify::Impact& impact) {
  Json nodes = Json::array();
  for (const auto& node : impact.nodes) {
    const bool counted = node.counted;
    Json changes = Json::array();
    for (const auto& c : node.changes) {
      Json j;
      j["from"] = name_or_null(c.from);
      j["to"] = name_or_null(c.to);
      j["from_requirement"] = name_or_null(c.from_requirement);
      j["to_requirement"] = name_or_null(c.to_requirement);
      j["states"] = counted ? Json(c.states) : Json(nullptr);
      j["share"] = share_json(node, c.share);
      j["share_exact"] = share_exact_json(node, c.share);
      j["example"] = state_json(c.example);
      changes.push_back(std::move(j));
    }
    Json j;
    j["adaptable"] = node.adaptable;
    j["status"] = node.status;
    j["counted"] = counted;
    j["states"] = counted ? Json(node.states) : Json(nullptr);
    j["changed_states"] = counted ? Json(node.changed_states) : Json(nullptr);
    j["changed_share"] = share_json(node, node.changed_share);
    j["changed_share_exact"] = share_exact_json(node, node.changed_share);
    j["not_counted_reason"] =
        counted || node.not_counted_reason.empty() ? Json(nullptr) : Json(node.not_counted_reason);
    j["changes"] = std::move(changes);
    nodes.push_back(std::move(j));
  }
  return nodes;
}

std::string impact_json(const verify::Impact& impact) {
  Json findings = Json::array();
  for (const auto& f : impact.findings)
    findings.push_back({{"check", f.check}, {"message", f.message}, {"adaptable", f.adaptable}});
  Json root;
  root["tool"] = "uabt";
  root["changed"] =
      std::any_of(impact.nodes.begin(), impact.nodes.end(),
                  [](const verify::NodeImpact& n) { return n.status != "unchanged"; });
  root["nodes"] = impact_nodes_json(impact);
  root["findings"] = std::move(findings);
  return root.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::vector<Finding> behaviour_change_findings(const verify::Impact& impact,
                                               const load::Mission& mission) {
  std::vector<Finding> out;
  for (const auto& node : impact.nodes) {
    if (node.status == "unchanged") continue;
    SourceLocation where{mission.requirements_file, 0, 0};
    for (const auto& site : mission.adaptables)
      if (site.id == node.adaptable) {
        where = site.location;
        break;
      }
    std::string message = node.adaptable + ": ";
    if (node.status == "added" || node.status == "removed")
      message += "the uplink " + std::string(node.status == "added" ? "adds" : "removes") +
                 " this adaptable node's requirements";
    else if (node.counted)
      message += std::to_string(node.changed_states) + " of " + count_text(node.states, "state") +
                 " (" + node.changed_share.text + ") change their alternative";
    else if (shares_only(node))
      message += space_share(node.changed_share) + " changes its alternative";
    else
      message +=
          "some states change their alternative (not counted: " + node.not_counted_reason + ")";
    Finding f = make_finding("uplink-behaviour-change", message, where);
    f.adaptable = node.adaptable;
    for (const auto& c : node.changes) {
      std::string note = move_text(c);
      if (node.counted)
        note += ": " + count_text(c.states, "state") + " (" + c.share.text + ")";
      else if (shares_only(node))
        note += ": " + space_share(c.share);
      note += ", e.g. " + format_state(c.example);
      f.notes.push_back(std::move(note));
      for (const auto* alt : {&c.from, &c.to})
        if (!alt->empty() &&
            std::find(f.alternatives.begin(), f.alternatives.end(), *alt) == f.alternatives.end())
          f.alternatives.push_back(*alt);
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace uabt::report
