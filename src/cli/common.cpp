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

std::string relative_to_mission(const std::filesystem::path& file,
                                const std::filesystem::path& mission_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path abs_file = fs::weakly_canonical(fs::absolute(file, ec), ec);
  const fs::path rel =
      abs_file.lexically_relative(fs::weakly_canonical(fs::absolute(mission_dir, ec), ec));
  return rel.empty() ? abs_file.generic_string() : rel.generic_string();
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

}  // namespace uabt::cli
