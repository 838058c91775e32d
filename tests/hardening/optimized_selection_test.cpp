// `--selection optimized` on an adaptable node where one requirement holds in every state: next
// to one whose guard no state satisfies, or alone with a guard that is always true. The
// decision structure then tests nothing; compile, conform and the gate handle it like any other.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

std::map<std::string, std::string> files_with(const std::string& domain,
                                              const std::string& requirements) {
  return {{"mission.xml", mission_with("    <Adaptable ID=\"navigation\"/>")},
          {"domain.fret", domain},
          {"requirements.fret", requirements},
          {"alternatives/navigation/a.xml", alternative_tree("a")},
          {"alternatives/navigation/b.xml", alternative_tree("b")}};
}

TEST(OptimizedSelection, ARequirementThatHoldsEverywhereCompilesConformsAndGates) {
  const std::map<std::string, std::map<std::string, std::string>> missions = {
      {"beside an unsatisfiable guard",
       files_with("integer battery in [0, 100]\n",
                  "R1: In navigation if battery > 80 & battery < 20 Mission shall satisfy "
                  "selected_alt = a\n"
                  "R2: In navigation Mission shall satisfy selected_alt = b\n")},
      {"alone, always true",
       files_with("integer x in [-3, 0]\n",
                  "R2: In navigation if !(x = 1) Mission shall satisfy selected_alt = b\n")}};
  for (const auto& [name, files] : missions) {
    SCOPED_TRACE(name);
    const TempMission m(files);
    const std::string dir = m.dir().string();
    const std::string compiled = (m.dir().parent_path() / "compiled.xml").string();
    const CliRun compile = run_cli({"compile", dir, "--selection", "optimized", "-o", compiled});
    ASSERT_EQ(compile.exit_code, 0) << compile.output;
    const std::string xml = read_all(compiled);
    EXPECT_NE(xml.find("<Sequence name=\"navigation\">"), std::string::npos) << xml;
    EXPECT_NE(xml.find("<Sequence name=\"R2\">"), std::string::npos) << xml;
    const CliRun conform = run_cli({"conform", dir, compiled});
    EXPECT_EQ(conform.exit_code, 0) << conform.output;
    // The gate decides (R1's guard is an error of its own), it does not crash.
    const std::string out = (m.dir().parent_path() / "out").string();
    const CliRun gate = run_cli({"gate", dir, "--selection", "optimized", "--out", out});
    EXPECT_TRUE(gate.exit_code == 0 || gate.exit_code == 1) << gate.exit_code << gate.output;
    EXPECT_TRUE(std::filesystem::is_regular_file(out + "/findings.json"));
    // Conform finds nothing wrong with the compiled tree (its shape is a note of style).
    std::istringstream lines(gate.output);
    for (std::string line; std::getline(lines, line);)
      EXPECT_FALSE(line.find(": error: ") != std::string::npos &&
                   line.find("[compiled-") != std::string::npos)
          << line;
  }
}

}  // namespace
}  // namespace uabt::testing
