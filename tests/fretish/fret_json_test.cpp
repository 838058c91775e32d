// FRET exports: reference files from FRET and the replication package, ids, variables,
// assumptions and the positions of findings in the JSON text.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "base/files.hpp"
#include "fretish/parse.hpp"
#include "fretish_test_support.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::string error;
  std::optional<std::string> content = read_text_file(path, error);
  EXPECT_TRUE(content) << path << ": " << error;
  return content.value_or("");
}

TEST(FretJson, EveryReferenceRequirementParses) {
  const fs::path fret_dir = shared_dir() / "reference" / "fret";
  const fs::path replication = replication_dir() / "mission" / "fretRequirements.json";
  if (!fs::exists(fret_dir) || !fs::exists(replication)) GTEST_SKIP() << "no reference data";
  std::vector<fs::path> files = {replication};
  for (const auto& entry : fs::directory_iterator(fret_dir))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::size_t exports = 0;
  for (const fs::path& path : files) {
    const std::string content = read(path);
    // semantics.json is FRET's template table, not an export: it has no "requirements".
    if (content.find("\"fulltext\"") == std::string::npos) continue;
    ++exports;
    fretish::Domain domain;
    fretish::ParseResult result =
        fretish::parse_fret_json(content, path.filename().string(), domain);
    for (const Finding& f : result.findings)
      ADD_FAILURE() << path.filename() << ":" << f.location.line << ":" << f.location.column << ": "
                    << f.message << " [" << f.check << "]";
    EXPECT_FALSE(result.requirements.empty()) << path;
    for (const fretish::Requirement& r : result.requirements) {
      EXPECT_FALSE(r.id.empty());
      EXPECT_TRUE(r.response) << r.id;
      EXPECT_GT(r.location.line, 1) << r.id;
    }
  }
  EXPECT_EQ(exports, 3u);
}

TEST(FretJson, ReplicationPackageIdsAndLocations) {
  const fs::path path = replication_dir() / "mission" / "fretRequirements.json";
  if (!fs::exists(path)) GTEST_SKIP() << "no replication package";
  fretish::Domain domain;
  fretish::ParseResult result =
      fretish::parse_fret_json(read(path), "mission/fretRequirements.json", domain);
  ASSERT_TRUE(result.findings.empty());
  ASSERT_EQ(result.requirements.size(), 2u);
  EXPECT_EQ(result.requirements[0].id, "R1");
  EXPECT_EQ(result.requirements[1].id, "R2");
  // "fulltext": "In navigation IF OnDust ..." is on line 8 of the file.
  EXPECT_EQ(result.requirements[0].location.line, 8);
  EXPECT_EQ(result.requirements[0].location.column, 22);
  EXPECT_EQ(result.requirements[0].location.file, "mission/fretRequirements.json");
  EXPECT_EQ(result.requirements[1].response->args[1]->text, "alt2");
  EXPECT_GT(result.requirements[1].location.line, result.requirements[0].location.line);
}

TEST(FretJson, FsmVariablesBecomeTypedDomain) {
  const fs::path path = shared_dir() / "reference" / "fret" / "fsm_reqts_and_vars.json";
  if (!fs::exists(path)) GTEST_SKIP() << "no reference data";
  fretish::Domain domain;
  fretish::ParseResult result = fretish::parse_fret_json(read(path), "fsm.json", domain);
  ASSERT_TRUE(result.findings.empty());
  EXPECT_EQ(result.requirements.size(), 13u);
  const fretish::Variable* state = domain.find("state");
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->type, fretish::VarType::real);
  const fretish::Variable* standby = domain.find("standby");
  ASSERT_NE(standby, nullptr);
  EXPECT_EQ(standby->type, fretish::VarType::boolean);
  EXPECT_GT(standby->location.line, 0);
  // Listed once per component and model, declared once; untyped entries (P, R) skipped.
  int standby_count = 0;
  for (const auto& v : domain.variables) standby_count += v.name == "standby";
  EXPECT_EQ(standby_count, 1);
  EXPECT_EQ(domain.find("P"), nullptr);
  EXPECT_EQ(domain.variables.size(), 18u);
}

TEST(FretJson, SyntheticExport) {
  const std::string content = R"json({
  "requirements": [
    {"reqid": "", "fulltext": "In navigation if OnDust Mission shall satisfy selected_alt = a"},
    {"reqid": "Req-2", "fulltext": "In navigation Mission shall satisfy selected_alt = b"},
    {"reqid": "one_terrain_Assumption", "fulltext": "Mission shall always satisfy !(OnDust & OnRocks)"},
    {"reqid": "assumption-not-really", "fulltext": "Mission shall satisfy x"},
    {"reqid": "Bad", "fulltext": "Mission shall satisfy (x"},
    {"reqid": "NoText"}
  ],
  "variables": [
    {"variable_name": "OnDust", "dataType": "boolean"},
    {"variable_name": "battery", "dataType": ["integer"]},
    {"variable_name": "count", "dataType": "unsigned integer"},
    {"variable_name": "slope", "dataType": "single"},
    {"variable_name": "untyped", "dataType": ""},
    {"variable_name": "weird", "dataType": "string"},
    {"variable_name": "battery", "dataType": "boolean"}
  ]
})json";
  fretish::Domain domain;
  fretish::ParseResult result = fretish::parse_fret_json(content, "reqs.json", domain);
  ASSERT_EQ(result.requirements.size(), 3u);
  EXPECT_EQ(result.requirements[0].id, "R1");
  EXPECT_EQ(result.requirements[1].id, "Req-2");
  EXPECT_EQ(result.requirements[2].id, "assumption-not-really");
  ASSERT_EQ(domain.assumptions.size(), 1u);
  EXPECT_EQ(domain.assumptions[0].name, "one_terrain_Assumption");
  EXPECT_EQ(fretish::to_fretish(*domain.assumptions[0].expr), "!(OnDust & OnRocks)");
  EXPECT_EQ(domain.assumptions[0].location.line, 5);

  ASSERT_NE(domain.find("battery"), nullptr);
  EXPECT_EQ(domain.find("battery")->type, fretish::VarType::integer);
  EXPECT_EQ(domain.find("count")->type, fretish::VarType::integer);
  EXPECT_EQ(domain.find("count")->lower, "0");
  EXPECT_EQ(domain.find("slope")->type, fretish::VarType::real);
  EXPECT_EQ(domain.find("untyped"), nullptr);
  EXPECT_EQ(domain.find("weird"), nullptr);

  const auto syntax = findings_of(result.findings, "fretish-syntax");
  ASSERT_EQ(syntax.size(), 2u);
  // The '(' error: line 7, inside the fulltext string that starts at column 35.
  EXPECT_EQ(syntax[0].location.line, 7);
  EXPECT_EQ(syntax[0].location.column, 35 + 24);
  EXPECT_NE(syntax[1].message.find("'NoText'"), std::string::npos);
  EXPECT_EQ(syntax[1].location.line, 8);
  const auto invalid = findings_of(result.findings, "domain-invalid");
  ASSERT_EQ(invalid.size(), 2u);
  EXPECT_NE(invalid[0].message.find("'weird'"), std::string::npos);
  EXPECT_EQ(invalid[0].location.line, 16);
  EXPECT_NE(invalid[1].message.find("'battery'"), std::string::npos);
}

TEST(FretJson, BareArrayAndBadDocuments) {
  fretish::Domain domain;
  fretish::ParseResult bare = fretish::parse_fret_json(
      "[{\"reqid\": \"A\", \"fulltext\": \"Mission shall satisfy x\"}]", "a.json", domain);
  ASSERT_EQ(bare.requirements.size(), 1u);
  EXPECT_EQ(bare.requirements[0].id, "A");
  EXPECT_EQ(bare.requirements[0].location.column, 30);

  fretish::ParseResult broken = fretish::parse_fret_json("[\n{\"reqid\": }", "b.json", domain);
  ASSERT_EQ(broken.findings.size(), 1u);
  EXPECT_EQ(broken.findings[0].check, "fretish-syntax");
  EXPECT_EQ(broken.findings[0].location.line, 2);

  fretish::ParseResult other = fretish::parse_fret_json("{\"a\": 1}", "c.json", domain);
  ASSERT_EQ(other.findings.size(), 1u);
  EXPECT_NE(other.findings[0].message.find("not a FRET export"), std::string::npos);
}

}  // namespace
}  // namespace uabt::testing
