#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "load/mission.hpp"
#include "report/model.hpp"

namespace uabt::cli {

// `--format text|json|sarif|junit` and `-o FILE`, shared by every command whose output is
// findings.
void add_findings_output_options(CLI::App& cmd, std::string& format, std::string& output);

// A report input holding the mission's own (load-stage) findings.
report::ReportInput report_input(const load::Mission& mission, std::vector<std::string> stages);

// The mission directory as SARIF should prefix its files ("missions/msl_curiosity/"), when it
// was given as a relative path inside the current directory; "" otherwise.
std::string uri_prefix_of(const std::string& mission_arg);

// Writes the findings in the chosen format; text goes to stderr unless -o is given, the
// machine formats to stdout. Returns the exit code (0 pass, 1 fail).
int write_findings(const report::ReportInput& input, const std::string& format,
                   const std::string& output);

}  // namespace uabt::cli
