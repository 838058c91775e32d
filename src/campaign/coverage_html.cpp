// `uabt coverage --format html`: the cells a set of runs visited, drawn over each node's
// coverage map, and the campaign's targets they covered and missed.
#include <map>
#include <set>

#include "campaign/campaign.hpp"
#include "report/common.hpp"
#include "report/coverage_view.hpp"
#include "report/proof_timeline.hpp"
#include "report/reports.hpp"

namespace uabt::campaign {

namespace {

using report::detail::anchor;
using report::detail::html_code;
using report::detail::html_escape;
using report::detail::inline_svg;

constexpr const char* kCoverageStyle = R"css(
tr.missed td { background: #ffebe9; }
tr.missed td:first-child { border-left: 4px solid #cf222e; }
tr.covered td:first-child { border-left: 4px solid #1a7f37; }
tr.unreachable td, tr.judged td { color: #57606a; }
td.cover code { word-break: break-all; }
)css";

std::string criterion_words(Criterion c) {
  return c == Criterion::mcdc ? "MC/DC" : criterion_name(c);
}

// One table of targets: what each is, whether the runs covered it, and what covers a miss.
std::string targets_table(const CoverageReport& report, const std::vector<std::size_t>& targets,
                          const std::map<std::size_t, const NodeVisit::TargetShare*>& shares) {
  if (targets.empty()) return "<p>No targets.</p>\n";
  const bool with_shares = !shares.empty();
  std::string out =
      "<table class=\"targets\">\n<thead><tr><th>Target</th><th>Criterion</th><th>Runs</th>";
  if (with_shares) out += "<th>Share of the space</th><th>Visited</th>";
  out += "<th>What covers a miss, or why it is not judged or reachable</th></tr></thead><tbody>\n";
  for (std::size_t k : targets) {
    const Target& t = report.targets[k];
    const auto judged = report.not_judged.find(k);
    std::string kind, verdict, why;
    if (!t.reachable) {
      kind = "unreachable";
      verdict = t.undecided ? "not decided" : "unreachable";
      why = html_escape(t.reason);
    } else if (report.covered[k]) {
      kind = "covered";
      verdict = "covered";
    } else if (judged != report.not_judged.end()) {
      kind = "judged";
      verdict = "not judged";
      why = html_escape(judged->second);
    } else {
      kind = "missed";
      verdict = "<strong>missed</strong>";
      why = html_code(covering_text(t));
    }
    out += "<tr class=\"" + kind + "\"><td>" + html_escape(t.text) + "</td><td>" +
           criterion_words(t.criterion) + "</td><td>" + verdict + "</td>";
    if (with_shares) {
      const auto s = shares.find(k);
      if (s == shares.end()) {
        out += "<td></td><td></td>";
      } else {
        out += "<td class=\"num\">" +
               html_escape(
                   report::detail::share_text({s->second->share.value, s->second->share.exact})) +
               "</td><td class=\"num\">" + html_escape(visited_text(s->second->visited)) + "</td>";
      }
    }
    out += "<td class=\"cover\">" + why + "</td></tr>\n";
  }
  out += "</tbody></table>\n";
  return out;
}

void node_section(const CoverageReport& report, const load::Mission& mission,
                  const std::vector<verify::Coverage>& maps, const std::string& node,
                  std::size_t index, std::string& out) {
  out += "<section id=\"" + anchor(index, node) + "\">\n<h2>Adaptable node " + html_code(node) +
         "</h2>\n";
  const NodeVisit* visit = nullptr;
  for (const auto& v : report.visits)
    if (v.adaptable == node) visit = &v;
  for (const auto& [skipped, reason] : report.skipped)
    if (skipped == node)
      out += "<p class=\"callout info\">No targets and no map for " + html_code(node) + ": " +
             html_escape(reason) + ".</p>\n";
  if (visit == nullptr) {
    out += "</section>\n";
    return;
  }
  if (!visit->share_not_computed.empty())  // a solved node: its states counted, not measured
    out += "<p>" + std::to_string(visit->visited.cells) +
           " states visited, share not computed: " + html_escape(visit->share_not_computed) +
           ".</p>\n";
  else
    out += "<p>" + std::to_string(visit->visited.cells) + " of " + std::to_string(visit->cells) +
           (visit->counted ? " states" : " cells") + " visited, " +
           html_escape(visited_text(visit->visited)) + ".</p>\n";
  const verify::Coverage* coverage = nullptr;
  for (const auto& c : maps)
    if (c.adaptable == node) coverage = &c;
  const std::string map = visit->no_map.empty() && coverage != nullptr
                              ? report::coverage_map_svg(mission, *coverage, visit->marks)
                              : std::string();
  if (!map.empty()) {
    out += "<h3>The cells the runs visited, over the coverage map</h3>\n" + inline_svg(map) + "\n";
  } else {
    std::string why = visit->no_map;
    if (why.empty() && coverage != nullptr)
      why = coverage->not_counted_reason.empty() ? coverage->not_measured_reason
                                                 : coverage->not_counted_reason;
    out += "<p class=\"callout info\">No coverage map of " + html_code(node) +
           (why.empty() ? std::string(".") : ": " + html_escape(why) + ".") + "</p>\n";
  }
  std::vector<std::size_t> targets;
  for (std::size_t k = 0; k < report.targets.size(); ++k)
    if (report.targets[k].adaptable == node && report.targets[k].criterion != Criterion::guarantee)
      targets.push_back(k);
  std::map<std::size_t, const NodeVisit::TargetShare*> shares;
  for (const auto& t : visit->targets) shares.emplace(t.target, &t);
  out += "<h3>Targets</h3>\n" + targets_table(report, targets, shares) + "</section>\n";
}

}  // namespace

std::string coverage_html(const CoverageReport& report, const load::Mission& mission,
                          const std::vector<verify::Coverage>& maps,
                          const std::string& tool_version) {
  bool passed = true;
  for (std::size_t k = 0; k < report.targets.size(); ++k)
    passed =
        passed && (!report.targets[k].reachable || report.covered[k] || report.not_judged.count(k));
  const char* verdict = passed ? "PASS" : "FAIL";
  // The nodes in mission order, each once; then those only the report names.
  std::vector<std::string> nodes;
  std::set<std::string> seen;
  for (const auto& site : mission.adaptables)
    if (!site.id.empty() && seen.insert(site.id).second) nodes.push_back(site.id);
  for (const auto& v : report.visits)
    if (seen.insert(v.adaptable).second) nodes.push_back(v.adaptable);
  for (const auto& [node, reason] : report.skipped)
    if (seen.insert(node).second) nodes.push_back(node);
  std::vector<std::size_t> guarantees;
  for (std::size_t k = 0; k < report.targets.size(); ++k)
    if (report.targets[k].criterion == Criterion::guarantee) guarantees.push_back(k);

  std::string out = report::detail::page_head(
      "coverage", report.mission, passed, verdict,
      std::string(report::detail::page_style()) + kCoverageStyle,
      {html_escape(coverage_headline(report)),
       std::string(passed
                       ? "The runs cover every reachable target."
                       : "The runs miss reachable targets: each is listed with what covers it.") +
           " · uabt coverage " + html_escape(tool_version)});
  out += "<nav><a href=\"#runs\">Runs</a>";
  for (std::size_t i = 0; i < nodes.size(); ++i)
    out += "<a href=\"#" + anchor(i, nodes[i]) + "\">" + html_escape(nodes[i]) + "</a>";
  if (!guarantees.empty()) out += "<a href=\"#guarantees\">Guarantee targets</a>";
  out += "</nav>\n<main>\n";

  out += "<section id=\"runs\">\n<h2>Runs</h2>\n";
  if (report.runs.empty()) {
    out += "<p>No run.</p>\n";
  } else {
    out +=
        "<table>\n<thead><tr><th>Run</th><th>Observations</th><th>Ticks</th><th>Stopped "
        "by</th></tr></thead><tbody>\n";
    for (const auto& r : report.runs)
      out += "<tr><td>" + html_code(r.source) + "</td><td class=\"num\">" +
             std::to_string(r.observations.size()) + "</td><td class=\"num\">" +
             std::to_string(r.ticks) + "</td><td>" + html_escape(r.error) + "</td></tr>\n";
    out += "</tbody></table>\n";
  }
  out += "</section>\n";
  for (std::size_t i = 0; i < nodes.size(); ++i)
    node_section(report, mission, maps, nodes[i], i, out);
  if (!guarantees.empty())
    out += "<section id=\"guarantees\">\n<h2>Guarantee targets</h2>\n" +
           targets_table(report, guarantees, {}) + "</section>\n";
  if (!report.notes.empty()) {
    out += "<section id=\"notes\">\n<h2>Notes</h2>\n<ul>\n";
    for (const auto& note : report.notes) out += "<li>" + html_escape(note) + "</li>\n";
    out += "</ul>\n</section>\n";
  }
  return out + report::detail::page_foot(tool_version, report.mission, false);
}

}  // namespace uabt::campaign
