#include <iostream>

#include "base/diagnostics.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "monitor/trace_files.hpp"

namespace uabt::cli {

// Checks a recorded trace against FRET requirements (ARCHITECTURE §10). Exit 0 when every guarantee
// held and everything was monitored; 1 when one was violated or could not be monitored, or an
// input has errors; 2 for a bad command line or a requirements file with nothing to monitor.
void register_monitor(CLI::App& app, int& exit_code) {
  struct Args {
    std::string requirements, trace, domain, format = "text", output;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("monitor", "Check a recorded trace against FRET requirements");
  cmd->add_option("REQUIREMENTS", args->requirements,
                  "a .fret file, a FRET export (.json), or a mission folder (its "
                  "requirements.fret and domain.fret)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("TRACE", args->trace, "JSON lines: {\"tick\": t, \"state\": {...}}")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--domain", args->domain, "domain.fret: types, assumptions, tick period")
      ->check(CLI::ExistingFile);
  cmd->add_option("--format", args->format, "output format")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("-o,--output", args->output, "write to FILE instead of standard output");
  cmd->callback([args, &exit_code] {
    std::vector<Finding> findings;
    const monitor::TraceFilesCheck check =
        monitor::check_trace_files(args->requirements, args->domain, args->trace, findings);
    if (check.nothing_to_monitor) {
      std::cerr << check.requirements_file
                << ": error: nothing to monitor: the file states no requirement\n";
      exit_code = kExitUsage;
      return;
    }
    if (!check.report) {
      std::cerr << format_text(findings);
      exit_code = kExitFail;
      return;
    }
    const monitor::TraceReport& report = *check.report;
    if (!findings.empty()) std::cerr << format_text(findings);
    emit(args->output, args->format == "json" ? monitor::trace_report_json(report)
                                              : monitor::trace_report_text(report));
    exit_code = report.pass ? kExitPass : kExitFail;
  });
}

}  // namespace uabt::cli
