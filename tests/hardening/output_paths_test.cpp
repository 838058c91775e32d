// Where uabt writes its output (-o FILE, --out DIR, every file of the gate's report folder): a
// regular file is replaced atomically, a symlink followed, a character device written directly,
// anything else refused with exit 2 and what is wrong with the path. Only temporary files and
// symlinks are written: no test writes a device of the machine (/dev/zero takes any write, and
// /dev/full is only reached through a link, for the error it gives).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

namespace fs = std::filesystem;

const char* const kNodes =
    "<root BTCPP_format=\"4\">\n  <TreeNodesModel>\n    <Action ID=\"MoveForward\"/>\n"
    "  </TreeNodesModel>\n</root>\n";

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The good mission, and a scratch folder beside it with a nodes.xml for `uabt schema`.
struct Scratch {
  TempMission mission{good_mission_files()};
  fs::path dir = mission.dir();
  fs::path scratch = mission.dir().parent_path() / "scratch";

  Scratch() {
    fs::create_directories(scratch);
    write_text(scratch / "nodes.xml", kNodes);
  }
  std::string nodes() const { return (scratch / "nodes.xml").string(); }
  std::string at(const std::string& name) const { return (scratch / name).string(); }
};

bool still_a_fifo(const fs::path& p) {
  return fs::is_fifo(fs::symlink_status(p));
}

TEST(OutputPaths, ASymlinkIsFollowedAndItsTargetReplaced) {
  const Scratch s;
  write_text(s.scratch / "target.xml", "old");
  fs::create_symlink("target.xml", s.scratch / "link.xml");
  const CliRun run = run_cli({"compile", s.dir.string(), "-o", s.at("link.xml")});
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::is_symlink(s.scratch / "link.xml"));
  EXPECT_NE(read_all(s.scratch / "target.xml").find("<root BTCPP_format"), std::string::npos);
  // A link to a file not written yet: the file is created where the link points.
  fs::create_symlink("fresh.xsd", s.scratch / "schema-link.xsd");
  const CliRun schema = run_cli({"schema", s.nodes(), "-o", s.at("schema-link.xsd")});
  EXPECT_EQ(schema.exit_code, 0) << schema.output;
  EXPECT_TRUE(fs::is_symlink(s.scratch / "schema-link.xsd"));
  EXPECT_NE(read_all(s.scratch / "fresh.xsd").find("<xs:schema"), std::string::npos);
}

TEST(OutputPaths, ACharacterDeviceIsWrittenInPlace) {
  const Scratch s;
  fs::create_symlink("/dev/zero", s.scratch / "zero");
  const CliRun run = run_cli({"schema", s.nodes(), "-o", s.at("zero")});
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::is_symlink(s.scratch / "zero"));
  EXPECT_TRUE(fs::is_character_file("/dev/zero"));
}

TEST(OutputPaths, ADeviceThatRefusesTheBytesIsAnError) {
  const Scratch s;
  fs::create_symlink("/dev/full", s.scratch / "full");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"schema", s.nodes(), "-o", s.at("full")},
        std::vector<std::string>{"compile", s.dir.string(), "-o", s.at("full")}}) {
    SCOPED_TRACE(args.front());
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("uabt: " + s.at("full") + ": cannot write: No space left on device"),
              std::string::npos)
        << run.output;
    EXPECT_TRUE(fs::is_symlink(s.scratch / "full"));
  }
}

TEST(OutputPaths, AFifoADirectoryAndASocketAreNeverReplaced) {
  const Scratch s;
  ASSERT_EQ(::mkfifo((s.scratch / "fifo").c_str(), 0600), 0);
  fs::create_directory(s.scratch / "folder");
  for (const auto& [name, kind] : {std::pair<std::string, std::string>{"fifo", "a fifo"},
                                   std::pair<std::string, std::string>{"folder", "a directory"}}) {
    SCOPED_TRACE(name);
    const CliRun compile = run_cli({"compile", s.dir.string(), "-o", s.at(name)});
    EXPECT_EQ(compile.exit_code, 2) << compile.output;
    EXPECT_EQ(compile.output, "uabt: " + s.at(name) + ": is " + kind +
                                  "; uabt writes a regular file or a character device, and "
                                  "replaces nothing else\n");
    const CliRun schema = run_cli({"schema", s.nodes(), "-o", s.at(name)});
    EXPECT_EQ(schema.exit_code, 2) << schema.output;
  }
  EXPECT_TRUE(still_a_fifo(s.scratch / "fifo"));
  EXPECT_TRUE(fs::is_directory(s.scratch / "folder"));
  // Through a symlink too.
  fs::create_symlink("fifo", s.scratch / "to-fifo");
  EXPECT_EQ(run_cli({"compile", s.dir.string(), "-o", s.at("to-fifo")}).exit_code, 2);
  EXPECT_TRUE(fs::is_symlink(s.scratch / "to-fifo"));
  EXPECT_TRUE(still_a_fifo(s.scratch / "fifo"));
}

TEST(OutputPaths, AnOutFolderThatIsAFileIsACommandLineError) {
  const Scratch s;
  write_text(s.scratch / "report.txt", "mine");
  const CliRun gate = run_cli({"gate", s.dir.string(), "--out", s.at("report.txt")});
  EXPECT_EQ(gate.exit_code, 2) << gate.output;
  EXPECT_EQ(gate.output,
            "uabt: " + s.at("report.txt") + ": --out names a regular file, not a directory\n");
  EXPECT_EQ(read_all(s.scratch / "report.txt"), "mine");
  // A folder below a file cannot be made either.
  const CliRun below = run_cli({"gate", s.dir.string(), "--out", s.at("report.txt/out")});
  EXPECT_EQ(below.exit_code, 2) << below.output;
  EXPECT_EQ(below.output, "uabt: " + s.at("report.txt/out") + ": " + s.at("report.txt") +
                              " is a regular file, not a directory\n");
  for (const char* command : {"report", "tests"}) {
    SCOPED_TRACE(command);
    const CliRun run = run_cli({command, s.dir.string(), "--out", s.at("report.txt")});
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("--out names a regular file, not a directory"), std::string::npos)
        << run.output;
  }
  const CliRun prove = run_cli({"prove", s.dir.string(), "--counterexamples", s.at("report.txt")});
  EXPECT_EQ(prove.exit_code, 2) << prove.output;
  EXPECT_NE(prove.output.find("--counterexamples names a regular file"), std::string::npos)
      << prove.output;
  EXPECT_EQ(read_all(s.scratch / "report.txt"), "mine");
}

// Every file the gate writes in its folder follows the same rules: a fifo where findings.txt
// goes stays a fifo, and the gate says so.
TEST(OutputPaths, TheGateNeverReplacesAReportFileThatIsNotAFile) {
  const Scratch s;
  fs::create_directory(s.scratch / "out");
  ASSERT_EQ(::mkfifo((s.scratch / "out" / "findings.txt").c_str(), 0600), 0);
  const CliRun gate = run_cli({"gate", s.dir.string(), "--out", s.at("out")});
  EXPECT_EQ(gate.exit_code, 2) << gate.output;
  EXPECT_NE(gate.output.find(s.at("out") + "/findings.txt: is a fifo"), std::string::npos)
      << gate.output;
  EXPECT_TRUE(still_a_fifo(s.scratch / "out" / "findings.txt"));
}

// The gate writes through a symlinked report folder and symlinked report files alike.
TEST(OutputPaths, TheGateWritesThroughSymlinks) {
  const Scratch s;
  fs::create_directory(s.scratch / "real");
  fs::create_symlink("real", s.scratch / "out");
  write_text(s.scratch / "kept.md", "old");
  fs::create_symlink("../kept.md", s.scratch / "real" / "summary.md");
  const CliRun gate = run_cli({"gate", s.dir.string(), "--out", s.at("out")});
  EXPECT_EQ(gate.exit_code, 0) << gate.output;
  EXPECT_TRUE(fs::is_symlink(s.scratch / "out"));
  EXPECT_TRUE(fs::is_symlink(s.scratch / "real" / "summary.md"));
  EXPECT_NE(read_all(s.scratch / "kept.md"), "old");
  EXPECT_TRUE(fs::is_regular_file(s.scratch / "real" / "findings.json"));
}

}  // namespace
}  // namespace uabt::testing
