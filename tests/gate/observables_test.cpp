// What a property may read (ARCHITECTURE §10, §12): a label several nodes share means any of them —
// in the mission and after an uplink merge — and a label whose last node an uplink retired is
// a property-reference error that says so, at the property.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "gate/load_support.hpp"
#include "gate/properties.hpp"
#include "style_missions.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::gate {
namespace {

using uabt::testing::load_merged;
using uabt::testing::mission_files;
using uabt::testing::TempMission;

std::vector<Finding> references(const load::Mission& m) {
  std::vector<Finding> out;
  for (Finding& f : check_mission_properties(m))
    if (f.check == "property-reference") out.push_back(std::move(f));
  return out;
}

// on_mud, with a <Drill/> of its own: after the merge the mission has two Drill nodes.
void add_drilling_mud_uplink(std::map<std::string, std::string>& files) {
  auto& alt = files["uplinks/on_mud/alternatives/navigation/on_mud.xml"];
  const std::string drive = "<MoveForward";
  ASSERT_NE(alt.find(drive), std::string::npos);
  alt.insert(alt.find(drive), "<Drill/>\n      ");
}

TEST(PropertyObservables, ANodeIdTheUplinkAlsoUsesMeansAnyOfThem) {
  auto files = mission_files("msl_curiosity");
  add_drilling_mud_uplink(files);
  const TempMission t(files, "msl_curiosity");
  const load::Mission merged = load_merged(t.dir(), {t.dir() / "uplinks/on_mud"});
  EXPECT_EQ(mission_observables(merged).variables.count("Drill.running"), 1u);
  EXPECT_TRUE(references(merged).empty()) << format_text(references(merged));
}

TEST(PropertyObservables, TwoNodesWithOneIdMeanAnyOfThem) {
  const auto files = uabt::testing::unnamed_drills();
  for (const auto& [path, text] : files)
    EXPECT_EQ(text.find("name=\"Drill\""), std::string::npos) << path;
  const TempMission t(files, "sample_drilling");
  const load::Mission m = load_merged(t.dir());
  EXPECT_TRUE(references(m).empty()) << format_text(references(m));
}

TEST(PropertyObservables, AnUplinkThatRetiresTheLastNodeSaysSo) {
  auto files = mission_files("msl_curiosity");
  files["requirements.fret"] +=
      "Backing: the rover shall never satisfy MoveBackward.running & IsDug\n";
  const TempMission t(files, "msl_curiosity");
  EXPECT_TRUE(references(load_merged(t.dir())).empty()) << "on_rocks drives backward";

  const load::Mission merged = load_merged(t.dir(), {t.dir() / "uplinks/retire_rocks"});
  const std::vector<Finding> found = references(merged);
  ASSERT_EQ(found.size(), 1u) << format_text(check_mission_properties(merged));
  EXPECT_EQ(found[0].requirements, std::vector<std::string>{"Backing"});
  EXPECT_EQ(found[0].location.file, merged.requirements_file);
  EXPECT_EQ(found[0].location.line, 23) << "the property's line";
  EXPECT_NE(found[0].message.find("removed the last node 'MoveBackward'"), std::string::npos)
      << found[0].message;
  EXPECT_NE(found[0].message.find("alternative 'on_rocks' of 'navigation'"), std::string::npos)
      << found[0].message;
  EXPECT_NE(found[0].message.find("Req2"), std::string::npos) << found[0].message;
}

// A condition only the retired alternative checks is no observable either, for the same reason.
TEST(PropertyObservables, AnUplinkThatRetiresTheLastConditionSaysSo) {
  auto files = mission_files("msl_curiosity");
  files["requirements.fret"] += "Left: the rover shall never satisfy IsRockAtLeft & IsDug\n";
  const TempMission t(files, "msl_curiosity");
  EXPECT_TRUE(references(load_merged(t.dir())).empty());
  const std::vector<Finding> found =
      references(load_merged(t.dir(), {t.dir() / "uplinks/retire_rocks"}));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].location.line, 23);
  EXPECT_NE(found[0].message.find("removed the last node 'IsRockAtLeft'"), std::string::npos)
      << found[0].message;
}

}  // namespace
}  // namespace uabt::gate
