#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "monitor/check_trace.hpp"

namespace uabt::monitor {

// What `uabt monitor REQUIREMENTS TRACE [--domain FILE]` decides, from its files.
struct TraceFilesCheck {
  std::string requirements_file;      // the file the requirements were read from
  bool nothing_to_monitor = false;    // the file states no requirement (report unset)
  std::optional<TraceReport> report;  // unset when an input has errors (in the findings)
};

// Reads REQUIREMENTS (a .fret file, a FRET export (.json), or a mission folder: its
// requirements.fret, and its domain.fret unless `domain` names one), the domain (`domain`, ""
// for none) and the trace, and checks the trace (check_trace). Problems with the inputs are
// findings; the requirements the trace states for its adaptable nodes are named as a user
// opens them from the folder that holds the requirements file.
TraceFilesCheck check_trace_files(const std::filesystem::path& requirements, std::string domain,
                                  const std::filesystem::path& trace,
                                  std::vector<Finding>& findings);

}  // namespace uabt::monitor
