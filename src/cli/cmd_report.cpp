#include <iostream>

#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "cli/findings_output.hpp"
#include "report/reports.hpp"
#include "verify/verify.hpp"

namespace uabt::cli {

// The terrain coverage report alone: what share of the state space each alternative takes,
// where guards overlap and where none holds, as HTML with its SVG pictures and Markdown.
void register_report(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, source_root, out = "uabt-report";
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd =
      app.add_subcommand("report", "Write the terrain coverage report (HTML, SVG, Markdown)");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("--out", args->out, "report directory (default: uabt-report)");
  add_source_root_option(*cmd, args->source_root);
  cmd->callback([args, &exit_code] {
    check_output_directory(args->out, "--out");  // before the work, not after it
    auto mission = load_or_complain(args->mission, {}, exit_code);
    if (!mission) return;
    verify::Result result = verify::verify_mission(*mission, {});
    report::ReportInput input =
        report::ReportInput::of(*mission, tool_version(), {"load", "verify"});
    input.findings.insert(input.findings.end(), result.findings.begin(), result.findings.end());
    sort_findings(input.findings);
    input.coverage = std::move(result.coverage);
    input.uri_prefix = sarif_uri_prefix(args->mission, args->source_root);
    const std::filesystem::path out(args->out);
    write_file_atomically(out / "report.html", report::to_html(input));
    write_file_atomically(out / "summary.md", report::to_markdown(input));
    for (const auto& coverage : input.coverage)
      write_file_atomically(out / ("coverage-" + coverage.adaptable + ".svg"),
                            report::coverage_svg(coverage));
    std::cout << "wrote " << out.generic_string() << "/report.html\n";
    exit_code = input.passed() ? kExitPass : kExitFail;
  });
}

}  // namespace uabt::cli
