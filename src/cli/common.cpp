#include "cli/common.hpp"

#include <iostream>

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

}  // namespace uabt::cli
