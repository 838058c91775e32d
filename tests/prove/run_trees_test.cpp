// The nodes a run has, one rule (load::run_trees, ARCHITECTURE §12): the gate's property check
// names exactly the node labels of the engine built on the compiled tree, so a property the gate
// admits reads a node every run has, and one it refuses reads a node no run has.
#include <set>

#include "gate/properties.hpp"
#include "prove_support.hpp"
#include "runtime/engine.hpp"
#include "runtime/observed_nodes.hpp"
#include "runtime/world.hpp"
#include "sweep_mission.hpp"

namespace uabt::testing {
namespace {

// Leaves that answer failure: only the nodes the engine builds matter here.
class FailingWorld : public runtime::World {
 public:
  std::uint32_t bind_leaf(const runtime::LeafBinding&) override { return 0; }
  runtime::NodeStatus tick_leaf(const runtime::LeafContext&) override {
    return runtime::NodeStatus::failure;
  }
  void halt_leaf(const runtime::LeafContext&) override {}
};

// `<label>.running` for every label a node of the run answers to, as the gate names them.
std::set<std::string> gate_labels(const load::Mission& m) {
  std::set<std::string> out;
  const std::string suffix = ".running";
  for (const auto& [name, type] : gate::mission_observables(m).variables)
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      out.insert(name.substr(0, name.size() - suffix.size()));
  return out;
}

// The same, from the engine: every alive node outside the generated selection trees, by name
// and by ID. The compiler's call of a selection tree stands where the Adaptable was; the
// property reads that node as the mode `<adaptable>`, not as a `SubTree` label.
std::set<std::string> engine_labels(const load::Mission& m, const runtime::Engine& engine) {
  std::set<std::string> out;
  for (runtime::NodeId id = 0; id < engine.node_count(); ++id) {
    const runtime::NodeInfo& info = engine.info(id);
    if (!info.alive || runtime::generated_selection_tree(m, info.tree_id)) continue;
    const std::string* called = info.element ? info.element->attribute("ID") : nullptr;
    if (info.kind == "SubTree" && called && runtime::generated_selection_tree(m, *called)) continue;
    out.insert(info.kind);
    if (!info.name.empty()) out.insert(info.name);
  }
  return out;
}

TEST(RunTrees, TheGateNamesTheNodesOfTheEngineBuiltOnTheCompiledTree) {
  int compared = 0, sub_not_called = 0;
  for (unsigned seed = 1; seed <= 150; ++seed) {
    const SweepMission mission(seed, false, false, SweepMission::Forms::every);
    const TempMission t(mission.files);
    const Gated g(t.dir(), mission.style, false);
    if (!g.ok() || !g.outcome->passed()) continue;  // a rejected tree is never run
    FailingWorld world;
    const runtime::Engine engine = runtime::Engine::build(*g.doc, world);
    const load::Mission& m = *g.outcome->mission;
    EXPECT_EQ(gate_labels(m), engine_labels(m, engine)) << "seed " << seed;
    ++compared;
    sub_not_called += mission.files.at("mission.xml").find("<SubTree") == std::string::npos;
  }
  std::printf("run trees: %d missions compared, %d with a tree nothing calls\n", compared,
              sub_not_called);
  EXPECT_GE(compared, 100);
  EXPECT_GE(sub_not_called, 30) << "the tree nothing calls is the case this test is for";
}

// A user adds a tree to mission.xml and a guarantee on its node, but no SubTree calls it: the
// gate says the run has no such node (prove used to fail with "the trace has no variable").
TEST(RunTrees, AGuaranteeOnATreeNothingCallsIsRefusedAndOnACalledOneAdmitted) {
  auto files = mission_files("msl_curiosity");
  std::string& xml = files["mission.xml"];
  const std::string spare =
      "<BehaviorTree ID=\"Spare\"><Sequence name=\"SpareCheck\"><Drill/></Sequence>"
      "</BehaviorTree>\n";
  xml.insert(xml.rfind("</root>"), spare);
  files["requirements.fret"] += "Spare: the rover shall never satisfy SpareCheck.running\n";
  {
    const TempMission t(files, "msl_curiosity");
    std::string error;
    auto m = load::load_mission(t.dir(), {}, error);
    ASSERT_TRUE(m) << error;
    const auto found = gate::check_mission_properties(*m);
    ASSERT_EQ(found.size(), 1u) << format_text(found);
    EXPECT_EQ(found[0].check, "property-reference");
    EXPECT_NE(found[0].message.find("its only nodes 'SpareCheck' are in the tree 'Spare', which "
                                    "no tree of the run calls"),
              std::string::npos)
        << found[0].message;
  }
  // Called from the main tree, the node runs and the guarantee gets a verdict.
  const std::string root = "<Sequence name=\"root_sequence\">";
  ASSERT_NE(xml.find(root), std::string::npos);
  xml.insert(xml.find(root) + root.size(), "<SubTree ID=\"Spare\"/>");
  const TempMission t(files, "msl_curiosity");
  const Gated g(t.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result r = g.prove("explicit");
  const prove::Answer* answer = nullptr;
  for (const prove::Answer& a : r.answers)
    if (a.requirement == "Spare") answer = &a;
  ASSERT_NE(answer, nullptr);
  EXPECT_EQ(answer->verdict, prove::Verdict::violated) << answer->reason;
}

}  // namespace
}  // namespace uabt::testing
