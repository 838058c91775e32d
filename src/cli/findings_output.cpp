#include "cli/findings_output.hpp"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>

#include "base/diagnostics.hpp"
#include "cli/common.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::cli {

void add_findings_output_options(CLI::App& cmd, std::string& format, std::string& output) {
  cmd.add_option("--format", format, "findings format")
      ->check(CLI::IsMember({"text", "json", "sarif", "junit"}));
  cmd.add_option("-o,--output", output, "write the findings to FILE instead of standard output");
}

void add_source_root_option(CLI::App& cmd, std::string& source_root) {
  cmd.add_option("--source-root", source_root,
                 "directory SARIF locations are relative to (default: the top of the git work "
                 "tree that holds the mission, else the current directory)")
      ->check(CLI::ExistingDirectory);
}

namespace {

namespace fs = std::filesystem;

// The top of the git work tree that holds `dir` (a .git directory, or a worktree's .git
// file), if any.
std::optional<fs::path> git_top(const fs::path& dir) {
  std::error_code ec;
  for (fs::path p = fs::weakly_canonical(fs::absolute(dir, ec), ec); !p.empty();
       p = p.parent_path()) {
    if (fs::exists(p / ".git", ec)) return p;
    if (p == p.root_path()) break;
  }
  return std::nullopt;
}

}  // namespace

std::string sarif_uri_prefix(const std::string& mission_arg, const std::string& source_root) {
  std::error_code ec;
  const fs::path mission = fs::weakly_canonical(fs::absolute(mission_arg, ec), ec);
  fs::path root;
  if (!source_root.empty())
    root = fs::weakly_canonical(fs::absolute(source_root, ec), ec);
  else if (auto top = git_top(mission_arg))
    root = *top;
  else
    root = fs::weakly_canonical(fs::current_path(ec), ec);
  const fs::path rel = mission.lexically_relative(root);
  if (rel.empty() || *rel.begin() == "..") return mission.generic_string() + "/";  // outside
  std::string text = rel.generic_string();
  while (!text.empty() && text.back() == '/') text.pop_back();
  if (text.empty() || text == ".") return {};
  return text + "/";
}

int write_findings(const report::ReportInput& input, const std::string& format,
                   const std::string& output,
                   const std::pair<std::string, std::string>& verdict_words) {
  std::string text;
  if (format == "json") {
    text = report::to_json(input);
  } else if (format == "sarif") {
    text = report::to_sarif(input);
  } else if (format == "junit") {
    text = report::to_junit(input);
  } else if (format == "html") {
    text = report::to_html(input);
  } else {
    TextOptions options;
    if (input.mission != nullptr) {
      options.path_prefix = path_prefix_for(input.mission->dir);
      options.source_dir = input.mission->dir;
    }
    // A person at a terminal gets the source line and a caret; logs and files do not.
    options.show_source = output.empty() && ::isatty(STDERR_FILENO) != 0;
    text = format_text(input.findings, options);
    // "pass with 1 guarantee retired": what the reports' banners say (same words).
    const std::string verdict = input.verdict_text();
    text += input.mission_name + ": " +
            (input.passed() ? verdict_words.first + verdict.substr(std::string("pass").size())
                            : verdict_words.second) +
            "\n";
    if (output.empty()) {
      std::cerr << text;
      return input.passed() ? kExitPass : kExitFail;
    }
  }
  emit(output, text);
  return input.passed() ? kExitPass : kExitFail;
}

}  // namespace uabt::cli
