#pragma once
#include <filesystem>
#include <string>

namespace uabt::testing {

inline std::filesystem::path source_dir() {
  return UABT_SOURCE_DIR;
}
inline std::filesystem::path shared_dir() {
  return UABT_SHARED_DIR;
}
inline std::filesystem::path mission_dir(const std::string& name) {
  return source_dir() / "missions" / name;
}
inline std::filesystem::path replication_dir() {
  return shared_dir() / "reference" / "seed-replication" / "bt-generator";
}

}  // namespace uabt::testing
