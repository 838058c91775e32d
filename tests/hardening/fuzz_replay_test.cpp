// Replays the fuzz targets' seed corpora and every input a fuzzer found (tests/fuzz/regressions/)
// through the same checks the libFuzzer targets run, so the ordinary build keeps them fixed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "bt/schema.hpp"
#include "fuzz/entry_points.hpp"
#include "fuzz/format_harnesses.hpp"
#include "fuzz/nodes_harness.hpp"
#include "fuzz/pipeline_harness.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs_of(const std::string& target, const std::string& kind) {
  std::vector<fs::path> files;
  const fs::path dir = source_dir() / "tests" / "fuzz" / kind / target;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && it->path().filename().string().front() != '.')
      files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// Every input of `target` passes `check`; returns how many there were.
std::size_t replay(const std::string& target, const std::string& kind,
                   const std::function<std::string(std::string_view)>& check) {
  const auto files = inputs_of(target, kind);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    const std::string data = contents(file);
    std::string problem;
    EXPECT_NO_THROW(problem = check(data));
    EXPECT_EQ(problem, "") << kind << "/" << target << "/" << file.filename().string();
  }
  return files.size();
}

TEST(FuzzReplay, Fretish) {
  EXPECT_GT(replay("fretish", "corpus", fuzz::check_requirements_file), 5u);
  replay("fretish", "regressions", fuzz::check_requirements_file);
}

TEST(FuzzReplay, Domain) {
  EXPECT_GT(replay("domain", "corpus", fuzz::check_domain_file), 3u);
  replay("domain", "regressions", fuzz::check_domain_file);
}

TEST(FuzzReplay, FretJson) {
  EXPECT_GT(replay("fret_json", "corpus", fuzz::check_fret_json), 3u);
  replay("fret_json", "regressions", fuzz::check_fret_json);
}

TEST(FuzzReplay, BtXml) {
  EXPECT_GT(replay("bt_xml", "corpus", fuzz::check_bt_xml), 10u);
  replay("bt_xml", "regressions", fuzz::check_bt_xml);
}

TEST(FuzzReplay, Pipeline) {
  fuzz::PipelineHarness harness;
  // A longer solver limit than the fuzzer's: a slow machine must not turn a verdict into
  // "inconclusive" here (both are accepted, but the invariants are checked on more verdicts).
  const auto check = [&](std::string_view data) { return harness.check(data, 2000); };
  EXPECT_GT(replay("pipeline", "corpus", check), 3u);
  replay("pipeline", "regressions", check);
}

// The seeds (more than `seeds` of them) and the regressions of a target over a fixed mission.
template <class Harness, class... Limit>
void replay_target(const std::string& target, std::size_t seeds, Limit... limit) {
  const Harness harness;
  const auto check = [&](std::string_view data) { return harness.check(data, limit...); };
  EXPECT_GT(replay(target, "corpus", check), seeds);
  replay(target, "regressions", check);
}

TEST(FuzzReplay, World) {
  replay_target<fuzz::WorldHarness>("world", 3);
}

TEST(FuzzReplay, Uplink) {
  replay_target<fuzz::UplinkHarness>("uplink", 3, 2000u);  // a longer solver limit, as above
}

TEST(FuzzReplay, Scenario) {
  replay_target<fuzz::ScenarioHarness>("scenario", 3);
}

TEST(FuzzReplay, Trace) {
  replay_target<fuzz::TraceHarness>("trace", 3);
}

TEST(FuzzReplay, Nodes) {
  replay_target<fuzz::NodesHarness>("nodes", 5, 2000u);  // a longer solver limit, as above
}

TEST(FuzzReplay, ScenarioUplink) {
  replay_target<fuzz::ScenarioUplinkHarness>("scenario_uplink", 5);
}

// The nodes target reaches the schema, not only the loader's errors: its complete seed loads
// without an error and gives a schema with the robot's node.
TEST(FuzzReplay, NodesHarnessCompleteSeedLoadsAndWritesASchema) {
  const fuzz::NodesHarness harness;
  ASSERT_EQ(harness.check(contents(source_dir() / "tests/fuzz/corpus/nodes/complete.xml"), 2000),
            "");
  std::string error;
  const auto mission = load::load_mission(harness.dir(), {}, error);
  ASSERT_TRUE(mission.has_value()) << error;
  EXPECT_FALSE(has_errors(mission->findings));
  ASSERT_TRUE(mission->nodes.has_value());
  EXPECT_NE(bt::write_schema(*mission->nodes).find("<xs:complexType name=\"node_Drill\">"),
            std::string::npos);
}

// The scenario-uplink target takes uplinks through the gate mid-run: of its fixed packages the
// gate passes two and rejects the overlapping one, and its first seed sees all three verdicts.
TEST(FuzzReplay, ScenarioUplinkHarnessPackagesAreAcceptedAndRejectedMidRun) {
  const fuzz::ScenarioUplinkHarness harness;
  EXPECT_TRUE(harness.passes_alone("uplinks/cool"));
  EXPECT_TRUE(harness.passes_alone("uplinks/rotary_v2"));
  EXPECT_FALSE(harness.passes_alone("uplinks/overlap"));
  const fs::path seed = source_dir() / "tests/fuzz/corpus/scenario_uplink/all_three.json";
  ASSERT_EQ(harness.check(contents(seed)), "");
  manager::ManagerOptions options;
  options.max_ticks = 40;
  const manager::ManagerRun run =
      manager::BehaviorTreeManager(
          harness.dir(), runtime::parse_scenario(contents(seed), "scenarios/fuzz.json"), options)
          .run();
  EXPECT_EQ(run.accepted_uplinks, (std::vector<std::string>{"uplinks/rotary_v2", "uplinks/cool"}));
  std::vector<std::string> verdicts;
  for (const runtime::TraceEvent& e : run.trace)
    if (e.event == "uplink") verdicts.push_back(e.uplink + " " + e.verdict);
  EXPECT_EQ(verdicts,
            (std::vector<std::string>{"uplinks/overlap rejected", "uplinks/rotary_v2 accepted",
                                      "uplinks/cool accepted"}));
}

// The uplink target reaches the uplink gate's contract, not only the loader's errors: its
// fixed package, placed by the seed uplink.json, passes the gate.
TEST(FuzzReplay, UplinkHarnessPackagePasses) {
  const fuzz::UplinkHarness harness;
  ASSERT_EQ(
      harness.check(contents(source_dir() / "tests/fuzz/corpus/uplink/place_before.json"), 2000),
      "");
  std::string error;
  const auto running = load::load_mission(harness.dir(), {}, error);
  ASSERT_TRUE(running.has_value()) << error;
  load::LoadOptions options;
  options.uplinks.push_back(harness.dir() / "uplinks" / "fuzz");
  auto merged = load::load_mission(harness.dir(), options, error);
  ASSERT_TRUE(merged.has_value()) << error;
  const gate::Outcome outcome = gate::run_uplink_gate(*running, std::move(*merged), {}, "test");
  EXPECT_TRUE(outcome.passed()) << outcome.report.findings.size() << " findings";
  ASSERT_TRUE(outcome.report.uplink.has_value());
}

// Found by fuzz_world (regressions/world/initial-escaped-newline-error-past-the-last-line.json):
// a syntax error in "initial" was placed by counting in the decoded string, so "\n" escapes
// moved it to line 3 of a one-line file. It is now where the parser stopped, as written.
TEST(FuzzReplay, WorldInitialErrorStandsWhereTheEscapedTextIsWritten) {
  try {
    prove::parse_world("{\"initial\": \"IsBitCool &\\n\\n(\"}\n", "world.json");
    FAIL() << "the world was accepted";
  } catch (const prove::WorldError& e) {
    EXPECT_STREQ(e.what(), "world.json:1:30: error: initial: expected an expression after '('");
    EXPECT_EQ(e.location.line, 1);
    EXPECT_EQ(e.location.column, 30);
  }
  // An escape before the error counts as written: \u0026 is '&', six characters.
  try {
    prove::parse_world("{\"initial\": \"IsBitCool \\u0026 )\"}", "world.json");
    FAIL() << "the world was accepted";
  } catch (const prove::WorldError& e) {
    EXPECT_EQ(e.location.column, 31) << e.what();
  }
}

// Found by the tighter fuzz_fret_json check
// (regressions/fret_json/fulltext-escaped-newline-error-past-the-last-line.json): a syntax
// error in a "fulltext" was placed by counting in the decoded sentence, so "\n" escapes moved
// it past the last line of the export. It is now where the sentence ends, as written.
TEST(FuzzReplay, FretExportErrorStandsWhereTheEscapedFulltextIsWritten) {
  fretish::Domain domain;
  const fretish::ParseResult parsed = fretish::parse_fret_json(
      "[{\"reqid\": \"R1\", \"fulltext\": \"Mission shall\\n\\n\\nsatisfy (\"}]\n",
      "requirements.json", domain);
  ASSERT_EQ(parsed.findings.size(), 1u);
  EXPECT_EQ(parsed.findings[0].location.line, 1);
  EXPECT_EQ(parsed.findings[0].location.column, 59) << parsed.findings[0].message;
}

// Found by fuzz_trace under UBSan (regressions/trace/integer-beyond-64-bits-cast-undefined.jsonl):
// whether a number is whole was asked by casting it to a 64-bit integer, undefined for 2.2e31.
// The fuzz build's replay (ctest -L fuzz) fails on the old code; here, what the user reads.
TEST(FuzzReplay, TraceIntegerBeyond64BitsDoesNotFitAnIntegerVariable) {
  std::vector<Finding> findings;
  const auto trace = monitor::read_trace(
      "{\"tick\": 1, \"state\": {\"depth\": 22222222222222222222222222222220.5}}\n", "trace.jsonl",
      findings);
  ASSERT_TRUE(trace.has_value());
  std::vector<Finding> parsed;
  const fretish::Domain domain =
      fretish::parse_domain_file("integer depth in [0, 20]\n", "domain.fret", parsed);
  const auto requirements =
      fretish::parse_requirements_file("R: Mission shall always satisfy depth <= 20\n",
                                       "requirements.fret")
          .requirements;
  monitor::check_trace(requirements, domain, *trace, "trace.jsonl", findings);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].message,
            "'depth' at tick 1 does not fit its type: the domain declares it integer");
  EXPECT_EQ(findings[0].location.line, 1);
}

// Found by fuzz_scenario (regressions/scenario/escaped-key-error-without-line-and-column.json):
// the position scanner kept a key's escapes as written ("Dr\u0069ll"), so the error about the
// key the parser decoded (Drill) found no position and named the file alone.
TEST(FuzzReplay, ScenarioErrorUnderAnEscapedKeyHasItsLineAndColumn) {
  try {
    runtime::parse_scenario("{\"actions\": {\"Dr\\u0069ll\": {\"ticks\": 0}}}\n",
                            "scenarios/fuzz.json");
    FAIL() << "the scenario was accepted";
  } catch (const runtime::ScenarioError& e) {
    EXPECT_STREQ(e.what(),
                 "scenarios/fuzz.json:1:38: error: /actions/Drill/ticks: must be at least 1, "
                 "not 0");
  }
}

// Found by fuzz_bt_xml (regressions/bt_xml/writer-explicit-id-not-an-xml-name.xml): the writer
// turned <Decorator ID="Cu<x"> into the element name <Cu<x>, so its output did not parse. An ID
// that is no XML name now stays in the explicit syntax.
TEST(FuzzReplay, WriterOutputParsesForIdsThatAreNotXmlNames) {
  for (const fs::path& file : inputs_of("bt_xml", "regressions")) {
    SCOPED_TRACE(file.filename().string());
    std::vector<Finding> findings;
    const auto doc = bt::parse_document(contents(file), "tree.xml", findings);
    if (!doc) continue;
    const std::string written = bt::write_document(*doc);
    std::vector<Finding> again;
    EXPECT_TRUE(bt::parse_document(written, "written.xml", again).has_value()) << written;
  }
}

// Caught by fuzz_nodes' schema check
// (regressions/nodes/schema-port-named-skipIf-declared-twice.xml, schema-port-named-xmlns.xml): a
// port named _skipIf was declared as an attribute of its node besides the common attribute group's
// _skipIf, and a port named xmlns as an attribute XML Schema forbids, so the schema did not compile
// (xmllint: "Duplicate attribute use"). A port BehaviorTree.CPP does not set from an attribute, and
// xmlns, now have no attribute of their own.
TEST(FuzzReplay, SchemaDeclaresNoAttributeForReservedPortNames) {
  std::vector<Finding> findings;
  const auto doc = bt::parse_document(
      "<root BTCPP_format=\"4\"><TreeNodesModel><Action ID=\"Drill\">"
      "<input_port name=\"_skipIf\" type=\"int\"/><input_port name=\"xmlns\"/>"
      "<input_port name=\"ID\"/><input_port name=\"mode\"/>"
      "</Action></TreeNodesModel></root>",
      "nodes.xml", findings);
  ASSERT_TRUE(doc.has_value());
  const std::string xsd = bt::write_schema(doc->node_models);
  const std::size_t at = xsd.find("  <xs:complexType name=\"node_Drill\">");
  ASSERT_NE(at, std::string::npos) << xsd;
  EXPECT_EQ(xsd.substr(at, xsd.find("</xs:complexType>", at) - at),
            "  <xs:complexType name=\"node_Drill\">\n"
            "    <xs:attribute name=\"mode\" type=\"xs:string\" use=\"required\"/>\n"
            "    <xs:attributeGroup ref=\"commonAttributeGroup\"/>\n  ");
  for (const fs::path& file : inputs_of("nodes", "regressions")) {
    SCOPED_TRACE(file.filename().string());
    std::vector<Finding> read;
    const auto models = bt::parse_document(contents(file), "nodes.xml", read);
    ASSERT_TRUE(models.has_value());
    EXPECT_EQ(fuzz::detail::SchemaCheck().check(bt::write_schema(models->node_models)), "");
  }
}

// Found by fuzz_scenario_uplink
// (regressions/scenario_uplink/uplink-path-with-newline-splits-the-error-line.json): an uplink
// package written "uplin\n/cool" put a line break into `uabt run`'s error, so its second half
// was a line that names no file. Each misfit is one line again, the name escaped.
TEST(FuzzReplay, ScenarioMisfitWithANewlineInANameStaysOneLine) {
  const fuzz::ScenarioUplinkHarness harness;
  const std::string text = "{\"events\": [{\"at\": 2, \"uplink\": \"uplin\\n/cool\"}]}\n";
  try {
    manager::BehaviorTreeManager(harness.dir(), runtime::parse_scenario(text, "scenarios/s.json"))
        .run();
    FAIL() << "the scenario was accepted";
  } catch (const runtime::ScenarioError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind("scenarios/s.json:1:33: error: uplink package 'uplin\\n/cool' is not a "
                         "directory (a path from the mission directory ",
                         0),
              0u)
        << what;
  }
}

// The harness's fixed mission with the shipped requirements passes the gate: the pipeline
// target reaches compile and conform, not only the loader's errors.
TEST(FuzzReplay, PipelineHarnessMissionPasses) {
  fuzz::PipelineHarness harness;
  std::string error;
  harness.check(contents(source_dir() / "tests/fuzz/corpus/pipeline/msl_and_exploration.txt"),
                2000);
  auto mission = load::load_mission(harness.dir(), {}, error);
  ASSERT_TRUE(mission.has_value()) << error;
  const gate::Outcome outcome = gate::run_gate(std::move(*mission), {}, "test");
  EXPECT_TRUE(outcome.passed()) << outcome.report.findings.size() << " findings";
  EXPECT_FALSE(outcome.compiled_xml.empty());
}

}  // namespace
}  // namespace uabt::testing
