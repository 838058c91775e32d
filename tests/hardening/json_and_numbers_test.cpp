// Issue 25, point 1: hostile JSON nesting, numbers that fit no type and domains too large to
// count are refused with a place in the file and uabt's own words, in every input format. The
// huge inputs are generated here; before the fix they crashed (stack overflow), ran out of
// memory or hung, which ctest's timeout catches.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "base/json_input.hpp"
#include "base/number_fit.hpp"
#include "fretish/parse.hpp"
#include "hardening_support.hpp"
#include "load/uplink.hpp"
#include "monitor/trace.hpp"
#include "prove/world_model.hpp"
#include "runtime/scenario.hpp"

namespace uabt::testing {
namespace {

std::string nested_arrays(int depth) {
  return std::string(static_cast<std::size_t>(depth), '[') +
         std::string(static_cast<std::size_t>(depth), ']');
}

// No library exception text may reach the user.
void expect_own_words(const std::string& message) {
  EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

// --- the shared reader -------------------------------------------------------------------------

TEST(JsonInput, NestingUpToTheLimitParses) {
  JsonInputError error;
  EXPECT_TRUE(parse_json_input(nested_arrays(kMaxJsonDepth), error)) << error.message;
}

TEST(JsonInput, NestingBeyondTheLimitIsRefusedAtTheBracket) {
  for (const int depth : {kMaxJsonDepth + 1, 100000}) {
    SCOPED_TRACE(depth);
    JsonInputError error;
    EXPECT_FALSE(parse_json_input("{\"a\":\n  " + nested_arrays(depth) + "}", error));
    EXPECT_EQ(error.line, 2);
    // The object on line 1 is the first level: the 64th bracket on line 2 is one too many.
    EXPECT_EQ(error.column, 2 + kMaxJsonDepth);
    EXPECT_NE(error.message.find("nested deeper than " + std::to_string(kMaxJsonDepth)),
              std::string::npos)
        << error.message;
  }
}

TEST(JsonInput, BracketsInsideStringsDoNotCount) {
  JsonInputError error;
  const std::string text = "{\"s\": \"" + std::string(1000, '[') + "\\\"" + "\"}";
  EXPECT_TRUE(parse_json_input(text, error)) << error.message;
}

TEST(JsonInput, NumbersThatFitNoTypeAreRefusedAtTheNumber) {
  struct Case {
    std::string text;
    int column;
    std::string says;
  };
  for (const Case& c : {Case{"{\"x\": 1e400}", 7, "1e400 does not fit in a 64-bit real"},
                        Case{"[1, -2.5E+999]", 5, "-2.5E+999 does not fit"},
                        Case{"{\"x\": 100000000000000000000000000}", 7, "does not fit in 64 bits"},
                        Case{"[-9223372036854775809]", 2, "does not fit in 64 bits"}}) {
    SCOPED_TRACE(c.text);
    JsonInputError error;
    EXPECT_FALSE(parse_json_input(c.text, error));
    EXPECT_EQ(error.line, 1);
    EXPECT_EQ(error.column, c.column);
    EXPECT_NE(error.message.find(c.says), std::string::npos) << error.message;
    expect_own_words(error.message);
  }
}

TEST(JsonInput, NumbersThatFitAreRead) {
  JsonInputError error;
  const auto j =
      parse_json_input("[-9223372036854775808, 9223372036854775807, 1e-400, 1.5e308]", error);
  ASSERT_TRUE(j) << error.message;
  EXPECT_EQ((*j)[0].get<std::int64_t>(), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ((*j)[2].get<double>(), 0.0);
}

TEST(JsonInput, SyntaxErrorsAreInUabtsWords) {
  JsonInputError error;
  EXPECT_FALSE(parse_json_input("{\n  \"a\": [1, 2\n", error));
  EXPECT_EQ(error.line, 3);
  EXPECT_EQ(error.message.rfind("invalid JSON in array: ", 0), 0u) << error.message;
  expect_own_words(error.message);
}

TEST(JsonInput, AKeyWrittenTwiceInOneObjectIsRefusedAtTheSecond) {
  JsonInputError error;
  EXPECT_FALSE(parse_json_input("{\"ticks\": 1,\n \"x\": {\"ticks\": 2},\n \"ticks\" : 3}", error));
  EXPECT_EQ(error.line, 3);
  EXPECT_EQ(error.column, 2);
  EXPECT_NE(error.message.find("key \"ticks\" appears twice in one object (first at 1:2)"),
            std::string::npos)
      << error.message;
}

TEST(JsonInput, EqualKeysInDifferentObjectsAndEqualValuesAreFine) {
  JsonInputError error;
  EXPECT_TRUE(parse_json_input(
      "[{\"a\": \"a\", \"b\": {\"a\": 1}}, {\"a\": \"a\"}, \"a\", {\"s\": \"\\\"a\\\": 1\"}]",
      error))
      << error.message;
}

// --- every JSON input --------------------------------------------------------------------------

// What `parse` throws as `Error`, or "accepted".
template <class Error, class Parse>
std::string thrown(Parse parse) {
  try {
    parse();
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

// Each format with `value` placed where a value belongs; returns the error text.
std::string scenario_error(const std::string& value) {
  return thrown<runtime::ScenarioError>([&] {
    runtime::parse_scenario("{\"initial\": {\"OnDust\": " + value + "}}", "scenarios/s.json");
  });
}

std::string world_error(const std::string& value) {
  return thrown<prove::WorldError>([&] {
    prove::parse_world("{\"actions\": {\"Drill\": {\"ticks\": " + value + "}}}", "world.json");
  });
}

std::string fret_export_error(const std::string& value) {
  fretish::Domain domain;
  const auto result =
      fretish::parse_fret_json("{\"requirements\": [{\"reqid\": \"R\", \"x\": " + value + "}]}",
                               "requirements.json", domain);
  return result.findings.empty() ? "accepted" : format_text(result.findings);
}

std::string trace_error(const std::string& value) {
  std::vector<Finding> findings;
  const auto trace = monitor::read_trace("{\"tick\": 0, \"state\": {\"x\": " + value + "}}\n",
                                         "t.jsonl", findings);
  return trace ? "accepted" : format_text(findings);
}

std::string uplink_error(const std::string& value) {
  TempMission m({{"uplink.json", "{\"remove\": " + value + "}"}});
  std::vector<Finding> findings;
  load::read_uplink_plan(m.dir() / "uplink.json", "uplinks/u/uplink.json", findings);
  return findings.empty() ? "accepted" : format_text(findings);
}

struct Format {
  const char* name;
  std::string (*error_for)(const std::string& value);
  std::string where;  // how an error at the value begins: file:line:col: error:
};

TEST(JsonInputs, EveryFormatRefusesDeepNestingAndHugeNumbersWithAPlace) {
  const Format formats[] = {
      {"scenario", scenario_error, "scenarios/s.json:1:24: error: "},
      {"world.json", world_error, "world.json:1:33: error: "},
      {"FRET export", fret_export_error, "requirements.json:1:39: error: "},
      {"trace", trace_error, "t.jsonl:1:28: error: "},
      {"uplink.json", uplink_error, "uplinks/u/uplink.json:1:12: error: "},
  };
  for (const Format& f : formats) {
    SCOPED_TRACE(f.name);
    const std::string deep = f.error_for(nested_arrays(100000));
    EXPECT_NE(deep.find("nested deeper than"), std::string::npos) << deep;
    const std::string huge = f.error_for("1e400");
    EXPECT_EQ(huge.rfind(f.where, 0), 0u) << huge;
    EXPECT_NE(huge.find("1e400 does not fit"), std::string::npos) << huge;
    expect_own_words(huge);
    const std::string broken = f.error_for("[1,");
    EXPECT_NE(broken.find("invalid JSON"), std::string::npos) << broken;
    expect_own_words(broken);
  }
}

TEST(JsonInputs, EveryFormatRefusesAKeyWrittenTwice) {
  const Format formats[] = {
      {"scenario", scenario_error, "scenarios/s.json:1:"},
      {"world.json", world_error, "world.json:1:"},
      {"FRET export", fret_export_error, "requirements.json:1:"},
      {"trace", trace_error, "t.jsonl:1:"},
      {"uplink.json", uplink_error, "uplinks/u/uplink.json:1:"},
  };
  for (const Format& f : formats) {
    SCOPED_TRACE(f.name);
    const std::string twice = f.error_for("{\"k\": 1, \"k\": 2}");
    EXPECT_EQ(twice.rfind(f.where, 0), 0u) << twice;
    EXPECT_NE(twice.find("key \"k\" appears twice"), std::string::npos) << twice;
  }
}

TEST(JsonInputs, RunRefusesADeepScenarioUnderInitial) {
  auto files = good_mission_files();
  files["scenarios/deep.json"] =
      "{\"max_ticks\": 3,\n \"initial\": {\"OnDust\": " + nested_arrays(100000) + "}}";
  TempMission m(files);
  const CliRun run =
      run_cli({"run", m.dir().string(), "--scenario", (m.dir() / "scenarios/deep.json").string()});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("deep.json:2:"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("nested deeper than"), std::string::npos) << run.output;
}

// --- numbers in FRETISH files ------------------------------------------------------------------

TEST(Numbers, DomainBoundsThatDoNotFitAreRefusedAtTheBound) {
  struct Case {
    std::string declaration;
    int column;
  };
  for (const Case& c : {Case{"integer wind in [0, 100000000000000000000000000]", 21},
                        Case{"integer wind in [-9223372036854775809, 0]", 18},
                        Case{"real wind in [0, 1e400]", 18}}) {
    SCOPED_TRACE(c.declaration);
    std::vector<Finding> findings;
    fretish::parse_domain_file("# wind\n" + c.declaration + "\n", "domain.fret", findings);
    ASSERT_FALSE(findings.empty());
    EXPECT_EQ(findings[0].check, "domain-invalid");
    EXPECT_EQ(findings[0].location.line, 2);
    EXPECT_EQ(findings[0].location.column, c.column);
    EXPECT_NE(findings[0].message.find("does not fit"), std::string::npos) << findings[0].message;
  }
}

TEST(Numbers, TheWholeInt64RangeIsAValidDomain) {
  std::vector<Finding> findings;
  fretish::parse_domain_file("integer wind in [-9223372036854775808, 9223372036854775807]\n",
                             "domain.fret", findings);
  EXPECT_TRUE(findings.empty()) << format_text(findings);
}

TEST(Numbers, AGuardNumberThatDoesNotFitIsRefusedAtTheNumber) {
  const GateRun run = gate_with(
      "requirements.fret",
      "Req1: In navigation if OnDust & wind < 1e400 Mission shall satisfy selected_alt = on_dust\n"
      "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n");
  const Finding* f = run.first("fretish-syntax");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->location.file, "requirements.fret");
  EXPECT_EQ(f->location.line, 1);
  EXPECT_EQ(f->location.column, 40);
  EXPECT_NE(f->message.find("1e400 does not fit"), std::string::npos) << f->message;
  EXPECT_FALSE(run.passed());
}

TEST(Numbers, DurationsAndTickPeriodsThatDoNotFitAreRefusedAtTheNumber) {
  const auto requirements = fretish::parse_requirements_file(
      "P: the rover shall within 1e400 ticks satisfy OnDust\n", "requirements.fret");
  ASSERT_FALSE(requirements.findings.empty());
  EXPECT_EQ(requirements.findings[0].check, "fretish-syntax");
  EXPECT_EQ(requirements.findings[0].location.column, 27);
  EXPECT_NE(requirements.findings[0].message.find("1e400 does not fit"), std::string::npos)
      << requirements.findings[0].message;

  std::vector<Finding> findings;
  fretish::parse_domain_file("tick 1e400 ms\n", "domain.fret", findings);
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings[0].location.column, 6);
  EXPECT_NE(findings[0].message.find("1e400 does not fit"), std::string::npos)
      << findings[0].message;
}

// --- domains too large to count ----------------------------------------------------------------

std::string domain_with_enum(std::size_t literals) {
  std::string out =
      "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n"
      "enum terrain in {";
  for (std::size_t i = 0; i < literals; ++i) out += (i ? ", t" : "t") + std::to_string(i);
  return out + "}\n";
}

TEST(DomainSize, AnEnumBeyondTheLimitIsRefusedAtItsDeclaration) {
  std::vector<Finding> findings;
  fretish::parse_domain_file(domain_with_enum(100000), "domain.fret", findings);
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings[0].check, "domain-invalid");
  EXPECT_EQ(findings[0].location.line, 3);
  EXPECT_EQ(findings[0].location.column, 6);
  EXPECT_NE(findings[0].message.find("at most " + std::to_string(fretish::kMaxEnumValues)),
            std::string::npos)
      << findings[0].message;
}

TEST(DomainSize, AnEnumAtTheLimitIsVerified) {
  const GateRun run = gate_with("domain.fret", domain_with_enum(fretish::kMaxEnumValues));
  EXPECT_EQ(run.error_in("domain.fret"), nullptr) << run.text();
}

// The uplink impact report counts states over every declared integer: the whole int64 range
// overflowed its size check and was enumerated (std::bad_alloc after 14 GB).
TEST(DomainSize, AnUplinkOverTheWholeInt64RangeIsGated) {
  auto files = good_mission_files();
  files["domain.fret"] +=
      "integer wind in [-9223372036854775808, 9223372036854775807]\n"
      "assume calm_enough: wind > -100\n";
  files["uplinks/windy/requirements.fret"] =
      "Windy: In navigation if wind >= 8 Mission shall satisfy selected_alt = on_dust\n";
  files["uplinks/windy/uplink.json"] = "{\"place\": {\"Windy\": {\"before\": \"Req1\"}}}\n";
  TempMission m(files);
  const CliRun run =
      run_cli({"gate", m.dir().string(), "--uplink", (m.dir() / "uplinks/windy").string(), "--out",
               (m.dir() / "report").string()});
  EXPECT_LE(run.exit_code, 1) << run.output;
  EXPECT_EQ(run.output.find("bad_alloc"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("m: "), std::string::npos) << run.output;  // the verdict line
}

}  // namespace
}  // namespace uabt::testing
