// The gate's realizability step (src/gate/realizability.cpp): requirements no tree can meet fail
// the gate with their minimal conflict, an uplink's requirement named first; requirements the
// mission's own tree is proved to meet in world.json's world only get a note.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "gate/load_support.hpp"
#include "gate/uplink.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::gate {
namespace {

using uabt::testing::mission_with;
using uabt::testing::TempMission;

std::vector<const Finding*> of_check(const Outcome& o, const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : o.report.findings)
    if (f.check == check) out.push_back(&f);
  return out;
}

bool ran(const Outcome& o, const std::string& stage) {
  for (const auto& s : o.report.stages)
    if (s == stage) return true;
  return false;
}

Outcome gate_on(const TempMission& t) {
  std::string error;
  auto m = load::load_mission(t.dir(), {}, error);
  EXPECT_TRUE(m.has_value()) << error;
  return run_gate(std::move(*m), {}, "test");
}

// An uplink whose guarantee conflicts with one of the mission's: drilling on rocks at once,
// while the rover never drills away from the target (and the environment decides both the
// terrain and whether the rover is there).
TEST(RealizabilityGate, AnUplinkMakingTheRequirementsImpossibleIsRejectedNamingItFirst) {
  const std::filesystem::path curiosity = uabt::testing::mission_dir("msl_curiosity");
  TempMission package(std::map<std::string, std::string>{
      {"requirements.fret",
       "DrillOnRocks: upon OnRocks the rover shall immediately satisfy Drill.running\n"}});
  const Outcome o =
      run_uplink_gate(uabt::testing::load_merged(curiosity),
                      uabt::testing::load_merged(curiosity, {package.dir()}), {}, "test");
  EXPECT_FALSE(o.passed());
  EXPECT_TRUE(ran(o, "realize"));
  const auto conflicts = of_check(o, "requirements-unrealizable");
  ASSERT_EQ(conflicts.size(), 1u) << format_text(o.report.findings);
  EXPECT_EQ(conflicts[0]->severity, Severity::error);
  // In file order NoDrillAway comes first; the uplink's requirement is named first.
  EXPECT_EQ(conflicts[0]->requirements, (std::vector<std::string>{"DrillOnRocks", "NoDrillAway"}));
  EXPECT_NE(conflicts[0]->message.find("no behavior tree meets DrillOnRocks and NoDrillAway"),
            std::string::npos)
      << conflicts[0]->message;
  // The inputs that defeat every tree: rocks while the rover is not at the target.
  ASSERT_FALSE(conflicts[0]->notes.empty());
  EXPECT_NE(conflicts[0]->notes[0].find("OnRocks = true"), std::string::npos)
      << conflicts[0]->notes[0];
  EXPECT_NE(conflicts[0]->notes[0].find("IsInLocation = false"), std::string::npos)
      << conflicts[0]->notes[0];
}

TEST(RealizabilityGate, TheMissionsOwnRequirementsAreRealizable) {
  const std::filesystem::path curiosity = uabt::testing::mission_dir("msl_curiosity");
  std::string error;
  auto m = load::load_mission(curiosity, {}, error);
  ASSERT_TRUE(m) << error;
  const Outcome o = run_gate(std::move(*m), {}, "test");
  EXPECT_TRUE(o.passed()) << format_text(o.report.findings);
  EXPECT_TRUE(ran(o, "realize"));
  EXPECT_TRUE(of_check(o, "requirements-unrealizable").empty());
  EXPECT_TRUE(of_check(o, "realizability-undecided").empty());
}

// `Calm` is no tree's to decide, so no tree meets "always Calm" against every environment; but
// world.json starts it true and no action changes it, so the mission's tree is proved to meet it
// there: a note that the requirement relies on the world, not a rejection. Without that initial
// state the proof fails and the conflict is an error.
TEST(RealizabilityGate, ARequirementTheTreeMeetsOnlyThroughTheWorldIsANote) {
  const auto gate_with = [](const std::string& world) {
    const TempMission t({{"mission.xml", mission_with("    <Sequence>\n      <Stow/>\n"
                                                      "    </Sequence>")},
                         {"domain.fret", "boolean Calm\n"},
                         {"requirements.fret", "StaysCalm: the rover shall always satisfy Calm\n"},
                         {"world.json", world}});
    return gate_on(t);
  };
  const Outcome calm = gate_with("{\"initial\": \"Calm\", \"actions\": {\"Stow\": {}}}");
  EXPECT_TRUE(calm.passed()) << format_text(calm.report.findings);
  auto found = of_check(calm, "requirements-unrealizable");
  ASSERT_EQ(found.size(), 1u) << format_text(calm.report.findings);
  EXPECT_EQ(found[0]->severity, Severity::note);
  EXPECT_EQ(found[0]->requirements, (std::vector<std::string>{"StaysCalm"}));
  ASSERT_EQ(found[0]->notes.size(), 2u);
  EXPECT_NE(found[0]->notes[1].find("the mission's tree meets them in the world"),
            std::string::npos)
      << found[0]->notes[1];

  const Outcome any = gate_with("{\"actions\": {\"Stow\": {}}}");
  EXPECT_FALSE(any.passed());
  EXPECT_EQ(of_check(any, "prove-violated").size(), 1u) << format_text(any.report.findings);
  found = of_check(any, "requirements-unrealizable");
  ASSERT_EQ(found.size(), 1u) << format_text(any.report.findings);
  EXPECT_EQ(found[0]->severity, Severity::error);
}

// The gate admits a tree on its proofs: a guarantee whose realizability is not decided (not a
// safety requirement) is a note there, while `uabt realizable` fails closed on it.
TEST(RealizabilityGate, AnUndecidedComponentIsANoteInTheGate) {
  const TempMission t(
      {{"mission.xml", mission_with("    <Sequence>\n      <Stow/>\n"
                                    "    </Sequence>")},
       {"domain.fret", "boolean Go\n"},
       {"requirements.fret", "Stowed: upon Go the rover shall eventually satisfy Stow.success\n"},
       {"world.json", "{\"actions\": {\"Stow\": {\"results\": [\"success\"]}}}"}});
  const Outcome o = gate_on(t);
  const auto found = of_check(o, "realizability-undecided");
  ASSERT_EQ(found.size(), 1u) << format_text(o.report.findings);
  EXPECT_EQ(found[0]->severity, Severity::note);
  EXPECT_TRUE(of_check(o, "requirements-unrealizable").empty());
}

}  // namespace
}  // namespace uabt::gate
