#include "report/common.hpp"
#include "report/coverage_view.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"
#include "report/uplink_sections.hpp"

namespace uabt::report {

namespace {

void coverage_section(const verify::Coverage& coverage, std::string& out) {
  out += "\n### Coverage of " + detail::markdown_code(coverage.adaptable) + "\n\n";
  if (!coverage.counted && (coverage.measured || coverage.bounded)) {
    out += coverage.measured
               ? "Measured exactly: the domain measures " +
                     detail::markdown_code(coverage.measure.text) +
                     " (the real variables' length, area or volume, summed over the discrete "
                     "values).\n\n"
               : "Shares " + detail::markdown_text(detail::not_measured_text(coverage)) +
                     "; certified bounds instead.\n\n";
    out += "| Alternative | Requirement | Share |\n|---|---|---:|\n";
    auto row = [&](const std::string& name, const std::string& requirement,
                   const std::optional<detail::ShownShare>& share, const verify::Exact& lo,
                   const verify::Exact& hi) {
      out +=
          "| " + name + " | " + requirement + " | " +
          detail::markdown_text(share ? detail::share_text(*share) : detail::bounds_text(lo, hi)) +
          " |\n";
    };
    for (std::size_t i = 0; i < coverage.alternatives.size(); ++i) {
      const auto& a = coverage.alternatives[i];
      row(detail::markdown_text(a.name) + (a.reachable ? "" : " (never selected)"),
          detail::markdown_text(a.requirement), detail::alternative_share(coverage, i),
          a.share_lower, a.share_upper);
    }
    row("*gap: none selected*", "", detail::gap_share(coverage), coverage.gap_share_lower,
        coverage.gap_share_upper);
    row("*overlap: two or more guards hold*", "", detail::overlap_share(coverage),
        coverage.overlap_share_lower, coverage.overlap_share_upper);
  } else if (!coverage.counted) {
    out +=
        "Not counted: " +
        detail::markdown_text(coverage.not_counted_reason.empty() ? "no reason given"
                                                                  : coverage.not_counted_reason) +
        ".\n\n";
    out += "| Alternative | Requirement | Selected in some state |\n|---|---|---|\n";
    for (const auto& alternative : coverage.alternatives)
      out += "| " + detail::markdown_text(alternative.name) + " | " +
             detail::markdown_text(alternative.requirement) + " | " +
             (alternative.reachable ? "yes" : "**no**") + " |\n";
  } else {
    out += "| Alternative | Requirement | States | Share |\n|---|---|---:|---:|\n";
    for (const auto& alternative : coverage.alternatives) {
      out += "| " + detail::markdown_text(alternative.name) +
             (alternative.reachable ? "" : " (never selected)") + " | " +
             detail::markdown_text(alternative.requirement) + " | " +
             std::to_string(alternative.states) + " | " +
             detail::percent(alternative.states, coverage.states) + " |\n";
    }
    out += "| *gap: none selected* | | " + std::to_string(coverage.gap_states) + " | " +
           detail::percent(coverage.gap_states, coverage.states) + " |\n";
    out += "| **total** | | " + std::to_string(coverage.states) + " | 100.0% |\n\n";
    out +=
        "Gap: " + std::to_string(coverage.gap_states) + " of " + std::to_string(coverage.states) +
        " states (" + detail::percent(coverage.gap_states, coverage.states) + ")" +
        (coverage.gap_states > 0 ? " select no alternative: the node fails there." : ".") + "  \n";
    out += "Overlap: " + std::to_string(coverage.overlap_states) + " of " +
           std::to_string(coverage.states) + " states (" +
           detail::percent(coverage.overlap_states, coverage.states) + ")" +
           (coverage.overlap_states > 0 ? " are claimed by two or more guards." : ".") + "\n";
  }
  if (!coverage.gap_region.empty() && coverage.gap_regions.empty()) {
    out += "\nUncovered region:\n\n";
    for (const auto& cube : coverage.gap_region) out += "- " + detail::markdown_code(cube) + "\n";
  }
  if (!coverage.alternatives.empty())
    out += "\nDecision table (priority order, then the gap and overlap regions):\n\n" +
           detail::decision_table_markdown(coverage);
}

}  // namespace

std::string to_markdown(const ReportInput& input) {
  const auto counts = detail::count_severities(input.findings);
  std::string out;
  out += "## uabt: " + detail::markdown_text(input.mission_name) + "\n\n";
  out += "**Verdict: " + input.banner() + "** | " + detail::counts_text(counts) + " | uabt " +
         detail::markdown_text(input.tool_version);
  if (!input.stages.empty()) {
    out += " | stages:";
    for (std::size_t i = 0; i < input.stages.size(); ++i)
      out += (i == 0 ? " " : ", ") + detail::markdown_text(input.stages[i]);
  }
  out += "\n\n### Findings\n\n";
  if (input.findings.empty()) {
    out += "No findings.\n";
  } else {
    out += "| Severity | Check | Location | Message |\n|---|---|---|---|\n";
    for (const auto& finding : input.findings) {
      std::string message = detail::markdown_text(finding.message);
      if (!finding.adaptable.empty())
        message += " (node " + detail::markdown_code(finding.adaptable) + ")";
      if (finding.more_like_it > 0) message += "; " + detail::markdown_text(finding.notes.back());
      out += std::string("| ") + severity_name(finding.severity) + " | " +
             detail::markdown_code(finding.check) + " | " +
             detail::markdown_code(detail::location_text(finding.location)) + " | " + message +
             " |\n";
    }
    bool any_witness = false;
    for (const auto& finding : input.findings) {
      if (finding.witness.empty()) continue;
      if (!any_witness) out += "\nWitnesses (states in which the finding is true):\n\n";
      any_witness = true;
      out += "- " + detail::markdown_code(finding.check) + " at " +
             detail::markdown_code(detail::location_text(finding.location)) + ": " +
             detail::markdown_text(format_state(finding.witness, " = ")) + "\n";
    }
    out += "\n`uabt explain CHECK-ID` says why a check matters and how to fix it.\n";
  }
  if (input.uplink) out += detail::uplink_markdown(*input.uplink);
  if (input.proofs) out += proofs_markdown(*input.proofs);
  if (input.campaign) {
    out += "\n### Test campaign\n\n" + detail::markdown_text(input.campaign->headline()) + "\n";
    const auto details = input.campaign->details();
    if (!details.empty()) out += "\n";
    for (const auto& line : details) out += "- " + detail::markdown_text(line) + "\n";
  }
  for (const auto& coverage : input.coverage) coverage_section(coverage, out);
  return out;
}

}  // namespace uabt::report
