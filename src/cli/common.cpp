#include "cli/common.hpp"

#include <iostream>

#include "base/diagnostics.hpp"
#include "base/files.hpp"

namespace uabt::cli {

const char* tool_version() {
  return UABT_VERSION;
}

std::optional<load::Mission> load_or_complain(const std::filesystem::path& dir,
                                              const load::LoadOptions& options) {
  std::string error;
  auto mission = load::load_mission(dir, options, error);
  if (!mission) std::cerr << "uabt: " << dir.generic_string() << ": " << error << "\n";
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
  auto mission = load_or_complain(dir, options);
  if (!mission) {
    exit_code = kExitUsage;
    return std::nullopt;
  }
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
