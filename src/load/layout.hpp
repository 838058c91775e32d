#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace uabt::load {

// Where a mission's files are. uabt's own layout (ARCHITECTURE §2) or the paper's replication
// package as it is (mission/, resource/<adaptable>/<alt>/<alt>.xml).
struct AlternativeFile {
  std::string adaptable;
  std::string name;  // the name requirements use: file stem, or the package's folder
  std::filesystem::path path;
};

struct MissionLayout {
  std::string kind;  // "uabt" | "replication"
  std::filesystem::path mission_xml;
  std::filesystem::path requirements;  // .fret or .json; empty when none was found
  std::optional<std::filesystem::path> domain;
  std::optional<std::filesystem::path> nodes;
  std::vector<AlternativeFile> alternatives;  // sorted by adaptable, then name
};

// alternatives/<adaptable>/<alt>.xml below `root`, sorted; empty when `root` is missing.
std::vector<AlternativeFile> discover_alternatives(const std::filesystem::path& root);

// Finds the files of the mission in `dir`. Sets `error` and returns nullopt when `dir`
// holds neither layout.
std::optional<MissionLayout> discover_layout(const std::filesystem::path& dir, std::string& error);

}  // namespace uabt::load
