// The Proofs section of report.html and the page of `uabt prove --format html`: each
// guarantee's verdict, and a violated one's counterexample as a timeline (ticks as columns).
#include "report/common.hpp"
#include "report/proof_timeline.hpp"
#include "report/proofs.hpp"

namespace uabt::report {

namespace {

using detail::html_code;
using detail::html_escape;

// Cells of one timeline row. A boolean is a filled or an empty cell (its word stays in the
// cell, transparent, so that a copy of the table keeps it); an action's cell is shaded while
// it runs.
std::string cell_html(const detail::TimelineCell& cell, bool violating) {
  std::string cls;
  switch (cell.kind) {
    case detail::CellKind::text: break;
    case detail::CellKind::on: cls = "on"; break;
    case detail::CellKind::off: cls = "off"; break;
    case detail::CellKind::running: cls = "run"; break;
    case detail::CellKind::idle: cls = "idle"; break;
  }
  if (violating) cls += cls.empty() ? "viol" : " viol";
  return std::string("<td") + (cls.empty() ? "" : " class=\"" + cls + "\"") + ">" +
         html_escape(cell.text) + "</td>";
}

}  // namespace

namespace detail {

void counterexample_html(const std::string& id, const std::string& heading, const ProofAnswer& a,
                         const ProofCounterexample& cex, const Proofs* replay, std::string& out) {
  out += "<article class=\"cex\" id=\"" + html_escape(id) + "\">\n<h3>" + heading + "</h3>\n";
  out += "<p class=\"req\">" + html_code(detail::location_text(a.location)) + " " +
         html_escape(a.text) + "</p>\n";
  out += "<div class=\"scroll\"><table class=\"timeline\">\n<thead><tr><th>tick</th>";
  for (const ProofTick& tick : cex.ticks)
    out += std::string("<th") + (tick.tick == cex.tick ? " class=\"viol\"" : "") + ">" +
           std::to_string(tick.tick) + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (const detail::TimelineRow& row : detail::timeline_of(cex)) {
    out += "<tr class=\"" + std::string(detail::row_kind_name(row.kind)) + "\"><th>" +
           (row.kind == detail::RowKind::root ? html_escape(row.label) : html_code(row.label)) +
           "</th>";
    for (std::size_t i = 0; i < row.cells.size(); ++i)
      out += cell_html(row.cells[i], cex.ticks[i].tick == cex.tick);
    out += "</tr>\n";
  }
  out +=
      "</tbody></table></div>\n<p class=\"legend\"><span class=\"key on\"></span>true "
      "<span class=\"key off\"></span>false <span class=\"key run\"></span>action running "
      "<span class=\"key viol\"></span>the violating tick</p>\n";
  for (const std::string& note : cex.notes)
    out += "<p class=\"cex-note\">" + html_escape(note) + "</p>\n";
  if (replay != nullptr)
    out +=
        "<p>Replay: " + html_code(replay_command(*replay, cex.scenario_file)) +
        (cex.scenario_file.empty() ? " (save the scenario below as <code>cex.json</code>)" : "") +
        " runs the same violation at tick " + std::to_string(cex.tick) + ".</p>\n";
  out += "<details><summary>The scenario" +
         (cex.scenario_file.empty() ? std::string() : " " + html_code(cex.scenario_file)) +
         "</summary>\n<pre>" + html_escape(cex.scenario) + "</pre>\n</details>\n</article>\n";
}

const char* proofs_style() {
  return R"css(
table.proofs td.verdict { font-weight: 700; }
table.proofs tr.proved td.verdict { color: #1a7f37; }
table.proofs tr.violated td.verdict { color: #cf222e; }
table.proofs tr.bounded td.verdict, table.proofs tr.unsupported td.verdict { color: #9a6700; }
.cex { border: 1px solid #d0d7de; border-left: 6px solid #cf222e; border-radius: 6px;
       padding: 8px 14px; margin: 16px 0; }
.cex h3 { margin: 4px 0; }
.scroll { overflow-x: auto; }
table.timeline th, table.timeline td { text-align: center; min-width: 28px; white-space: nowrap;
                                        font-size: 13px; }
table.timeline tbody th { text-align: left; }
table.timeline td.on { background: #0969da; color: transparent; }
table.timeline td.off { background: #fff; color: transparent; }
table.timeline td.run { background: #ddf4ff; }
table.timeline td.idle { color: #8c959f; }
table.timeline tr.root td { font-size: 11px; }
table.timeline .viol { outline: 3px solid #cf222e; outline-offset: -3px; }
table.timeline th.viol { background: #ffebe9; color: #cf222e; }
.legend { font-size: 13px; color: #57606a; }
.key { display: inline-block; width: 14px; height: 12px; border: 1px solid #8c959f;
       vertical-align: -1px; margin: 0 4px 0 12px; }
.key.on { background: #0969da; }
.key.run { background: #ddf4ff; }
.key.viol { border: 3px solid #cf222e; height: 8px; width: 10px; }
pre { background: #f6f8fa; padding: 8px; overflow-x: auto; font-size: 12px; }
)css";
}

}  // namespace detail

std::string proofs_html(const Proofs& proofs) {
  if (proofs.answers.empty()) return "";
  std::string out = "<section id=\"proofs\">\n<h2>Proofs</h2>\n";
  out += "<p>" + html_escape(proofs_summary(proofs)) + "</p>\n";
  out +=
      "<table class=\"proofs\">\n<thead><tr><th>Guarantee</th><th>Verdict</th>"
      "<th>Requirement</th><th>Where</th></tr></thead><tbody>\n";
  for (std::size_t i = 0; i < proofs.answers.size(); ++i) {
    const ProofAnswer& a = proofs.answers[i];
    std::string verdict = html_escape(proof_verdict_text(a));
    if (a.counterexample)
      verdict = "<a href=\"#cex-" + std::to_string(i) + "\">" + verdict + "</a>";
    if (!a.reason.empty())
      verdict += "<br><span class=\"meta\">" + html_escape(a.reason) + "</span>";
    out += "<tr class=\"" + html_escape(a.verdict) + "\"><td>" + html_code(a.requirement) +
           "</td><td class=\"verdict\">" + verdict + "</td><td>" + html_escape(a.text) +
           "</td><td>" + html_code(detail::location_text(a.location)) + "</td></tr>\n";
  }
  out += "</tbody></table>\n";
  for (const std::string& note : proofs.notes)
    out += "<p class=\"meta\">Note: " + html_escape(note) + "</p>\n";
  for (std::size_t i = 0; i < proofs.answers.size(); ++i)
    if (const auto& cex = proofs.answers[i].counterexample)
      detail::counterexample_html("cex-" + std::to_string(i),
                                  html_code(proofs.answers[i].requirement) +
                                      " is violated at tick " + std::to_string(cex->tick),
                                  proofs.answers[i], *cex, &proofs, out);
  out += "</section>\n";
  return out;
}

std::string proofs_page_html(const Proofs& proofs, const std::string& mission,
                             const std::string& tool_version) {
  bool passed = !proofs.answers.empty();
  for (const ProofAnswer& a : proofs.answers) passed = passed && a.verdict == "proved";
  const char* verdict = passed ? "PASS" : "FAIL";
  std::string out = detail::page_head(
      "prove", mission, passed, verdict, std::string(detail::page_style()) + detail::proofs_style(),
      {passed                   ? "Every guarantee is proved on every run the world model allows."
       : proofs.answers.empty() ? "The mission states no guarantee."
                                : "Not every guarantee is proved.",
       "uabt prove " + html_escape(tool_version)});
  out += "<main>\n";
  out += proofs.answers.empty() ? "<p>Nothing to prove.</p>\n" : proofs_html(proofs);
  return out + detail::page_foot(tool_version, mission, true);
}

}  // namespace uabt::report
