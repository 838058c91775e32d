#pragma once
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace uabt::testing {

// A mission directory written to a fresh temporary folder, removed again at the end of the
// test. Files are given as path (relative to the mission) → content.
class TempMission {
 public:
  explicit TempMission(const std::map<std::string, std::string>& files, std::string name = "m") {
    static std::atomic<int> counter{0};
    root_ = std::filesystem::temp_directory_path() /
            ("uabt-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    dir_ = root_ / name;
    std::filesystem::create_directories(dir_);
    for (const auto& [path, content] : files) write(path, content);
  }
  ~TempMission() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TempMission(const TempMission&) = delete;
  TempMission& operator=(const TempMission&) = delete;

  void write(const std::string& path, const std::string& content) const {
    const auto full = dir_ / path;
    std::filesystem::create_directories(full.parent_path());
    std::ofstream(full, std::ios::binary) << content;
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path root_;
  std::filesystem::path dir_;
};

// The smallest well-formed pieces, for tests that vary one thing.
inline std::string mission_with(const std::string& body) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
         "  <BehaviorTree ID=\"MainTree\">\n" +
         body + "\n  </BehaviorTree>\n</root>\n";
}

inline std::string alternative_tree(const std::string& id, const std::string& body = "<Stop/>") {
  return "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"" + id + "\">\n    " + body +
         "\n  </BehaviorTree>\n</root>\n";
}

// A mission of one adaptable node `node` whose alternatives only stop, with its domain and
// requirements.
inline std::map<std::string, std::string> one_node_mission(
    const std::string& node, const std::string& domain, const std::string& requirements,
    const std::vector<std::string>& alternatives) {
  std::map<std::string, std::string> files{
      {"mission.xml", mission_with("<Adaptable ID=\"" + node + "\"/>")},
      {"domain.fret", domain},
      {"requirements.fret", requirements}};
  for (const auto& a : alternatives)
    files["alternatives/" + node + "/" + a + ".xml"] = alternative_tree(a);
  return files;
}

// Two versions of such a mission, "old" and "new", that differ in their requirements.
struct TwoVersions {
  TwoVersions(const std::string& node, const std::string& domain,
              const std::string& old_requirements, const std::string& new_requirements,
              const std::vector<std::string>& alternatives)
      : old_version(one_node_mission(node, domain, old_requirements, alternatives), "old"),
        new_version(one_node_mission(node, domain, new_requirements, alternatives), "new") {}
  TempMission old_version, new_version;
};

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The files of a shipped mission, to vary one of them in a temporary copy.
inline std::map<std::string, std::string> mission_files(const std::string& name) {
  std::map<std::string, std::string> files;
  const auto root = mission_dir(name);
  for (const auto& e : std::filesystem::recursive_directory_iterator(root))
    if (e.is_regular_file())
      files[std::filesystem::relative(e.path(), root).generic_string()] = read_all(e.path());
  return files;
}

}  // namespace uabt::testing
