// A symbolic link that leads out of the mission folder (or an uplink package) is refused as an
// <include> outside the folder is: the file is not read, and nothing of it is shown.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

namespace fs = std::filesystem;

const std::string kOutside =
    "leads outside the mission folder through a symbolic link; uabt "
    "reads only files inside it";

// A file outside the mission whose first word must never appear in uabt's output.
class Outside {
 public:
  explicit Outside(const std::string& content) {
    dir_ = fs::temp_directory_path() / ("uabt-outside-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "secret.txt") << content;
  }
  ~Outside() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path file() const { return dir_ / "secret.txt"; }
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
};

// The good mission with `path` replaced by a symlink to `target`.
void link(const TempMission& m, const std::string& path, const fs::path& target) {
  fs::remove(m.dir() / path);
  fs::create_symlink(target, m.dir() / path);
}

TEST(Symlinks, AnAlternativeOutsideTheFolderIsNotRead) {
  const Outside outside(alternative_tree("on_dust", "<MoveForward/>"));
  TempMission m(good_mission_files());
  link(m, "alternatives/navigation/on_dust.xml", outside.file());
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome) << run.load_error;
  EXPECT_FALSE(run.passed()) << run.text();
  const Finding* f = run.error_in("alternatives/navigation/on_dust.xml", "load-file");
  ASSERT_NE(f, nullptr) << run.text();
  // The file is named once, by the finding's place.
  EXPECT_EQ(f->message, kOutside);
  EXPECT_EQ(run.first("ref-unknown-alternative"), nullptr) << run.text();
}

TEST(Symlinks, ADomainLinkedOutsideIsNeverEchoed) {
  const Outside outside("topsecretword:x:0:0:root:/root:/bin/bash\n");
  TempMission m(good_mission_files());
  link(m, "domain.fret", outside.file());
  const CliRun cli = run_cli({"verify", m.dir().string()});
  EXPECT_EQ(cli.exit_code, 1) << cli.output;
  EXPECT_EQ(cli.output.find("topsecretword"), std::string::npos) << cli.output;
  EXPECT_NE(cli.output.find("domain.fret: error: " + kOutside), std::string::npos) << cli.output;
  // The file is named once.
  EXPECT_EQ(cli.output.find("domain.fret: domain.fret"), std::string::npos) << cli.output;
}

TEST(Symlinks, EveryFileOfTheMissionIsConfined) {
  for (const std::string path : {"mission.xml", "requirements.fret", "nodes.xml"}) {
    const Outside outside("topsecretword and more\n");
    auto files = good_mission_files();
    files["nodes.xml"] = "<root BTCPP_format=\"4\"><TreeNodesModel/></root>\n";
    TempMission m(files);
    link(m, path, outside.file());
    const GateRun run = run_real_gate(m.dir());
    ASSERT_TRUE(run.outcome) << path << ": " << run.load_error;
    const Finding* f = run.error_in(path, "load-file");
    ASSERT_NE(f, nullptr) << path << ":\n" << run.text();
    EXPECT_EQ(f->message, kOutside);
    EXPECT_EQ(run.text().find("topsecretword"), std::string::npos) << run.text();
  }
}

TEST(Symlinks, AWorldModelLinkedOutsideIsNotRead) {
  const Outside outside("{\"topsecretword\": 1}\n");
  auto files = good_mission_files();
  files["requirements.fret"] += "Calm: Mission shall always satisfy !(OnDust & OnRocks)\n";
  TempMission m(files);
  fs::create_symlink(outside.file(), m.dir() / "world.json");
  const CliRun cli = run_cli({"prove", m.dir().string()});
  EXPECT_NE(cli.exit_code, 0) << cli.output;
  EXPECT_EQ(cli.output.find("topsecretword"), std::string::npos) << cli.output;
  EXPECT_NE(cli.output.find("world.json"), std::string::npos) << cli.output;
  EXPECT_NE(cli.output.find(kOutside), std::string::npos) << cli.output;
}

TEST(Symlinks, AnUplinkPackageFileLinkedOutsideIsNotRead) {
  const Outside outside("topsecretword\n");
  TempMission m(good_mission_files());
  const fs::path package = m.dir().parent_path() / "uplink";
  fs::create_directories(package);
  fs::create_symlink(outside.file(), package / "requirements.fret");
  std::string error;
  load::LoadOptions options;
  options.uplinks = {package};
  const auto mission = load::load_mission(m.dir(), options, error);
  ASSERT_TRUE(mission) << error;
  const std::string text = format_text(mission->findings);
  EXPECT_NE(text.find("requirements.fret: error: leads outside the uplink package through a "
                      "symbolic link; uabt reads only files inside it"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("topsecretword"), std::string::npos) << text;
}

TEST(Symlinks, ALinkThatStaysInsideTheFolderIsRead) {
  auto files = good_mission_files();
  files["shared/on_dust.xml"] = files["alternatives/navigation/on_dust.xml"];
  TempMission m(files);
  link(m, "alternatives/navigation/on_dust.xml", "../../shared/on_dust.xml");
  const GateRun run = run_real_gate(m.dir());
  EXPECT_TRUE(run.passed()) << run.text();
}

}  // namespace
}  // namespace uabt::testing
