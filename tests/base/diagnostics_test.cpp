#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/diagnostics.hpp"

namespace uabt {
namespace {

namespace fs = std::filesystem;

TEST(Diagnostics, UserPathJoinsThePrefix) {
  EXPECT_EQ(user_path("requirements.fret", "drone_bad/"), "drone_bad/requirements.fret");
  EXPECT_EQ(user_path("requirements.fret", ""), "requirements.fret");
  EXPECT_EQ(user_path("../out/c.xml", "missions/m/"), "missions/out/c.xml");
  EXPECT_EQ(user_path("/abs/c.xml", "missions/m/"), "/abs/c.xml");
  EXPECT_EQ(user_path("", "missions/m/"), "missions/m");
}

TEST(Diagnostics, PathPrefixIsTheMissionDirectoryAsTheUserOpensIt) {
  EXPECT_EQ(path_prefix_for("drone_bad"), "drone_bad/");
  EXPECT_EQ(path_prefix_for("./missions//m/"), "missions/m/");
  EXPECT_EQ(path_prefix_for("."), "");
  EXPECT_EQ(path_prefix_for("../m"), "../m/");
  EXPECT_EQ(path_prefix_for(fs::current_path() / "sub" / "m"), "sub/m/");
  EXPECT_EQ(path_prefix_for("/no/such/place/m"), "/no/such/place/m/");
}

Finding at(const std::string& file, int line, int column) {
  Finding f;
  f.check = "ref-undeclared";
  f.message = "'OnRokcs' in requirement Req2 is not declared in domain.fret";
  f.location = {file, line, column};
  f.notes = {"did you mean 'OnRocks'?"};
  return f;
}

TEST(Diagnostics, SourceLineAndCaretUnderTheColumn) {
  const fs::path dir = fs::temp_directory_path() / "uabt-diagnostics-test";
  fs::create_directories(dir);
  std::ofstream(dir / "requirements.fret")
      << "# comment\r\nReq2: In navigation if OnRokcs Mission shall satisfy selected_alt = x\r\n";
  TextOptions options;
  options.path_prefix = "m/";
  options.show_source = true;
  options.source_dir = dir;
  EXPECT_EQ(format_text({at("requirements.fret", 2, 24)}, options),
            "m/requirements.fret:2:24: error: 'OnRokcs' in requirement Req2 is not declared in "
            "domain.fret [ref-undeclared]\n"
            "   2 | Req2: In navigation if OnRokcs Mission shall satisfy selected_alt = x\n"
            "     |                        ^\n"
            "m/requirements.fret:2:24: note: did you mean 'OnRocks'?\n");
  // No line in the file, or no column: no excerpt.
  options.path_prefix.clear();
  EXPECT_EQ(format_text({at("requirements.fret", 9, 1)}, options).find(" | "), std::string::npos);
  EXPECT_EQ(format_text({at("missing.fret", 1, 1)}, options).find(" | "), std::string::npos);
  fs::remove_all(dir);
}

TEST(Diagnostics, RelatedLocationsAreNotes) {
  Finding f = at("requirements.fret", 2, 1);
  f.notes.clear();
  f.related.push_back({{"requirements.fret", 1, 1}, "the other requirement, Req1 (on_dust)"});
  TextOptions options;
  options.path_prefix = "m/";
  EXPECT_EQ(format_text({f}, options),
            "m/requirements.fret:2:1: error: 'OnRokcs' in requirement Req2 is not declared in "
            "domain.fret [ref-undeclared]\n"
            "m/requirements.fret:1:1: note: the other requirement, Req1 (on_dust)\n");
}

}  // namespace
}  // namespace uabt
