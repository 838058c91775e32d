#pragma once
// Writing a generated mission's files, for every family generator.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace uabt::bench {

// Writes `content` to `path`, making its folders; throws when it cannot.
inline void write_file(const std::filesystem::path& path, const std::string& content) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << content;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace uabt::bench
