#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "report/model.hpp"
#include "verify/verify.hpp"

namespace uabt::report {

// Every writer is deterministic: the same input gives the same bytes (no time, no absolute
// path, stable order, fixed number formatting).

// ARCHITECTURE §7's JSON: tool, version, mission, verdict, findings[], coverage[]; 2-space indent.
std::string to_json(const ReportInput& input);

// SARIF 2.1.0 for GitHub code scanning: one run, a rule per check of the catalogue (sorted by
// id), one result per finding with a line-independent fingerprint.
std::string to_sarif(const ReportInput& input);

// JUnit XML: a test suite per adaptable node and one for the mission, a test case per check
// that applies; error findings are failures, warnings go to system-out.
std::string to_junit(const ReportInput& input);

// One JUnit test case: failed when `failure` (its message) is set, else skipped when
// `skipped` (the reason) is.
struct JunitCase {
  std::string name;
  std::string failure, failure_type, failure_text;
  std::string skipped;
  std::string system_out;
};
struct JunitSuite {
  std::string name;
  std::vector<JunitCase> cases;
};
// The JUnit XML of these suites (the writer behind to_junit): escaped, deterministic.
std::string junit_xml(const std::vector<JunitSuite>& suites);

// GitHub-flavoured Markdown for a PR comment or a CI step summary.
std::string to_markdown(const ReportInput& input);

// One self-contained HTML page (inline CSS and SVG, no script, no external resource).
std::string to_html(const ReportInput& input);

// The terrain coverage picture of one adaptable node: a partition bar of the state space by
// selected alternative, the gap hatched in red, the overlap marked, and a legend.
std::string coverage_svg(const verify::Coverage& coverage);

// The selected alternative of one adaptable node over the first two drawable variables its
// guards read (booleans, enums, bounded numbers; numbers in at most 32 cells evaluated at their
// centre), computed with smt::evaluate; other variables are tried at a few values and a cell
// whose outcome depends on them is striped. Two or more guards holding are dotted. "" when the
// guards read fewer than two drawable variables. `visited`: cells runs visited, outlined over
// the map with the runs in their tooltip (none: the map alone, byte for byte).
std::string coverage_map_svg(const load::Mission& mission, const verify::Coverage& coverage,
                             const std::vector<verify::MapMark>& visited = {});

// The compiled tree's file in a report directory: the tree to uplink (a passing gate), or the
// candidate a failing gate rejected.
inline constexpr const char* kCompiledTree = "compiled.xml";
inline constexpr const char* kRejectedTree = "compiled.rejected.xml";

// Writes findings.txt, findings.json, findings.sarif, junit.xml, summary.md, report.html and,
// when `compiled_xml` is not empty, compiled.xml (verdict pass) or compiled.rejected.xml
// (fail) into `out_dir` (created if missing), each atomically. The other compiled file, left
// by an earlier run, is removed, so that the directory always describes one run. Throws
// std::runtime_error when a file cannot be written.
void write_reports(const ReportInput& input, const std::filesystem::path& out_dir,
                   const std::string& compiled_xml);

}  // namespace uabt::report
