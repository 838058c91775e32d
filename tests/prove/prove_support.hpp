#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "base/diagnostics.hpp"
#include "bt/xml_io.hpp"
#include "gate/gate.hpp"
#include "gate/proof_report.hpp"
#include "prove/world_model.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {

// Gates a mission directory and proves its guarantees on the compiled tree.
inline prove::Result prove_dir(const std::filesystem::path& dir, prove::Options options = {},
                               compile::SelectionStyle style = compile::SelectionStyle::sequence) {
  std::string error;
  auto mission = load::load_mission(dir, {}, error);
  EXPECT_TRUE(mission) << error;
  gate::Options gate_options;
  gate_options.compile.selection = style;
  gate_options.compile.selection_forced = true;
  gate::Outcome outcome = gate::check_mission(std::move(*mission), gate_options, "test");
  EXPECT_FALSE(outcome.compiled_xml.empty()) << format_text(outcome.report.findings);
  const prove::WorldModel world = prove::mission_world(*outcome.mission);
  return prove::prove(*outcome.mission, *outcome.compiled_tree, world, options);
}

// A mission gated once, to prove with either engine.
struct Gated {
  explicit Gated(const std::filesystem::path& dir,
                 compile::SelectionStyle style = compile::SelectionStyle::sequence,
                 bool forced = true) {
    std::string error;
    auto mission = load::load_mission(dir, {}, error);
    if (!mission) return;
    gate::Options options;
    options.compile.selection = style;
    options.compile.selection_forced = forced;
    outcome =
        std::make_unique<gate::Outcome>(gate::check_mission(std::move(*mission), options, "t"));
    if (outcome->compiled_xml.empty()) return;
    std::vector<Finding> findings;
    doc = bt::parse_document(outcome->compiled_xml, "compiled.xml", findings);
    world = prove::mission_world(*outcome->mission);
  }
  bool ok() const { return doc.has_value(); }
  prove::Result prove(const std::string& engine, std::uint64_t depth = 0) const {
    prove::Options o;
    o.engine = engine;
    o.depth = depth;
    return prove::prove(*outcome->mission, *doc, world, o);
  }
  std::unique_ptr<gate::Outcome> outcome;
  std::optional<bt::Document> doc;
  prove::WorldModel world;
};

inline const prove::Answer& answer(const prove::Result& r, const std::string& id) {
  for (const auto& a : r.answers)
    if (a.requirement == id) return a;
  static prove::Answer none;
  ADD_FAILURE() << "no answer for " << id;
  return none;
}

// sample_drilling's rotary alternative repaired: it cools a hot bit before it drills.
inline constexpr const char* kFixedRotary = R"(<root BTCPP_format="4" main_tree_to_execute="rotary">
  <BehaviorTree ID="rotary">
    <Sequence>
      <Fallback>
        <IsBitCool/>
        <CoolDown/>
      </Fallback>
      <Drill mode="rotary"/>
    </Sequence>
  </BehaviorTree>
</root>
)";

// sample_drilling where only a later tick can break `Cool`: the bit starts cool and the
// percussive alternative drills without cooling, so the second drilling cycle on hard rock
// drills the bit the first one heated (tick 2).
inline std::map<std::string, std::string> hot_bit_after_a_drill() {
  auto files = mission_files("sample_drilling");
  files["requirements.fret"] =
      "Hard: In drilling if HardRock Mission shall satisfy selected_alt = percussive\n"
      "Soft: In drilling Mission shall satisfy selected_alt = rotary\n"
      "Cool: Mission shall always satisfy Drill.running -> IsBitCool\n";
  files["alternatives/drilling/rotary.xml"] = kFixedRotary;
  // The percussive alternative drills without cooling: a hot bit only exists after a drill.
  files["alternatives/drilling/percussive.xml"] =
      alternative_tree("percussive", "<Drill mode=\"percussive\"/>");
  files["world.json"] =
      R"({"initial": "IsBitCool", "actions": {"Drill": {"ticks": 2, "results": ["success"],
         "on_success": "IsBitCool = false"}, "CoolDown": {"ticks": 1, "results": ["success"],
         "on_success": "IsBitCool = true"}}})";
  return files;
}

}  // namespace uabt::testing
