#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "load/mission.hpp"
#include "report/model.hpp"

namespace uabt::cli {

// `--format text|json|sarif|junit` and `-o FILE`, shared by every command whose output is
// findings.
void add_findings_output_options(CLI::App& cmd, std::string& format, std::string& output);

// `--source-root DIR`, for every command whose output may be SARIF.
void add_source_root_option(CLI::App& cmd, std::string& source_root);

// The mission directory as SARIF prefixes its files: relative to the source root
// ("missions/msl_curiosity/"; `source_root` when given, else the top of the git work tree
// that holds the mission, else the current directory), or its absolute path when it lies
// outside the root.
std::string sarif_uri_prefix(const std::string& mission_arg, const std::string& source_root);

// Writes the findings in the chosen format; text goes to stderr unless -o is given, the
// machine formats to stdout. The text ends with the mission's verdict in `verdict_words`
// (passed, failed). Returns the exit code (0 pass, 1 fail).
int write_findings(const report::ReportInput& input, const std::string& format,
                   const std::string& output,
                   const std::pair<std::string, std::string>& verdict_words = {"pass", "fail"});

}  // namespace uabt::cli
