#pragma once
// Helpers shared by the tests of src/bt.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "base/finding.hpp"
#include "bt/xml_io.hpp"

namespace uabt::bt::testing {

// A fresh directory under the system's temporary directory, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("uabt-bt-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::string& relative, const std::string& content) const {
    const std::filesystem::path file = path_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << content;
    return file;
  }

 private:
  std::filesystem::path path_;
};

inline std::vector<const Finding*> with_check(const std::vector<Finding>& findings,
                                              const std::string& check) {
  std::vector<const Finding*> out;
  for (const Finding& f : findings) {
    if (f.check == check) out.push_back(&f);
  }
  return out;
}

inline std::string describe(const std::vector<Finding>& findings) {
  std::string out;
  for (const Finding& f : findings) {
    out += f.location.file + ":" + std::to_string(f.location.line) + ":" +
           std::to_string(f.location.column) + ": " + f.message + " [" + f.check + "]\n";
  }
  return out;
}

// Parses text that must be read without any finding.
inline Document parse_clean(const std::string& text, const std::string& file = "test.xml") {
  std::vector<Finding> findings;
  std::optional<Document> doc = parse_document(text, file, findings);
  EXPECT_TRUE(findings.empty()) << describe(findings);
  EXPECT_TRUE(doc.has_value());
  return doc ? *doc : Document{};
}

}  // namespace uabt::bt::testing
