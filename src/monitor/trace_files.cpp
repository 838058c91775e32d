#include "monitor/trace_files.hpp"

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "fretish/durations.hpp"
#include "fretish/parse.hpp"

namespace uabt::monitor {

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

TraceFilesCheck check_trace_files(const fs::path& requirements, std::string domain_file,
                                  const fs::path& trace_path, std::vector<Finding>& findings) {
  TraceFilesCheck out;
  fretish::Domain domain;
  std::vector<fretish::Requirement> stated;
  fs::path requirements_path = requirements;
  std::error_code ec;
  if (fs::is_directory(requirements_path, ec)) {
    // A mission folder: its requirements, and its domain unless one is named.
    if (domain_file.empty() && fs::is_regular_file(requirements_path / "domain.fret", ec))
      domain_file = (requirements_path / "domain.fret").generic_string();
    requirements_path /= "requirements.fret";
  }
  out.requirements_file = requirements_path.generic_string();
  if (auto text = read_or_finding(requirements_path, findings)) {
    fretish::ParseResult parsed =
        requirements_path.extension() == ".json"
            ? fretish::parse_fret_json(*text, out.requirements_file, domain)
            : fretish::parse_requirements_file(*text, out.requirements_file);
    findings.insert(findings.end(), parsed.findings.begin(), parsed.findings.end());
    stated = std::move(parsed.requirements);
  }
  if (!domain_file.empty()) {
    if (auto text = read_or_finding(domain_file, findings)) {
      fretish::Domain declared = fretish::parse_domain_file(*text, domain_file, findings);
      for (auto& v : declared.variables)
        if (domain.find(v.name) == nullptr) domain.variables.push_back(std::move(v));
      for (auto& a : declared.assumptions) domain.assumptions.push_back(std::move(a));
      domain.tick_seconds = declared.tick_seconds;
    }
  }
  // Durations become ticks here, once, with the tick period of the domain.
  fretish::lower_durations(stated, domain.tick_seconds, findings);
  std::optional<Trace> trace;
  const std::string trace_file = trace_path.generic_string();
  if (auto text = read_or_finding(trace_path, findings))
    trace = read_trace(*text, trace_file, findings);
  if (has_errors(findings) || !trace) return out;
  // The run names the requirements it states relative to its mission folder (an uplink's
  // too): the folder that holds the requirements file makes them open from here.
  const std::string prefix = path_prefix_for(requirements_path.parent_path());
  for (TraceTick& tick : trace->ticks)
    for (TraceAdaptable& a : tick.adaptables)
      for (fretish::SelectionRequirement& r : a.stated)
        r.location.file = user_path(r.location.file, prefix);
  // A verdict over no requirement would read as a pass that checked nothing.
  if (stated.empty()) {
    out.nothing_to_monitor = true;
    return out;
  }
  out.report = check_trace(stated, domain, *trace, trace_file, findings);
  return out;
}

}  // namespace uabt::monitor
