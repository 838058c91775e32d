#include "cli/common.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <iostream>

#include "base/diagnostics.hpp"
#include "base/files.hpp"

namespace uabt::cli {

const char* tool_version() {
  return UABT_VERSION;
}

namespace {

std::string range_text(std::int64_t min, std::int64_t max) {
  if (max == min + 1) return std::to_string(min) + " or " + std::to_string(max);
  return "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
}

}  // namespace

std::int64_t whole_number(const std::string& option, const std::string& text, std::int64_t min,
                          std::int64_t max) {
  std::int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end || value < min || value > max) {
    // A number too long to read is not echoed whole.
    const std::string shown = text.size() > 24 ? text.substr(0, 20) + "…" : text;
    throw UsageError(option + " must be " + range_text(min, max) + ", not " +
                     (shown.empty() ? "nothing" : "'" + shown + "'"));
  }
  return value;
}

CLI::Option* add_number_option(CLI::App& cmd, const std::string& name, std::int64_t min,
                               std::int64_t max, const std::string& help,
                               std::function<void(std::int64_t)> set) {
  const std::string option = name.substr(name.rfind(',') + 1);  // "-o,--output": --output
  return cmd
      .add_option_function<std::string>(
          name,
          [option, min, max, set = std::move(set)](const std::string& text) {
            set(whole_number(option, text, min, max));
          },
          help + " (" + range_text(min, max) + ")")
      ->type_name("N");
}

void add_mission_argument(CLI::App& cmd, std::string& mission) {
  cmd.add_option("MISSION", mission, "mission directory")
      ->required()
      ->check(CLI::ExistingDirectory);
}

void add_nodes_option(CLI::App& cmd, std::string& nodes) {
  cmd.add_option("--nodes", nodes, "TreeNodesModel of the robot's nodes")->check(CLI::ExistingFile);
}

std::optional<load::Mission> load_or_complain(const std::filesystem::path& dir,
                                              const load::LoadOptions& options, int& exit_code) {
  std::string error;
  auto mission = load::load_mission(dir, options, error);
  if (!mission) {
    std::cerr << "uabt: " << dir.generic_string() << ": " << error << "\n";
    exit_code = kExitUsage;
  }
  return mission;
}

void relocate_findings(std::vector<Finding>& findings, const std::string& from,
                       const std::string& to) {
  for (auto& f : findings)
    if (f.location.file == from) f.location.file = to;
}

void emit(const std::string& path, const std::string& content) {
  if (path.empty() || path == "-") {
    std::cout << content;
    std::cout.flush();
    return;
  }
  write_file_atomically(path, content);
}

compile::SelectionStyle selection_style(const std::string& name) {
  if (name == "reactive") return compile::SelectionStyle::reactive;
  if (name == "optimized") return compile::SelectionStyle::optimized;
  return compile::SelectionStyle::sequence;
}

void apply_selection(const std::string& name, compile::Options& options) {
  if (name.empty()) return;
  options.selection = selection_style(name);
  options.selection_forced = true;
}

std::set<campaign::Criterion> campaign_criteria(const std::string& name) {
  using campaign::Criterion;
  if (name == "decision") return {Criterion::decision};
  if (name == "mcdc") return {Criterion::mcdc};
  if (name == "boundary") return {Criterion::boundary};
  if (name == "guarantee") return {Criterion::guarantee};
  return {Criterion::decision, Criterion::mcdc, Criterion::boundary, Criterion::guarantee};
}

std::optional<load::Mission> load_without_errors(const std::string& dir,
                                                 const std::vector<std::string>& uplinks,
                                                 int& exit_code) {
  load::LoadOptions options;
  for (const auto& u : uplinks) options.uplinks.push_back(u);
  auto mission = load_or_complain(dir, options, exit_code);
  if (!mission) return std::nullopt;
  std::vector<Finding> errors;
  for (const auto& f : mission->findings)
    if (f.severity == Severity::error) errors.push_back(f);
  if (!errors.empty()) {
    TextOptions text;
    text.path_prefix = path_prefix_for(mission->dir);
    std::cerr << format_text(errors, text) << "uabt: " << dir
              << ": the mission does not load; fix the errors above first\n";
    exit_code = kExitFail;
    return std::nullopt;
  }
  return mission;
}

}  // namespace uabt::cli
