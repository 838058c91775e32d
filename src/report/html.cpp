#include <algorithm>
#include <set>

#include "fretish/expr.hpp"
#include "report/common.hpp"
#include "report/coverage_view.hpp"
#include "report/proof_timeline.hpp"
#include "report/reports.hpp"
#include "report/uplink_sections.hpp"

namespace uabt::report {

namespace {

using detail::anchor;
using detail::html_code;
using detail::html_escape;
using detail::inline_svg;

constexpr const char* kStyle = R"css(
:root { color-scheme: light; }
body { font: 15px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; margin: 0;
       color: #1f2328; background: #fff; }
header { display: flex; align-items: center; gap: 28px; padding: 24px 32px;
         border-bottom: 6px solid; }
header.pass { border-color: #1a7f37; background: #dafbe1; }
header.fail { border-color: #cf222e; background: #ffebe9; }
.badge { font-size: 52px; font-weight: 800; letter-spacing: .06em; padding: 2px 22px;
         border-radius: 10px; color: #fff; }
.pass .badge { background: #1a7f37; }
.fail .badge { background: #cf222e; }
header h1 { margin: 0; font-size: 28px; }
header p { margin: 4px 0 0; }
main { padding: 8px 32px 32px; max-width: 1100px; }
nav { padding: 12px 32px; border-bottom: 1px solid #d0d7de; font-size: 14px; }
nav a { margin-right: 16px; }
h2 { border-bottom: 1px solid #d0d7de; padding-bottom: 4px; margin-top: 32px; }
code { font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; font-size: 90%;
       background: #f6f8fa; padding: 1px 4px; border-radius: 4px; }
.finding { border: 1px solid #d0d7de; border-left: 6px solid; border-radius: 6px;
           padding: 8px 14px; margin: 12px 0; }
.finding p { margin: 4px 0; }
.finding.error { border-left-color: #cf222e; }
.finding.warning { border-left-color: #bf8700; }
.finding.note { border-left-color: #0969da; }
.sev { font-weight: 700; text-transform: uppercase; font-size: 12px; padding: 1px 6px;
       border-radius: 4px; color: #fff; }
.error .sev { background: #cf222e; }
.warning .sev { background: #9a6700; }
.note .sev { background: #0969da; }
.msg { font-weight: 600; }
.meta, .hint { color: #57606a; font-size: 13px; }
table { border-collapse: collapse; margin: 8px 0; }
th, td { border: 1px solid #d0d7de; padding: 3px 10px; text-align: left; vertical-align: top; }
th { background: #f6f8fa; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
caption { text-align: left; font-size: 13px; color: #57606a; }
.swatch { display: inline-block; width: 12px; height: 12px; border: 1px solid #333;
          vertical-align: -1px; margin-right: 6px; }
.swatch.gap { background: repeating-linear-gradient(45deg, #d62728 0 3px, #fde0e0 3px 6px); }
table.conflicts td { text-align: center; color: #d62728; }
table.decision tr.gap td { background: #ffebe9; }
table.decision tr.overlap td { background: #eaeef2; }
table.decision tr.gap td:first-child { border-left: 4px solid #d62728; }
table.decision tr.overlap td:first-child { border-left: 4px solid #4d4d4d; }
.callout { border-left: 4px solid #cf222e; background: #fff5f5; padding: 6px 12px; }
.callout.info { border-color: #0969da; background: #f1f8ff; }
svg { max-width: 100%; height: auto; display: block; margin: 8px 0; }
footer { padding: 16px 32px; color: #57606a; font-size: 13px; border-top: 1px solid #d0d7de; }
@media print { nav { display: none; } header { border-bottom-width: 2px; } }
)css";

std::string code_list(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + html_code(item);
  return out;
}

std::string state_words(const State& state) {
  std::string out;
  for (const auto& [name, value] : state) {
    if (!out.empty()) out += ", ";
    out += html_code(name) + " = " + html_code(value.to_string());
  }
  return out;
}

// Where the report draws a finding's counterexample as a timeline: "#proofs" for a violated
// guarantee, the uplink section's article for a guarantee an uplink breaks; "" when nowhere.
std::string timeline_link(const ReportInput& input, const Finding& finding) {
  if (finding.check == "prove-violated") return "#proofs";
  if (!input.uplink || finding.requirements.size() != 1) return "";
  if (finding.check != "uplink-guarantee-weakened" && finding.check != "uplink-guarantee-removed")
    return "";
  const auto& contract = input.uplink->contract;
  for (std::size_t k = 0; k < contract.size(); ++k)
    if (contract[k].requirement == finding.requirements.front() && contract[k].old_on_merged &&
        contract[k].old_on_merged->counterexample)
      return "#" + detail::uplink_counterexample_id(k);
  return "";
}

// The anchor of the k-th (1-based) `requirements-unrealizable` finding, which the conflict
// matrix links to.
std::string conflict_anchor(std::size_t k) {
  return "conflict-" + std::to_string(k);
}

// The findings the conflict matrix shows: every minimal conflict, in report order.
std::vector<const Finding*> conflicts_of(const ReportInput& input) {
  std::vector<const Finding*> out;
  for (const auto& f : input.findings)
    if (f.check == "requirements-unrealizable") out.push_back(&f);
  return out;
}

void finding_html(const Finding& finding, const std::string& timeline, std::string& out,
                  const std::string& id = "") {
  const char* severity = severity_name(finding.severity);
  out += std::string("<article class=\"finding ") + severity + "\"" +
         (id.empty() ? "" : " id=\"" + id + "\"") + ">\n";
  out += std::string("<p><span class=\"sev\">") + severity + "</span> " + html_code(finding.check) +
         " at " + html_code(detail::location_text(finding.location)) + "</p>\n";
  out += "<p class=\"msg\">" + html_escape(finding.message) + "</p>\n";
  std::string meta;
  if (!finding.requirements.empty()) meta += "Requirements: " + code_list(finding.requirements);
  if (!finding.alternatives.empty())
    meta += (meta.empty() ? "" : " · ") + std::string("Alternatives: ") +
            code_list(finding.alternatives);
  if (!finding.node_path.empty())
    meta += (meta.empty() ? "" : " · ") + std::string("Node: ") + html_code(finding.node_path);
  if (!meta.empty()) out += "<p class=\"meta\">" + meta + "</p>\n";
  if (!timeline.empty() && !finding.notes.empty()) {
    // The counterexample's table keeps its columns; another section draws its timeline.
    std::string table;
    for (const auto& note : finding.notes) table += html_escape(note) + "\n";
    out += "<pre>" + table + "</pre>\n<p class=\"meta\"><a href=\"" + html_escape(timeline) +
           "\">The counterexample as a timeline</a></p>\n";
  } else if (!finding.notes.empty()) {
    out += "<ul class=\"meta\">\n";
    for (const auto& note : finding.notes) out += "<li>" + html_escape(note) + "</li>\n";
    out += "</ul>\n";
  }
  if (!finding.related.empty()) {
    // The places the terminal lists after the notes (SARIF's relatedLocations), in their order:
    // a path of ticks from the root, the ancestors of a node, the other half of a conflict.
    out += "<ol class=\"meta related\">\n";
    for (const auto& r : finding.related)
      out += "<li>" + html_code(detail::location_text(r.location)) + " " + html_escape(r.message) +
             "</li>\n";
    out += "</ol>\n";
  }
  if (!finding.witness.empty()) {
    out +=
        "<table class=\"witness\"><caption>Witness: a state of the domain in which this "
        "finding is true</caption>\n<thead><tr><th>Variable</th><th>Value</th></tr></thead>"
        "<tbody>\n";
    for (const auto& [name, value] : finding.witness)
      out += "<tr><td>" + html_code(name) + "</td><td>" + html_code(value.to_string()) +
             "</td></tr>\n";
    out += "</tbody></table>\n";
  }
  std::string hint =
      "Why it matters and how to fix it: " + html_code("uabt explain " + finding.check);
  if (const CheckInfo* info = find_check(finding.check)) hint += " — " + html_escape(info->summary);
  out += "<p class=\"hint\">" + hint + "</p>\n</article>\n";
}

void findings_section(const ReportInput& input, const std::vector<std::string>& shown,
                      std::string& out) {
  const std::vector<const Finding*> conflicts = conflicts_of(input);
  const auto id_of = [&](const Finding* f) {
    const auto it = std::find(conflicts.begin(), conflicts.end(), f);
    return it == conflicts.end()
               ? std::string()
               : conflict_anchor(static_cast<std::size_t>(it - conflicts.begin()) + 1);
  };
  out += "<section id=\"findings\">\n<h2>Findings</h2>\n";
  if (input.findings.empty()) {
    out += "<p>No findings: every check that ran passed.</p>\n</section>\n";
    return;
  }
  for (const auto& adaptable : shown) {
    std::vector<const Finding*> group;
    for (const auto& f : input.findings)
      if (f.adaptable == adaptable) group.push_back(&f);
    if (group.empty()) continue;
    const bool in_tree = std::find(input.adaptables.begin(), input.adaptables.end(), adaptable) !=
                         input.adaptables.end();
    out += "<h3>Adaptable node " + html_code(adaptable) +
           (in_tree ? "" : " <span class=\"meta\">(not in the mission tree)</span>") + "</h3>\n";
    for (const Finding* f : group) finding_html(*f, timeline_link(input, *f), out, id_of(f));
  }
  std::vector<const Finding*> mission_wide;
  for (const auto& f : input.findings)
    if (f.adaptable.empty()) mission_wide.push_back(&f);
  if (!mission_wide.empty()) {
    out += "<h3>Mission-wide</h3>\n";
    for (const Finding* f : mission_wide) finding_html(*f, timeline_link(input, *f), out, id_of(f));
  }
  out += "</section>\n";
}

// The minimal conflicts as a matrix: a row per conflict (linked to its finding, which lists the
// inputs that defeat every tree), a column per requirement in any conflict, a mark where the
// requirement belongs to the conflict. A requirement in many rows is the one to look at first.
void conflicts_section(const ReportInput& input, std::string& out) {
  const std::vector<const Finding*> conflicts = conflicts_of(input);
  if (conflicts.empty()) return;
  std::vector<std::string> columns;
  for (const Finding* f : conflicts)
    for (const auto& id : f->requirements)
      if (std::find(columns.begin(), columns.end(), id) == columns.end()) columns.push_back(id);
  out += "<section id=\"realizability\">\n<h2>Realizability</h2>\n<p>" +
         std::to_string(conflicts.size()) + " minimal set" + (conflicts.size() == 1 ? "" : "s") +
         " of guarantees that no behavior tree meets together, whatever it does: change a "
         "requirement of each, or state what the environment never does.</p>\n"
         "<table class=\"conflicts\">\n<thead><tr><th>Conflict</th>";
  for (const auto& id : columns) out += "<th>" + html_code(id) + "</th>";
  out += "</tr></thead><tbody>\n";
  for (std::size_t k = 0; k < conflicts.size(); ++k) {
    out += "<tr><th><a href=\"#" + conflict_anchor(k + 1) + "\">" + std::to_string(k + 1) +
           "</a> <span class=\"meta\">" + severity_name(conflicts[k]->severity) + "</span></th>";
    for (const auto& id : columns) {
      const auto& members = conflicts[k]->requirements;
      const bool in = std::find(members.begin(), members.end(), id) != members.end();
      out += in ? "<td title=\"" + html_escape(id) + "\">&#9679;</td>" : "<td></td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody></table>\n</section>\n";
}

void requirements_html(const ReportInput& input, const std::string& adaptable, std::string& out) {
  out += "<h3>Selection requirements, in priority order</h3>\n";
  if (input.mission == nullptr) {
    out += "<p>The mission could not be loaded: its requirements are not shown.</p>\n";
    return;
  }
  const auto selections = input.mission->selections_for(adaptable);
  if (selections.empty()) {
    out +=
        "<p class=\"callout\">No selection requirement names this node: it cannot "
        "select any alternative.</p>\n";
    return;
  }
  out +=
      "<table>\n<thead><tr><th>#</th><th>Requirement</th><th>Guard</th><th>Alternative</th>"
      "<th>Where</th></tr></thead><tbody>\n";
  for (std::size_t i = 0; i < selections.size(); ++i) {
    const auto& selection = *selections[i];
    const fretish::Requirement* requirement =
        detail::find_requirement(*input.mission, selection.id);
    std::string text = html_code(selection.id);
    if (requirement != nullptr && !requirement->text.empty())
      text += ": " + html_escape(requirement->text);
    const std::string guard = selection.guard
                                  ? html_code(fretish::to_fretish(*selection.guard))
                                  : std::string("<em>default</em>: always enabled, tried last");
    out += "<tr><td class=\"num\">" + std::to_string(i + 1) + "</td><td>" + text + "</td><td>" +
           guard + "</td><td>" + html_code(selection.alternative) + "</td><td>" +
           html_code(detail::location_text(selection.location)) + "</td></tr>\n";
  }
  out += "</tbody></table>\n";
}

void witness_examples(const ReportInput& input, const std::string& adaptable, std::string& out) {
  for (const auto& f : input.findings) {
    if (f.adaptable != adaptable || f.witness.empty()) continue;
    if (f.check == "guard-gap") {
      out +=
          "<p>For example, no alternative is selected when " + state_words(f.witness) + ".</p>\n";
    } else if (f.check == "guard-overlap") {
      const std::string who =
          f.requirements.empty() ? std::string("two guards") : code_list(f.requirements);
      const char* verb = f.requirements.size() > 2 ? " all hold when " : " both hold when ";
      out += "<p>For example, " + who + verb + state_words(f.witness) + ".</p>\n";
    }
  }
}

void coverage_html(const ReportInput& input, const std::string& adaptable, std::string& out) {
  out += "<h3>Terrain coverage</h3>\n";
  const verify::Coverage* coverage = nullptr;
  for (const auto& c : input.coverage)
    if (c.adaptable == adaptable) coverage = &c;
  if (coverage == nullptr) {
    out +=
        "<p class=\"callout info\">Coverage was not computed: the verification stage did not "
        "run for this node.</p>\n";
    return;
  }
  if (!coverage->variables.empty()) {
    // Say which variables the guards read and which only enter through an assumption.
    std::set<std::string> read;
    if (input.mission != nullptr)
      for (const auto* r : input.mission->selections_for(adaptable))
        if (r->guard)
          for (const auto& name : fretish::identifiers_of(*r->guard)) read.insert(name);
    std::vector<std::string> guards, assumed;
    for (const auto& v : coverage->variables) (read.count(v) ? guards : assumed).push_back(v);
    out += "<p>" + (guards.empty() ? std::string("The guards read no variable")
                                   : "The guards read " + code_list(guards));
    if (!assumed.empty())
      out += "; the domain's assumptions tie them to " + code_list(assumed) +
             ", which the counts include";
    out += ".</p>\n";
  }
  out += detail::coverage_html(*coverage);
  witness_examples(input, adaptable, out);

  if (input.mission != nullptr) {
    const std::string map = coverage_map_svg(*input.mission, *coverage);
    if (!map.empty()) {
      out += "<h4>Where each alternative is selected</h4>\n" + inline_svg(map) + "\n";
    }
  }
}

}  // namespace

const char* detail::page_style() {
  return kStyle;
}

std::string detail::page_head(std::string_view command, const std::string& mission, bool passed,
                              const std::string& verdict, const std::string& style,
                              const std::vector<std::string>& lines) {
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>uabt " +
      std::string(command) + ": " + html_escape(mission) + " " + html_escape(verdict) +
      "</title>\n<style>" + style + "</style>\n</head>\n<body>\n<header class=\"" +
      (passed ? "pass" : "fail") + "\">\n<div class=\"badge\">" + html_escape(verdict) +
      "</div>\n<div>\n<h1>Mission " + html_escape(mission) + "</h1>\n";
  for (const auto& line : lines) out += "<p>" + line + "</p>\n";
  return out + "</div>\n</header>\n";
}

std::string detail::page_foot(const std::string& tool_version, const std::string& mission,
                              bool explains_checks) {
  return "</main>\n<footer>Generated by uabt " + html_escape(tool_version) + " from mission " +
         html_escape(mission) + "." +
         (explains_checks ? " Every check is documented: <code>uabt explain CHECK-ID</code>."
                          : "") +
         "</footer>\n</body>\n</html>\n";
}

std::string to_html(const ReportInput& input) {
  const bool passed = input.passed();
  const std::string verdict = input.banner();
  const auto shown = detail::adaptables_shown(input);
  const std::string mission = input.mission_name.empty() ? "mission" : input.mission_name;

  std::string stages;
  for (std::size_t i = 0; i < input.stages.size(); ++i)
    stages += (i == 0 ? " · stages run: " : ", ") + html_escape(input.stages[i]);
  std::string out = detail::page_head(
      "report", mission, passed, verdict,
      std::string(kStyle) + (input.proofs || input.uplink ? detail::proofs_style() : ""),
      {passed ? "No error-severity finding in the stages that ran."
              : "Error-severity findings: the mission must not be uplinked as it is.",
       html_escape(detail::counts_text(detail::count_severities(input.findings))) + " · uabt " +
           html_escape(input.tool_version) + stages});

  out += "<nav><a href=\"#findings\">Findings</a>";
  if (input.uplink) out += "<a href=\"#uplink\">Uplink</a>";
  if (input.proofs && !input.proofs->answers.empty()) out += "<a href=\"#proofs\">Proofs</a>";
  if (!conflicts_of(input).empty()) out += "<a href=\"#realizability\">Realizability</a>";
  if (input.campaign) out += "<a href=\"#tests\">Test campaign</a>";
  for (std::size_t i = 0; i < shown.size(); ++i)
    out += "<a href=\"#" + anchor(i, shown[i]) + "\">" + html_escape(shown[i]) + "</a>";
  out += "</nav>\n<main>\n";

  findings_section(input, shown, out);
  if (input.uplink) out += detail::uplink_html(*input.uplink);
  if (input.proofs) out += proofs_html(*input.proofs);
  conflicts_section(input, out);
  if (input.campaign) {
    out += "<section id=\"tests\">\n<h2>Test campaign</h2>\n<p>" +
           html_escape(input.campaign->headline()) + "</p>\n";
    const auto details = input.campaign->details();
    if (!details.empty()) out += "<ul>\n";
    for (const auto& line : details) out += "<li>" + html_escape(line) + "</li>\n";
    if (!details.empty()) out += "</ul>\n";
    out += "</section>\n";
  }
  for (std::size_t i = 0; i < shown.size(); ++i) {
    out += "<section id=\"" + anchor(i, shown[i]) + "\">\n<h2>Adaptable node " +
           html_code(shown[i]) + "</h2>\n";
    requirements_html(input, shown[i], out);
    coverage_html(input, shown[i], out);
    out += "</section>\n";
  }
  return out + detail::page_foot(input.tool_version, mission, true);
}

}  // namespace uabt::report
