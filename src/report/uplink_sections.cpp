#include "report/uplink_sections.hpp"

#include "base/diagnostics.hpp"
#include "report/common.hpp"
#include "report/impact.hpp"

namespace uabt::report::detail {

namespace {

using Json = nlohmann::ordered_json;

// "placed before Req2", "appended (last before the default)", …
std::string rule_text(const load::UplinkMerge& m) {
  if (m.rule == "placed") return "placed " + m.relation + " " + m.anchor + " (uplink.json)";
  if (m.rule == "appended") return "new id: last before the default";
  if (m.rule == "replaced") return "existing id: replaced in place";
  return "removed (uplink.json)";
}

std::string priority_text(const load::UplinkMerge& m) {
  if (m.rule == "removed") return "-";
  if (m.priority == 0) return "not a selection requirement";
  return std::to_string(m.priority) + " of " + std::to_string(m.of);
}

std::string alternative_text(const std::string& alternative) {
  return alternative.empty() ? "(nothing: the node fails)" : alternative;
}

std::string count_text(const verify::NodeImpact& node, std::uint64_t part) {
  if (!node.counted) return "not counted";
  return std::to_string(part) + " (" + exact_share(part, node.states) + ", " +
         percent(part, node.states) + ")";
}

std::string node_summary(const verify::NodeImpact& node) {
  if (node.status == "unchanged") return "no state changes its alternative";
  if (node.status == "added" || node.status == "removed")
    return "the uplink " + std::string(node.status == "added" ? "adds" : "removes") +
           " this node's requirements";
  if (!node.counted) return "some states change (not counted: " + node.not_counted_reason + ")";
  return std::to_string(node.changed_states) + " of " + std::to_string(node.states) + " states (" +
         exact_share(node.changed_states, node.states) + ", " +
         percent(node.changed_states, node.states) + ") change their alternative";
}

// A Markdown code span for identifiers and states (they hold no backtick or '|').
std::string span(const std::string& text) {
  const std::string clean = clean_text(text);
  if (clean.find_first_of("`|\n") != std::string::npos) return html_escape(clean);
  return "`" + clean + "`";
}

std::string html_code(const std::string& text) {
  return "<code>" + html_escape(text) + "</code>";
}

}  // namespace

Json uplink_json(const UplinkChange& uplink) {
  Json merges = Json::array();
  for (const auto& m : uplink.merges) {
    Json j;
    j["requirement"] = m.requirement;
    j["rule"] = m.rule;
    j["relation"] = m.relation.empty() ? Json(nullptr) : Json(m.relation);
    j["anchor"] = m.anchor.empty() ? Json(nullptr) : Json(m.anchor);
    j["adaptable"] = m.adaptable.empty() ? Json(nullptr) : Json(m.adaptable);
    j["priority"] = m.priority == 0 ? Json(nullptr) : Json(m.priority);
    j["of"] = m.priority == 0 ? Json(nullptr) : Json(m.of);
    j["location"] =
        Json{{"file", m.location.file}, {"line", m.location.line}, {"column", m.location.column}};
    merges.push_back(std::move(j));
  }
  Json out;
  out["package"] = uplink.package;
  out["merge"] = std::move(merges);
  out["behaviour_change"] = impact_nodes_json(uplink.impact);
  return out;
}

std::string uplink_markdown(const UplinkChange& uplink) {
  std::string out = "\n### Uplink " + span(uplink.package) + "\n\n";
  out += "Where the merge put each requirement:\n\n";
  out += "| Requirement | Node | Rule | Priority |\n|---|---|---|---|\n";
  for (const auto& m : uplink.merges)
    out += "| " + span(m.requirement) + " | " + (m.adaptable.empty() ? "" : span(m.adaptable)) +
           " | " + rule_text(m) + " | " + priority_text(m) + " |\n";
  if (uplink.merges.empty()) out += "| *none* | | | |\n";
  out += "\nBehaviour change (running version -> merged version):\n";
  for (const auto& node : uplink.impact.nodes) {
    out += "\n- " + span(node.adaptable) + ": " + node_summary(node) + "\n";
    if (node.changes.empty()) continue;
    out += "\n  | From | To | States | Example |\n  |---|---|---:|---|\n";
    for (const auto& c : node.changes)
      out += "  | " + span(alternative_text(c.from)) + " | " + span(alternative_text(c.to)) +
             " | " + count_text(node, c.states) + " | " + span(format_state(c.example)) + " |\n";
  }
  return out;
}

std::string uplink_html(const UplinkChange& uplink) {
  std::string out = "<section id=\"uplink\">\n<h2>Uplink " + html_code(uplink.package) + "</h2>\n";
  out +=
      "<table><caption>Where the merge put each requirement</caption>\n<thead><tr><th>Requirement"
      "</th><th>Node</th><th>Rule</th><th>Priority</th></tr></thead>\n<tbody>\n";
  for (const auto& m : uplink.merges)
    out += "<tr><td>" + html_code(m.requirement) + "</td><td>" +
           (m.adaptable.empty() ? "" : html_code(m.adaptable)) + "</td><td>" +
           html_escape(rule_text(m)) + "</td><td>" + html_escape(priority_text(m)) + "</td></tr>\n";
  out += "</tbody></table>\n<h3>Behaviour change</h3>\n";
  for (const auto& node : uplink.impact.nodes) {
    out += "<p>" + html_code(node.adaptable) + ": " + html_escape(node_summary(node)) + "</p>\n";
    if (node.changes.empty()) continue;
    out +=
        "<table><thead><tr><th>From</th><th>To</th><th>States</th><th>Example state</th></tr>"
        "</thead>\n<tbody>\n";
    for (const auto& c : node.changes)
      out += "<tr><td>" + html_code(alternative_text(c.from)) + "</td><td>" +
             html_code(alternative_text(c.to)) + "</td><td>" +
             html_escape(count_text(node, c.states)) + "</td><td>" +
             html_code(format_state(c.example)) + "</td></tr>\n";
    out += "</tbody></table>\n";
  }
  out += "</section>\n";
  return out;
}

}  // namespace uabt::report::detail
