#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "report/reports.hpp"
#include "report/text.hpp"
#include "report_fixtures.hpp"

namespace uabt::report {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("uabt-report-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir))
    out.insert(entry.path().filename().string());
  return out;
}

TEST(WriteReports, WritesEveryFileAndNoTemporaries) {
  TempDir dir;
  const ReportInput input = testing::failing_input();
  const fs::path out = dir.path() / "reports" / "msl";  // missing parents are created
  write_reports(input, out, "<root BTCPP_format=\"4\"/>\n");
  EXPECT_EQ(names_in(out),
            (std::set<std::string>{"findings.txt", "findings.json", "findings.sarif", "junit.xml",
                                   "summary.md", "report.html", "compiled.rejected.xml"}))
      << "a failing gate keeps its candidate tree as compiled.rejected.xml, never compiled.xml";
  EXPECT_EQ(slurp(out / "findings.txt"), format_text(input.findings));
  EXPECT_EQ(slurp(out / "findings.json"), to_json(input));
  EXPECT_EQ(slurp(out / "findings.sarif"), to_sarif(input));
  EXPECT_EQ(slurp(out / "junit.xml"), to_junit(input));
  EXPECT_EQ(slurp(out / "summary.md"), to_markdown(input));
  EXPECT_EQ(slurp(out / "report.html"), to_html(input));
  EXPECT_EQ(slurp(out / "compiled.rejected.xml"), "<root BTCPP_format=\"4\"/>\n");
  // Passing, the same directory gets the tree to uplink and loses the rejected one.
  write_reports(testing::passing_input(), out, "<root BTCPP_format=\"4\"/>\n");
  EXPECT_TRUE(fs::exists(out / "compiled.xml"));
  EXPECT_FALSE(fs::exists(out / "compiled.rejected.xml"));
}

TEST(WriteReports, RewritingGivesTheSameBytesAndDropsAStaleCompiledTree) {
  TempDir dir;
  const ReportInput input = testing::failing_input();
  write_reports(input, dir.path(), "<root/>\n");
  const std::string html = slurp(dir.path() / "report.html");
  write_reports(input, dir.path(), "");
  EXPECT_EQ(slurp(dir.path() / "report.html"), html);
  EXPECT_FALSE(fs::exists(dir.path() / "compiled.xml"));
  EXPECT_FALSE(fs::exists(dir.path() / "compiled.rejected.xml"));
  EXPECT_EQ(names_in(dir.path()).size(), 6u);
}

TEST(WriteReports, UnwritableDirectoryThrows) {
  TempDir dir;
  fs::create_directories(dir.path());
  std::ofstream(dir.path() / "file") << "x";
  // A path under a regular file cannot be a directory.
  EXPECT_THROW(write_reports(testing::passing_input(), dir.path() / "file" / "out", ""),
               std::runtime_error);
}

}  // namespace
}  // namespace uabt::report
