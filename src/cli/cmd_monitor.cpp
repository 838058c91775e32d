#include <filesystem>
#include <iostream>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "monitor/check_trace.hpp"

namespace uabt::cli {

namespace {

namespace fs = std::filesystem;

std::optional<std::string> read_or_finding(const fs::path& path, std::vector<Finding>& findings) {
  std::string error;
  auto text = read_text_file(path, error);
  if (!text)
    findings.push_back(make_finding("load-file", path.generic_string() + ": " + error,
                                    {path.generic_string(), 0, 0}));
  return text;
}

}  // namespace

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
    fretish::Domain domain;
    std::vector<fretish::Requirement> requirements;
    fs::path requirements_path(args->requirements);
    std::error_code ec;
    if (fs::is_directory(requirements_path, ec)) {
      // A mission folder: its requirements, and its domain unless --domain names one.
      if (args->domain.empty() && fs::is_regular_file(requirements_path / "domain.fret", ec))
        args->domain = (requirements_path / "domain.fret").generic_string();
      requirements_path /= "requirements.fret";
    }
    const std::string requirements_file = requirements_path.generic_string();
    if (auto text = read_or_finding(requirements_path, findings)) {
      fretish::ParseResult parsed =
          requirements_path.extension() == ".json"
              ? fretish::parse_fret_json(*text, requirements_file, domain)
              : fretish::parse_requirements_file(*text, requirements_file);
      findings.insert(findings.end(), parsed.findings.begin(), parsed.findings.end());
      requirements = std::move(parsed.requirements);
    }
    if (!args->domain.empty()) {
      if (auto text = read_or_finding(args->domain, findings)) {
        fretish::Domain declared = fretish::parse_domain_file(*text, args->domain, findings);
        for (auto& v : declared.variables)
          if (domain.find(v.name) == nullptr) domain.variables.push_back(std::move(v));
        for (auto& a : declared.assumptions) domain.assumptions.push_back(std::move(a));
        domain.tick_seconds = declared.tick_seconds;
      }
    }
    // Durations become ticks here, once, with the tick period of --domain.
    fretish::lower_durations(requirements, domain.tick_seconds, findings);
    std::optional<monitor::Trace> trace;
    const std::string trace_file = fs::path(args->trace).generic_string();
    if (auto text = read_or_finding(args->trace, findings))
      trace = monitor::read_trace(*text, trace_file, findings);
    if (has_errors(findings) || !trace) {
      std::cerr << format_text(findings);
      exit_code = kExitFail;
      return;
    }
    // The run names the requirements it states relative to its mission folder (an uplink's
    // too): the folder that holds the requirements file makes them open from here.
    const std::string prefix = path_prefix_for(requirements_path.parent_path());
    for (monitor::TraceTick& tick : trace->ticks)
      for (monitor::TraceAdaptable& a : tick.adaptables)
        for (fretish::SelectionRequirement& r : a.stated)
          r.location.file = user_path(r.location.file, prefix);
    // A verdict over no requirement would read as a pass that checked nothing.
    if (requirements.empty()) {
      std::cerr << requirements_file
                << ": error: nothing to monitor: the file states no requirement\n";
      exit_code = kExitUsage;
      return;
    }
    const monitor::TraceReport report =
        monitor::check_trace(requirements, domain, *trace, trace_file, findings);
    if (!findings.empty()) std::cerr << format_text(findings);
    emit(args->output, args->format == "json" ? monitor::trace_report_json(report)
                                              : monitor::trace_report_text(report));
    exit_code = report.pass ? kExitPass : kExitFail;
  });
}

}  // namespace uabt::cli
