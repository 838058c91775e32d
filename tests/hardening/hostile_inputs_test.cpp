// Hostile and broken missions through the real gate (load → verify → compile → conform) and the
// real CLI: each gives a clear finding that names the file (and line where there is one), never
// a crash and never a pass.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

namespace fs = std::filesystem;

std::string junk(std::size_t size, bool with_nul) {
  std::string s;
  std::uint32_t x = 12345;
  for (std::size_t i = 0; i < size; ++i) {
    x = x * 1103515245u + 12345u;
    s += static_cast<char>((x >> 16) & 0xFF);
  }
  if (with_nul && size > 10) s[size / 2] = '\0';
  return s;
}

// The gate failed with an error finding located in `file` (at a line when `with_line`).
::testing::AssertionResult fails_in(const GateRun& run, const std::string& file,
                                    bool with_line = true, const std::string& check = "") {
  if (!run.outcome) return ::testing::AssertionFailure() << "not loaded: " << run.load_error;
  if (run.passed()) return ::testing::AssertionFailure() << "the gate passed:\n" << run.text();
  const Finding* f = run.error_in(file, check);
  if (f == nullptr)
    return ::testing::AssertionFailure() << "no error " << check << " in " << file << ":\n"
                                         << run.text();
  if (with_line && f->location.line < 1)
    return ::testing::AssertionFailure() << "the finding has no line: " << f->message;
  return ::testing::AssertionSuccess();
}

TEST(Hostile, TheGoodMissionPasses) {
  const GateRun run = gate_with("domain.fret", good_mission_files()["domain.fret"]);
  EXPECT_TRUE(run.passed()) << run.text();
}

// --- binary junk, invalid UTF-8, empty files -----------------------------------------------

TEST(Hostile, BinaryJunkInMissionXml) {
  const GateRun run = gate_with("mission.xml", junk(5000, true));
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-xml"));
  EXPECT_NE(run.error_in("mission.xml")->message.find("binary content"), std::string::npos);
}

TEST(Hostile, BinaryJunkInRequirements) {
  const GateRun run = gate_with("requirements.fret", junk(5000, true));
  ASSERT_TRUE(fails_in(run, "requirements.fret", true, "fretish-syntax"));
}

TEST(Hostile, BinaryJunkInDomain) {
  const GateRun run = gate_with("domain.fret", junk(5000, true));
  ASSERT_TRUE(fails_in(run, "domain.fret", true, "fretish-syntax"));
}

TEST(Hostile, BinaryJunkInAnAlternative) {
  const GateRun run = gate_with("alternatives/navigation/on_dust.xml", junk(3000, false));
  ASSERT_TRUE(fails_in(run, "alternatives/navigation/on_dust.xml", true, "bt-xml"));
}

TEST(Hostile, InvalidUtf8InMissionXmlIsLocated) {
  const GateRun run =
      gate_with("mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                            "      <Say text=\"caf\xE9\"/>\n    </Sequence>"));
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-xml"));
  const Finding* f = run.error_in("mission.xml");
  EXPECT_EQ(f->location.line, 5);
  EXPECT_NE(f->message.find("UTF-8"), std::string::npos) << f->message;
}

TEST(Hostile, InvalidUtf8InRequirementsIsLocated) {
  const GateRun run = gate_with(
      "requirements.fret",
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if On\xC3\x28Rocks Mission shall satisfy selected_alt = on_rocks\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  ASSERT_TRUE(fails_in(run, "requirements.fret", true, "fretish-syntax"));
  EXPECT_EQ(run.error_in("requirements.fret")->location.line, 2);
}

TEST(Hostile, InvalidUtf8InAQuotedIdentifierNeverReachesTheCompiledTree) {
  const GateRun run = gate_with(
      "requirements.fret",
      "Req1: In navigation if \"On\xFF\xFE\" Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed()) << run.text();
  EXPECT_TRUE(has_errors(run.findings()));
}

TEST(Hostile, InvalidUtf8InDomainIsLocated) {
  const GateRun run = gate_with("domain.fret", "boolean OnDust, OnRocks\nboolean \x80\x81\n");
  ASSERT_TRUE(fails_in(run, "domain.fret", true, "fretish-syntax"));
  EXPECT_EQ(run.error_in("domain.fret")->location.line, 2);
}

TEST(Hostile, EmptyMissionXml) {
  const GateRun run = gate_with("mission.xml", "");
  ASSERT_TRUE(fails_in(run, "mission.xml", false, "bt-xml"));
  EXPECT_NE(run.error_in("mission.xml")->message.find("empty file"), std::string::npos);
}

TEST(Hostile, EmptyRequirementsLeaveTheAdaptableNodeUnresolved) {
  const GateRun run = gate_with("requirements.fret", "");
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "ref-adaptable-unresolved"));
}

TEST(Hostile, EmptyDomainIsADomainWithoutAssumptions) {
  // Without "one terrain at a time" dust and rocks may be detected together: an overlap.
  const GateRun run = gate_with("domain.fret", "");
  ASSERT_TRUE(fails_in(run, "requirements.fret", true, "guard-overlap"));
}

TEST(Hostile, EmptyAlternative) {
  const GateRun run = gate_with("alternatives/navigation/on_rocks.xml", "");
  ASSERT_TRUE(fails_in(run, "alternatives/navigation/on_rocks.xml", false, "bt-xml"));
}

// --- missing files and paths ------------------------------------------------------------------

TEST(Hostile, MissingRequirementsFile) {
  auto files = good_mission_files();
  files.erase("requirements.fret");
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed());
  const Finding* f = run.first("load-file");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->severity, Severity::error);
  EXPECT_NE(f->message.find("requirements.fret"), std::string::npos) << f->message;
}

TEST(Hostile, MissingAlternativeFile) {
  auto files = good_mission_files();
  files.erase("alternatives/navigation/on_rocks.xml");
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "requirements.fret", true, "ref-unknown-alternative"));
  EXPECT_EQ(run.error_in("requirements.fret")->location.line, 2);
}

TEST(Hostile, MissionDirectoryWithoutMissionXml) {
  auto files = good_mission_files();
  files.erase("mission.xml");
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  EXPECT_FALSE(run.outcome.has_value());
  EXPECT_NE(run.load_error.find("mission.xml"), std::string::npos) << run.load_error;

  const CliRun cli = run_cli({"gate", m.dir().string(), "--out", (m.dir() / "out").string()});
  EXPECT_EQ(cli.exit_code, 2) << cli.output;
  EXPECT_NE(cli.output.find("mission.xml"), std::string::npos) << cli.output;
}

TEST(Hostile, CliMissingPathIsExitTwo) {
  TempMission m({});
  for (const char* command : {"gate", "verify"}) {
    const CliRun cli = run_cli({command, (m.dir() / "no-such-mission").string()});
    EXPECT_EQ(cli.exit_code, 2) << command << ": " << cli.output;
  }
}

TEST(Hostile, CliJunkMissionIsExitOneWithTheFile) {
  auto files = good_mission_files();
  files["mission.xml"] = junk(2000, true);
  TempMission m(files);
  const CliRun cli = run_cli({"gate", m.dir().string(), "--out", (m.dir() / "out").string()});
  EXPECT_EQ(cli.exit_code, 1) << cli.output;
  EXPECT_NE(cli.output.find("mission.xml:"), std::string::npos) << cli.output;
  EXPECT_NE(cli.output.find("[bt-xml]"), std::string::npos) << cli.output;

  const CliRun json = run_cli({"verify", m.dir().string(), "--format", "json"});
  EXPECT_EQ(json.exit_code, 1) << json.output;
  EXPECT_NE(json.output.find("\"verdict\": \"fail\""), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"file\": \"mission.xml\""), std::string::npos) << json.output;
}

TEST(Hostile, CliJunkRequirementsIsExitOneWithTheLine) {
  auto files = good_mission_files();
  files["requirements.fret"] =
      "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
      "Req2: In navigation if OnDust && Mission shall satisfy selected_alt = on_rocks\n";
  TempMission m(files);
  const CliRun cli = run_cli({"compile", m.dir().string(), "-o", (m.dir() / "c.xml").string()});
  EXPECT_EQ(cli.exit_code, 1) << cli.output;
  EXPECT_NE(cli.output.find("requirements.fret:2:"), std::string::npos) << cli.output;
  EXPECT_FALSE(fs::exists(m.dir() / "c.xml")) << "nothing is emitted for a broken mission";
}

// --- a directory where a file is expected ------------------------------------------------------

TEST(Hostile, DirectoryInsteadOfRequirementsFile) {
  auto files = good_mission_files();
  files.erase("requirements.fret");
  files["requirements.fret/nested.txt"] = "x";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed());
  const Finding* f = run.first("load-file");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_NE(f->message.find("requirements.fret"), std::string::npos) << f->message;
}

TEST(Hostile, DirectoryInsteadOfDomainFile) {
  auto files = good_mission_files();
  files.erase("domain.fret");
  files["domain.fret/nested.txt"] = "x";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "domain.fret", false, "load-file")) << "a domain.fret that cannot be "
                                                                   "read is not a missing domain";
}

TEST(Hostile, DirectoryInsteadOfMissionXml) {
  auto files = good_mission_files();
  files.erase("mission.xml");
  files["mission.xml/nested.txt"] = "x";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  if (run.outcome) {
    EXPECT_TRUE(fails_in(run, "mission.xml", false));
  } else {
    EXPECT_NE(run.load_error.find("mission.xml"), std::string::npos) << run.load_error;
  }
}

TEST(Hostile, DirectoryInsteadOfAnAlternative) {
  auto files = good_mission_files();
  files.erase("alternatives/navigation/on_dust.xml");
  files["alternatives/navigation/on_dust.xml/x"] = "x";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "requirements.fret", true, "ref-unknown-alternative"));
}

// --- size ------------------------------------------------------------------------------------

TEST(Hostile, TwentyMegabyteFilesAreRefusedByName) {
  const std::string big(20u * 1024u * 1024u, ' ');
  for (const char* file :
       {"mission.xml", "requirements.fret", "domain.fret", "alternatives/navigation/on_dust.xml"}) {
    SCOPED_TRACE(file);
    const GateRun run = gate_with(file, big);
    ASSERT_TRUE(run.outcome.has_value());
    EXPECT_FALSE(run.passed());
    const Finding* f = run.error_in(file);
    ASSERT_NE(f, nullptr) << run.text();
    EXPECT_NE(f->message.find("limit"), std::string::npos) << f->message;
  }
}

// --- XML tricks ------------------------------------------------------------------------------

TEST(Hostile, BillionLaughsIsRefusedBeforeExpansion) {
  std::string dtd = "<?xml version=\"1.0\"?>\n<!DOCTYPE root [\n  <!ENTITY lol \"lol\">\n";
  for (int i = 1; i < 10; ++i) {
    dtd += "  <!ENTITY lol" + std::to_string(i) + " \"";
    for (int k = 0; k < 10; ++k)
      dtd += "&lol" + (i == 1 ? std::string() : std::to_string(i - 1)) + ";";
    dtd += "\">\n";
  }
  dtd += "]>\n";
  const std::string xml = dtd + mission_with(
                                    "    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                    "      <Say text=\"&lol9;\"/>\n    </Sequence>");
  const GateRun run = gate_with("mission.xml", xml);
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-xml"));
  EXPECT_EQ(run.error_in("mission.xml")->location.line, 2);
  EXPECT_NE(run.error_in("mission.xml")->message.find("DTD"), std::string::npos);
}

TEST(Hostile, ExternalEntityIsRefused) {
  const std::string xml =
      "<?xml version=\"1.0\"?>\n<!DOCTYPE root [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>\n" +
      alternative_tree("on_dust", "<Say text=\"&x;\"/>");
  const GateRun run = gate_with("alternatives/navigation/on_dust.xml", xml);
  ASSERT_TRUE(fails_in(run, "alternatives/navigation/on_dust.xml", true, "bt-xml"));
  EXPECT_EQ(run.error_in("alternatives/navigation/on_dust.xml")->location.line, 2);
  for (const Finding& f : run.findings())
    EXPECT_EQ(f.message.find("root:"), std::string::npos) << "file content leaked: " << f.message;
}

TEST(Hostile, UnknownEntityIsAnError) {
  const GateRun run =
      gate_with("mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                            "      <Say text=\"&nope;\"/>\n    </Sequence>"));
  // tinyxml2 keeps an unknown entity as text; whatever it does, the mission must stay sane.
  ASSERT_TRUE(run.outcome.has_value());
  for (const Finding& f : run.findings()) EXPECT_FALSE(f.location.file.empty()) << f.message;
}

std::string mission_including(const std::string& path) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
         "  <include path=\"" +
         path +
         "\"/>\n"
         "  <BehaviorTree ID=\"MainTree\">\n"
         "    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n      <SubTree ID=\"Lib\"/>\n"
         "    </Sequence>\n  </BehaviorTree>\n</root>\n";
}

TEST(Hostile, IncludeWithDotDotLeavesTheMission) {
  auto files = good_mission_files();
  files["mission.xml"] = mission_including("../outside.xml");
  TempMission m(files);
  std::ofstream(m.dir().parent_path() / "outside.xml")
      << "<root><BehaviorTree ID=\"Lib\"><Stop/></BehaviorTree></root>";
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
  EXPECT_EQ(run.error_in("mission.xml", "bt-structure")->location.line, 2);
  EXPECT_NE(run.error_in("mission.xml", "bt-structure")->message.find("leaves the mission"),
            std::string::npos);
}

TEST(Hostile, IncludeWithAnAbsolutePathIsRefused) {
  auto files = good_mission_files();
  TempMission m(files);
  std::ofstream(m.dir().parent_path() / "outside.xml")
      << "<root><BehaviorTree ID=\"Lib\"><Stop/></BehaviorTree></root>";
  m.write("mission.xml", mission_including((m.dir().parent_path() / "outside.xml").string()));
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
  EXPECT_NE(run.error_in("mission.xml", "bt-structure")->message.find("absolute"),
            std::string::npos);
}

TEST(Hostile, IncludeThroughASymlinkLeavingTheMission) {
  auto files = good_mission_files();
  files["mission.xml"] = mission_including("lib/inside.xml");
  TempMission m(files);
  const fs::path outside = m.dir().parent_path() / "outside.xml";
  std::ofstream(outside) << "<root><BehaviorTree ID=\"Lib\"><Stop/></BehaviorTree></root>";
  fs::create_directories(m.dir() / "lib");
  fs::create_symlink(outside, m.dir() / "lib" / "inside.xml");
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
  EXPECT_NE(run.error_in("mission.xml", "bt-structure")->message.find("leaves the mission"),
            std::string::npos);
}

TEST(Hostile, IncludeOfASymlinkedDirectoryLeavingTheMission) {
  auto files = good_mission_files();
  files["mission.xml"] = mission_including("lib/outside.xml");
  TempMission m(files);
  const fs::path outside_dir = m.dir().parent_path() / "elsewhere";
  fs::create_directories(outside_dir);
  std::ofstream(outside_dir / "outside.xml")
      << "<root><BehaviorTree ID=\"Lib\"><Stop/></BehaviorTree></root>";
  fs::create_directory_symlink(outside_dir, m.dir() / "lib");
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
}

TEST(Hostile, IncludeCycle) {
  auto files = good_mission_files();
  files["mission.xml"] = mission_including("a.xml");
  files["a.xml"] =
      "<root><include path=\"b.xml\"/><BehaviorTree ID=\"Lib\"><Stop/></BehaviorTree></root>";
  files["b.xml"] = "<root><include path=\"a.xml\"/></root>";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed());
  const Finding* f = run.first("bt-structure");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_NE(f->message.find("include cycle"), std::string::npos) << run.text();
}

// --- tree structure --------------------------------------------------------------------------

TEST(Hostile, SubTreeCycle) {
  const GateRun run =
      gate_with("mission.xml",
                "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
                "  <BehaviorTree ID=\"MainTree\">\n"
                "    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n      <SubTree ID=\"A\"/>\n"
                "    </Sequence>\n  </BehaviorTree>\n"
                "  <BehaviorTree ID=\"A\">\n    <SubTree ID=\"B\"/>\n  </BehaviorTree>\n"
                "  <BehaviorTree ID=\"B\">\n    <Sequence><Stop/><SubTree ID=\"A\"/></Sequence>\n"
                "  </BehaviorTree>\n</root>\n");
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
  EXPECT_NE(run.error_in("mission.xml")->message.find("SubTree cycle"), std::string::npos)
      << run.text();
}

TEST(Hostile, SelfRecursiveAlternative) {
  const GateRun run = gate_with("alternatives/navigation/on_dust.xml",
                                alternative_tree("on_dust", "<SubTree ID=\"on_dust\"/>"));
  ASSERT_TRUE(fails_in(run, "alternatives/navigation/on_dust.xml", true, "bt-structure"));
}

TEST(Hostile, DuplicateRequirementIds) {
  const GateRun run =
      gate_with("requirements.fret",
                "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
                "Req1: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
                "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  ASSERT_TRUE(fails_in(run, "requirements.fret", true, "ref-duplicate-id"));
  EXPECT_EQ(run.error_in("requirements.fret", "ref-duplicate-id")->location.line, 2);
}

TEST(Hostile, DuplicateAdaptableNodes) {
  const GateRun run = gate_with(
      "mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                  "      <Adaptable ID=\"navigation\"/>\n    </Sequence>"));
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "ref-duplicate-id"));
  EXPECT_EQ(run.error_in("mission.xml", "ref-duplicate-id")->location.line, 5);
}

TEST(Hostile, DuplicateTreeIds) {
  const GateRun run = gate_with("alternatives/navigation/on_rocks.xml",
                                alternative_tree("on_dust", "<MoveBackward/>"));
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed()) << run.text();
  EXPECT_NE(run.first("ref-duplicate-id"), nullptr) << run.text();
}

TEST(Hostile, AdaptableWithChildren) {
  const GateRun run = gate_with(
      "mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\">\n"
                                  "        <Stop/>\n      </Adaptable>\n    </Sequence>"));
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
  const Finding* f = run.error_in("mission.xml", "bt-structure");
  EXPECT_EQ(f->location.line, 4);
  EXPECT_EQ(f->location.column, 7);
  EXPECT_NE(f->message.find("no children"), std::string::npos) << f->message;
}

TEST(Hostile, AdaptableWithoutId) {
  const GateRun run = gate_with(
      "mission.xml",
      mission_with("    <Sequence>\n      <Adaptable/>\n      <Adaptable ID=\"navigation\"/>\n"
                   "    </Sequence>"));
  ASSERT_TRUE(fails_in(run, "mission.xml", true, "bt-structure"));
  EXPECT_EQ(run.error_in("mission.xml", "bt-structure")->location.line, 4);
}

TEST(Hostile, AdaptableInsideAnAlternative) {
  // An alternative is plain behaviour: an adaptable node in it would survive compilation.
  const GateRun run = gate_with("alternatives/navigation/on_dust.xml",
                                alternative_tree("on_dust", "<Adaptable ID=\"navigation\"/>"));
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed()) << run.text();
}

TEST(Hostile, ConditionNameThatIsNotAnXmlName) {
  // A quoted FRETISH identifier may hold anything; as a condition leaf it must not inject XML
  // into the compiled tree, and the gate must not pass it.
  for (const char* name : {"On Dust", "IsOk/><AlwaysSuccess", "a\"b", "x&y", "<Stop/>"}) {
    SCOPED_TRACE(name);
    std::string quoted;
    for (const char* c = name; *c; ++c)
      quoted += (*c == '"' ? std::string("\\\"") : std::string(1, *c));
    const GateRun run =
        gate_with("requirements.fret",
                  "Req1: In navigation if \"" + quoted +
                      "\" Mission shall satisfy selected_alt = on_dust\n"
                      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
    ASSERT_TRUE(run.outcome.has_value());
    EXPECT_FALSE(run.passed()) << run.text();
    const Finding* f = run.error_in("requirements.fret");
    EXPECT_NE(f, nullptr) << "the name should be refused where it is written:\n" << run.text();
  }
}

// --- arithmetic --------------------------------------------------------------------------------

TEST(Hostile, HugeNumericLiteralGivesACorrectVerdict) {
  auto files = good_mission_files();
  files["domain.fret"] = "integer battery in [0, 100]\n";
  files["requirements.fret"] =
      "Req1: In navigation if battery > 99999999999999999999999999 Mission shall satisfy "
      "selected_alt = on_dust\n"
      "Req2: In navigation if battery < 99999999999999999999999999 Mission shall satisfy "
      "selected_alt = on_rocks\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed());
  // Req1 can never hold; Req2 always holds, so the default is shadowed.
  const Finding* unsat = run.first("guard-unsatisfiable");
  ASSERT_NE(unsat, nullptr) << run.text();
  EXPECT_EQ(unsat->location.file, "requirements.fret");
  EXPECT_EQ(unsat->location.line, 1);
  EXPECT_EQ(run.first("verification-inconclusive"), nullptr) << run.text();
}

TEST(Hostile, HugeNumericBoundsAreHandled) {
  auto files = good_mission_files();
  files["domain.fret"] =
      "integer battery in [-99999999999999999999999999, 99999999999999999999999999]\n";
  files["requirements.fret"] =
      "Req1: In navigation if battery > 99999999999999999999999990 Mission shall satisfy "
      "selected_alt = on_dust\n"
      "Req2: In navigation if battery <= 99999999999999999999999990 Mission shall satisfy "
      "selected_alt = on_rocks\n";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  // Two disjoint guards that cover the whole range: no overlap, no gap.
  EXPECT_EQ(run.first("guard-overlap"), nullptr) << run.text();
  EXPECT_EQ(run.first("guard-gap"), nullptr) << run.text();
  ASSERT_EQ(run.outcome->verification.coverage.size(), 1u);
  EXPECT_FALSE(run.outcome->verification.coverage[0].counted);
}

TEST(Hostile, DivisionByZeroIsFlaggedWhereItIsWritten) {
  auto files = good_mission_files();
  files["domain.fret"] = "integer x in [0, 10]\n";
  files["requirements.fret"] =
      "Req1: In navigation if x / 0 > 1 Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  const Finding* f = run.first("arith-division-by-zero");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->location.file, "requirements.fret");
  EXPECT_EQ(f->location.line, 1);
  EXPECT_EQ(f->location.column, 24) << "where 'x / 0' starts";
}

TEST(Hostile, DivisionByZeroNeverPasses) {
  // x / 0 means nothing, in FRET, Z3 and the robot's scripts alike: a guard built on it must not
  // be uplinked.
  auto files = good_mission_files();
  files["domain.fret"] = "integer x in [0, 10]\n";
  files["requirements.fret"] =
      "Req1: In navigation if x / 0 > 1 Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir());
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed()) << run.text();
}

TEST(Hostile, NonlinearContradictionNeverPasses) {
  auto files = good_mission_files();
  files["domain.fret"] = "integer x, y\n";
  files["requirements.fret"] =
      "Req1: In navigation if x * y > 2 & x * x < 0 Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir(), 2000);
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed()) << run.text();
  const Finding* unsat = run.first("guard-unsatisfiable");
  const Finding* unknown = run.first("verification-inconclusive");
  ASSERT_TRUE(unsat != nullptr || unknown != nullptr) << run.text();
  const Finding* f = unsat ? unsat : unknown;
  EXPECT_EQ(f->severity, Severity::error);
  EXPECT_EQ(f->location.file, "requirements.fret");
  EXPECT_EQ(f->location.line, 1);
}

TEST(Hostile, UndecidableGuardIsInconclusiveAndFailsTheGate) {
  // x³ + y³ = z³ has no positive solution (Fermat, n = 3), which no solver decides for
  // unbounded integers: the answer is "unknown", and unknown fails the gate.
  auto files = good_mission_files();
  files["domain.fret"] = "integer x, y, z\n";
  files["requirements.fret"] =
      "Req1: In navigation if x * x * x + y * y * y = z * z * z & x > 0 & y > 0 & z > 0 Mission "
      "shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n";
  TempMission m(files);
  const GateRun run = run_real_gate(m.dir(), 300);
  ASSERT_TRUE(run.outcome.has_value());
  EXPECT_FALSE(run.passed()) << run.text();
  const Finding* f = run.first("verification-inconclusive");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->severity, Severity::error);
  EXPECT_EQ(f->location.file, "requirements.fret");
  EXPECT_EQ(f->location.line, 1);

  const CliRun cli = run_cli({"verify", m.dir().string(), "--timeout-ms", "300"});
  EXPECT_EQ(cli.exit_code, 1) << cli.output;
  EXPECT_NE(cli.output.find("[verification-inconclusive]"), std::string::npos) << cli.output;
}

}  // namespace
}  // namespace uabt::testing
