#include "report/uplink_sections.hpp"

#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"
#include "report/common.hpp"
#include "report/impact.hpp"
#include "report/proof_timeline.hpp"

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

std::string changed_states_text(const verify::NodeImpact& node,
                                const verify::SelectionChange& change) {
  if (node.counted)
    return std::to_string(change.states) + " (" + change.share.text + ", " +
           percent(change.states, node.states) + ")";
  return node.measured ? space_share(change.share) : "not counted";
}

std::string node_summary(const verify::NodeImpact& node) {
  if (node.status == "unchanged") return "no state changes its alternative";
  if (node.status == "added" || node.status == "removed")
    return "the uplink " + std::string(node.status == "added" ? "adds" : "removes") +
           " this node's requirements";
  if (node.counted)
    return std::to_string(node.changed_states) + " of " + std::to_string(node.states) +
           " states (" + node.changed_share.text + ", " +
           percent(node.changed_states, node.states) + ") change their alternative";
  if (node.measured) return space_share(node.changed_share) + " changes its alternative";
  return "some states change (not counted: " + node.not_counted_reason + ")";
}

// "weakened (uplink.json: weaken, "reason")".
std::string change_text(const ContractChange& c) {
  std::string out = c.change;
  if (c.change == "removed" && c.old_holds) out += ", still holds";
  if (!c.consent.empty()) out += " (uplink.json " + c.consent + "s it: " + c.consent_reason + ")";
  return out;
}

// The cells of one contract row: guarantee, change, status on board, the old statement on the
// merged mission, the new statement on the merged mission.
std::vector<std::string> contract_cells(const ContractChange& c) {
  return {c.requirement, change_text(c), c.before.empty() ? "-" : c.before,
          c.old_after.empty() ? "-" : c.old_after, c.after.empty() ? "-" : c.after};
}

const char* const kContractHeader[] = {"Guarantee", "Change", "Before (on board)",
                                       "Old statement, merged", "New statement, merged"};

// JSON null for "not there" (an empty text, an unset priority), the value otherwise.
Json or_null(const std::string& text) {
  return text.empty() ? Json(nullptr) : Json(text);
}
Json or_null(int number) {
  return number == 0 ? Json(nullptr) : Json(number);
}

}  // namespace

std::string uplink_counterexample_id(std::size_t index) {
  return "uplink-cex-" + std::to_string(index);
}

Json uplink_json(const UplinkChange& uplink) {
  Json merges = Json::array();
  for (const auto& m : uplink.merges) {
    Json j;
    j["requirement"] = m.requirement;
    j["rule"] = m.rule;
    j["relation"] = or_null(m.relation);
    j["anchor"] = or_null(m.anchor);
    j["adaptable"] = or_null(m.adaptable);
    j["priority"] = or_null(m.priority);
    j["of"] = m.priority == 0 ? Json(nullptr) : Json(m.of);
    j["location"] =
        Json{{"file", m.location.file}, {"line", m.location.line}, {"column", m.location.column}};
    merges.push_back(std::move(j));
  }
  Json contract = Json::array();
  for (const ContractChange& c : uplink.contract) {
    Json j;
    j["requirement"] = c.requirement;
    j["change"] = c.change;
    j["before_text"] = or_null(c.before_text);
    j["after_text"] = or_null(c.after_text);
    j["before"] = or_null(c.before);
    j["old_after"] = or_null(c.old_after);
    j["after"] = or_null(c.after);
    j["old_holds"] = c.old_holds;
    j["consent"] = or_null(c.consent);
    j["consent_reason"] = or_null(c.consent_reason);
    contract.push_back(std::move(j));
  }
  Json out;
  out["package"] = uplink.package;
  out["contract"] = std::move(contract);
  out["merge"] = std::move(merges);
  out["behaviour_change"] = impact_nodes_json(uplink.impact);
  return out;
}

std::string uplink_markdown(const UplinkChange& uplink) {
  std::string out = "\n### Uplink " + markdown_code(uplink.package) + "\n\n";
  if (!uplink.contract.empty()) {
    out += "Guarantees the uplink changes (the mission's contract):\n\n|";
    for (const char* h : kContractHeader) out += std::string(" ") + h + " |";
    out += "\n|---|---|---|---|---|\n";
    for (const ContractChange& c : uplink.contract) {
      const std::vector<std::string> cells = contract_cells(c);
      out += "| " + markdown_code(cells[0]) + " |";
      for (std::size_t i = 1; i < cells.size(); ++i) out += " " + markdown_text(cells[i]) + " |";
      out += "\n";
    }
    out += "\n";
  }
  out += "Where the merge put each requirement:\n\n";
  out += "| Requirement | Node | Rule | Priority |\n|---|---|---|---|\n";
  for (const auto& m : uplink.merges)
    out += "| " + markdown_code(m.requirement) + " | " +
           (m.adaptable.empty() ? "" : markdown_code(m.adaptable)) + " | " +
           markdown_text(rule_text(m)) + " | " + markdown_text(priority_text(m)) + " |\n";
  if (uplink.merges.empty()) out += "| *none* | | | |\n";
  out += "\nBehaviour change (running version -> merged version):\n";
  for (const auto& node : uplink.impact.nodes) {
    out += "\n- " + markdown_code(node.adaptable) + ": " + markdown_text(node_summary(node)) + "\n";
    if (node.changes.empty()) continue;
    out += "\n  | From | To | States | Example |\n  |---|---|---:|---|\n";
    for (const auto& c : node.changes)
      out += "  | " + markdown_code(alternative_text(c.from)) + " | " +
             markdown_code(alternative_text(c.to)) + " | " +
             markdown_text(changed_states_text(node, c)) + " | " +
             markdown_code(format_state(c.example)) + " |\n";
  }
  return out;
}

std::string uplink_html(const UplinkChange& uplink) {
  std::string out = "<section id=\"uplink\">\n<h2>Uplink " + html_code(uplink.package) + "</h2>\n";
  if (!uplink.contract.empty()) {
    out +=
        "<table><caption>Guarantees the uplink changes (the mission's contract)</caption>\n"
        "<thead><tr>";
    for (const char* h : kContractHeader) out += std::string("<th>") + h + "</th>";
    out += "</tr></thead>\n<tbody>\n";
    for (const ContractChange& c : uplink.contract) {
      const std::vector<std::string> cells = contract_cells(c);
      out += "<tr><td>" + html_code(cells[0]) + "</td>";
      for (std::size_t i = 1; i < cells.size(); ++i)
        out += "<td>" + html_escape(cells[i]) + "</td>";
      out += "</tr>\n";
    }
    out += "</tbody></table>\n";
    // The run of the merged mission that breaks a guarantee's old statement, drawn as the
    // Proofs section draws a violation.
    for (std::size_t k = 0; k < uplink.contract.size(); ++k) {
      const ContractChange& c = uplink.contract[k];
      if (!c.old_on_merged || !c.old_on_merged->counterexample) continue;
      const ProofCounterexample& cex = *c.old_on_merged->counterexample;
      counterexample_html(uplink_counterexample_id(k),
                          "The merged mission breaks what " + html_code(c.requirement) +
                              " said before, at tick " + std::to_string(cex.tick),
                          *c.old_on_merged, cex, nullptr, out);
    }
  }
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
             html_escape(changed_states_text(node, c)) + "</td><td>" +
             html_code(format_state(c.example)) + "</td></tr>\n";
    out += "</tbody></table>\n";
  }
  out += "</section>\n";
  return out;
}

}  // namespace uabt::report::detail
