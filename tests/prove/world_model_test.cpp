// world.json: contracts, the initial condition, and errors that point into the file.
#include <gtest/gtest.h>

#include "prove/world_model.hpp"

namespace uabt::testing {
namespace {

using prove::parse_world;
using prove::WorldError;

TEST(WorldModel, ReadsContracts) {
  const auto w = parse_world(R"({"initial": "!IsDug & battery >= 50",
  "actions": {"Drill": {"ticks": [5, 30], "results": ["success", "failure"], "on_success": "IsDug = true"},
              "Inc": {"ticks": 1, "results": ["success"], "on_success": "vv = vv < 8 ? vv + 1 : vv"}}})",
                             "world.json");
  ASSERT_TRUE(w.initial);
  ASSERT_EQ(w.actions.size(), 2u);
  const auto& drill = w.actions.at("Drill");
  EXPECT_EQ(drill.min_ticks, 5);
  EXPECT_EQ(drill.max_ticks, 30);
  EXPECT_EQ(drill.results.size(), 2u);
  EXPECT_EQ(drill.on_success, "IsDug = true");
  EXPECT_EQ(drill.location.line, 2);
  const auto& inc = w.actions.at("Inc");
  EXPECT_EQ(inc.min_ticks, 1);
  EXPECT_EQ(inc.max_ticks, 1);
  EXPECT_EQ(inc.results, std::vector<runtime::NodeStatus>{runtime::NodeStatus::success});
  EXPECT_EQ(w.find("Drill(mode=rotary)", "Drill"), &drill);
  EXPECT_EQ(w.find("Other", "Other"), nullptr);
}

TEST(WorldModel, ErrorsNameFileLineAndColumn) {
  struct Case {
    std::string text, message;
    int line, column;
  };
  const std::vector<Case> cases = {
      {"{\"actions\": {\"Drill\": {\"ticks\": [3, 1]}}}", "min is above max", 1, 24},
      {"{\"actions\": {\"Drill\": {\"ticks\": 0}}}", "ticks must be a whole number", 1, 24},
      {"{\"actions\": {\"Drill\": {\"results\": [\"maybe\"]}}}", "not \"maybe\"", 1, 24},
      {"{\"actions\": {\n  \"Drill\": {\"on_success\": \"IsDug = = true\"}}}",
       "on_success of 'Drill'", 2, 13},
      {"{\"actions\": {\"Drill\": {\"speed\": 1}}}", "unknown key 'speed'", 1, 24},
      {"{\"initial\": 3}", "initial must be a FRETISH expression", 1, 2},
      {"{\"initial\": \"a & & b\"}", "initial:", 1, 18},
      {"{\"start\": \"a\"}", "unknown key 'start'", 1, 2},
      {"{\"actions\": [1, 2]}", "actions must be an object", 1, 2},
      {"{\n\"actions\": {,}}", "invalid JSON", 2, 13},
  };
  for (const Case& c : cases) {
    try {
      parse_world(c.text, "world.json");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const WorldError& e) {
      EXPECT_NE(e.text.find(c.message), std::string::npos) << c.text << " → " << e.what();
      EXPECT_EQ(e.location.file, "world.json");
      EXPECT_EQ(e.location.line, c.line) << c.text << " → " << e.what();
      EXPECT_EQ(e.location.column, c.column) << c.text << " → " << e.what();
    }
  }
}

TEST(WorldModel, AssignedNames) {
  EXPECT_EQ(prove::assigned_names("IsDug = true"), std::vector<std::string>{"IsDug"});
  EXPECT_EQ(prove::assigned_names("a := 1; b += a; c == 2; @d = b"),
            (std::vector<std::string>{"a", "b", "d"}));
  EXPECT_TRUE(prove::assigned_names("x == 1").empty());
  // Read by the script parser, not by scanning text: an assignment on the right of another
  // writes too, and a string holding `;` and `=` writes nothing.
  EXPECT_EQ(prove::assigned_names("a := b := 3"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(prove::assigned_names("note = 'x = 1; y = 2'"), std::vector<std::string>{"note"});
}

}  // namespace
}  // namespace uabt::testing
