// Every file and section the documentation and the command-line help refer to exists in the
// repository: README.md, every other Markdown file (reports/ aside: it is generated) and the
// `--help` of uabt and of every subcommand. A reference is a Markdown link, a path in backticks
// whose first directory is one of the repository's (or `docs/`), a path in the help text, or a
// section citation. Code, tests and documents cite the architecture page as "ARCHITECTURE §N":
// each must name a section ARCHITECTURE.md has, and "DESIGN §N" (a document the repository
// does not hold) is never cited.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = UABT_SOURCE_DIR;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// The repository's own Markdown files: not the build trees, not the generated reports.
std::vector<fs::path> markdown_files() {
  std::vector<fs::path> out;
  for (auto it = fs::recursive_directory_iterator(kRoot); it != fs::recursive_directory_iterator();
       ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() &&
        (name.starts_with(".") || name.starts_with("build") || name == "reports")) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && it->path().extension() == ".md") out.push_back(it->path());
  }
  return out;
}

// A token that names a file of the repository: no placeholder, a '/', and a first directory the
// repository has (or docs/, which it has not), or one beside the document; ":line:col" dropped.
std::string repository_path(std::string token, const fs::path& dir) {
  token = std::regex_replace(token, std::regex(R"((:\d+)+$)"), "");
  while (!token.empty() && std::string(".,;:").find(token.back()) != std::string::npos)
    token.pop_back();
  if (token.empty() || token.front() == '-' || token.find('/') == std::string::npos ||
      token.find_first_of(" \t<>*{}|$=(),;\"'") != std::string::npos ||
      token.find("\xE2\x80\xA6") != std::string::npos)  // …
    return "";
  const std::string first = token.substr(0, token.find('/'));
  if (first.empty() || first == "." || first == "..") return "";
  std::error_code ec;
  if (first == "docs" || fs::is_directory(kRoot / first, ec) || fs::exists(dir / first, ec))
    return token;
  return "";
}

bool resolves(const std::string& path, const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / path, ec) || fs::exists(kRoot / path, ec);
}

// The section numbers ARCHITECTURE.md has: "## 10. Time" gives "10", "### 10.1 How" "10.1".
const std::set<std::string>& architecture_sections() {
  static const std::set<std::string> sections = [] {
    std::set<std::string> out;
    const std::string text = read(kRoot / "ARCHITECTURE.md");
    static const std::regex heading(R"((^|\n)#{2,3} ([0-9]+(\.[0-9]+)*)\.? )");
    for (std::sregex_iterator it(text.begin(), text.end(), heading), end; it != end; ++it)
      out.insert((*it)[2].str());
    return out;
  }();
  return sections;
}

// "ARCHITECTURE §10" must name a section of ARCHITECTURE.md; "DESIGN §8", "DESIGN.md §3" and
// "DESIGN.md" name a document outside the repository.
void design_citations(const std::string& text, const std::string& where,
                      std::vector<std::string>& dangling) {
  static const std::regex design(R"(DESIGN(\.md)?\s*§\s*[0-9]+(\.[0-9]+)*|DESIGN\.md)");
  for (std::sregex_iterator it(text.begin(), text.end(), design), end; it != end; ++it)
    dangling.push_back(where + ": '" + it->str() +
                       "' (the repository has no DESIGN.md; cite ARCHITECTURE §N)");
  static const std::regex cited(R"(ARCHITECTURE(\.md)?\s*((§\s*[0-9]+(\.[0-9]+)*(,\s*)?)+))");
  static const std::regex number(R"([0-9]+(\.[0-9]+)*)");
  for (std::sregex_iterator it(text.begin(), text.end(), cited), end; it != end; ++it) {
    const std::string sections = (*it)[2].str();
    for (std::sregex_iterator n(sections.begin(), sections.end(), number); n != end; ++n)
      if (!architecture_sections().contains(n->str()))
        dangling.push_back(where + ": 'ARCHITECTURE §" + n->str() +
                           "' (ARCHITECTURE.md has no such section)");
  }
}

std::vector<std::string> dangling_in_markdown(const fs::path& file) {
  std::vector<std::string> dangling;
  const std::string text = read(file);
  const std::string where = fs::relative(file, kRoot).generic_string();
  const fs::path dir = file.parent_path();
  design_citations(text, where, dangling);
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
    std::string target = (*it)[1].str();
    if (std::regex_search(target, std::regex("^[a-z]+:")) || target.front() == '#') continue;
    target = target.substr(0, target.find('#'));
    if (!resolves(target, dir)) dangling.push_back(where + ": link to '" + target + "'");
  }
  static const std::regex code(R"(`([^`\n]+)`)");
  for (std::sregex_iterator it(text.begin(), text.end(), code), end; it != end; ++it) {
    const std::string path = repository_path((*it)[1].str(), dir);
    if (!path.empty() && !resolves(path, dir)) dangling.push_back(where + ": `" + path + "`");
  }
  return dangling;
}

std::vector<std::string> dangling_in_help(const std::string& help, const std::string& where) {
  std::vector<std::string> dangling;
  design_citations(help, where, dangling);
  static const std::regex token(R"([A-Za-z0-9_./-]+)");
  for (std::sregex_iterator it(help.begin(), help.end(), token), end; it != end; ++it) {
    const std::string path = repository_path(it->str(), kRoot);
    if (!path.empty() && !resolves(path, kRoot)) dangling.push_back(where + ": '" + path + "'");
  }
  return dangling;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += "  " + l + "\n";
  return out;
}

// The subcommands `uabt --help` lists.
std::vector<std::string> subcommands() {
  const std::string help = uabt::testing::run_uabt_in(kRoot.string(), "--help").out;
  std::vector<std::string> out;
  std::istringstream lines(help);
  std::string line;
  bool in_list = false;
  while (std::getline(lines, line)) {
    if (line.starts_with("SUBCOMMANDS") || line.starts_with("Subcommands")) {
      in_list = true;
      continue;
    }
    if (!in_list) continue;
    std::smatch m;
    if (std::regex_match(line, m, std::regex(R"(\s+([a-z]+)\s.*)"))) out.push_back(m[1]);
  }
  return out;
}

TEST(DocReferences, EveryMarkdownFileReferencesOnlyWhatExists) {
  std::vector<std::string> dangling;
  const std::vector<fs::path> files = markdown_files();
  ASSERT_GE(files.size(), 4u);  // README.md, missions/, checks/, grammar/ at least
  for (const fs::path& file : files) {
    const auto found = dangling_in_markdown(file);
    dangling.insert(dangling.end(), found.begin(), found.end());
  }
  EXPECT_TRUE(dangling.empty()) << "dangling references:\n" << joined(dangling);
}

TEST(DocReferences, EveryCommandHelpReferencesOnlyWhatExists) {
  const std::vector<std::string> commands = subcommands();
  for (const char* expected : {"gate", "verify", "compile", "run", "prove", "monitor", "explain"})
    ASSERT_NE(std::find(commands.begin(), commands.end(), expected), commands.end())
        << "uabt --help does not list '" << expected << "'";
  std::vector<std::string> dangling =
      dangling_in_help(uabt::testing::run_uabt_in(kRoot.string(), "--help").out, "uabt --help");
  for (const std::string& command : commands) {
    const auto run = uabt::testing::run_uabt_in(kRoot.string(), command + " --help");
    EXPECT_EQ(run.exit_code, 0) << command;
    const auto found = dangling_in_help(run.out, "uabt " + command + " --help");
    dangling.insert(dangling.end(), found.begin(), found.end());
  }
  EXPECT_TRUE(dangling.empty()) << "dangling references:\n" << joined(dangling);
}

// Every comment in the code and the tests cites only sections that exist.
TEST(DocReferences, EverySourceFileCitesOnlySectionsThatExist) {
  std::vector<std::string> dangling;
  int files = 0;
  for (const char* top : {"src", "tests", "grammar", "cmake"}) {
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / top)) {
      if (!entry.is_regular_file() || entry.path().filename() == "references_test.cpp") continue;
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp" && ext != ".cmake" && ext != ".txt") continue;
      ++files;
      design_citations(read(entry.path()), fs::relative(entry.path(), kRoot).generic_string(),
                       dangling);
    }
  }
  design_citations(read(kRoot / "CMakeLists.txt"), "CMakeLists.txt", dangling);
  ASSERT_GT(files, 100);
  EXPECT_TRUE(dangling.empty()) << "dangling references:\n" << joined(dangling);
}

// The checker itself: it names what does not exist and passes what does.
TEST(DocReferences, TheCheckerNamesEachDanglingReference) {
  const std::string help =
      "--scenario FILE  scenario JSON (DESIGN §8); see missions/README.md and docs/checks.md";
  const auto found = dangling_in_help(help, "help");
  ASSERT_EQ(found.size(), 2u) << joined(found);
  EXPECT_EQ(found[0], "help: 'DESIGN §8' (the repository has no DESIGN.md; cite ARCHITECTURE §N)");
  EXPECT_EQ(found[1], "help: 'docs/checks.md'");
}

TEST(DocReferences, TheCheckerKnowsTheArchitectureSections) {
  std::vector<std::string> dangling;
  design_citations("runs (ARCHITECTURE §8); cells (ARCHITECTURE §10.1); (ARCHITECTURE §10, §12)",
                   "a.cpp", dangling);
  EXPECT_TRUE(dangling.empty()) << joined(dangling);
  design_citations("see ARCHITECTURE §31 and ARCHITECTURE §10.9", "b.cpp", dangling);
  ASSERT_EQ(dangling.size(), 2u) << joined(dangling);
  EXPECT_EQ(dangling[0], "b.cpp: 'ARCHITECTURE §31' (ARCHITECTURE.md has no such section)");
  EXPECT_EQ(dangling[1], "b.cpp: 'ARCHITECTURE §10.9' (ARCHITECTURE.md has no such section)");
}

}  // namespace
