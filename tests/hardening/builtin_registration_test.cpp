// A nodes.xml that registers one of BehaviorTree.CPP 4.x's built-ins again used to pass: the
// factory refuses a second registration on board.
#include <gtest/gtest.h>

#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

const std::string kRegistered =
    "<root BTCPP_format=\"4\">\n"
    "<TreeNodesModel>\n"
    "  <Condition ID=\"OnDust\"/>\n"
    "  <Condition ID=\"OnRocks\"/>\n"
    "  <Action ID=\"MoveForward\"/>\n"
    "  <Action ID=\"MoveBackward\"/>\n"
    "  <Action ID=\"Stop\"/>\n";

GateRun gate_with_nodes(const std::string& extra) {
  auto files = good_mission_files();
  files["nodes.xml"] = kRegistered + extra + "</TreeNodesModel>\n</root>\n";
  TempMission m(files);
  return run_real_gate(m.dir());
}

TEST(BuiltinRegistration, ABuiltInRegisteredAgainIsAnError) {
  const GateRun run = gate_with_nodes("  <Control ID=\"Sequence\"/>\n");
  ASSERT_TRUE(run.outcome) << run.load_error;
  EXPECT_FALSE(run.passed()) << run.text();
  const Finding* f = run.error_in("nodes.xml", "ref-duplicate-id");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->message,
            "node ID 'Sequence' is built into BehaviorTree.CPP 4.x, and nodes.xml registers it "
            "again");
  EXPECT_EQ(f->location.line, 8);
  EXPECT_EQ(f->location.column, 3);
}

TEST(BuiltinRegistration, EveryFamilyOfBuiltInIsCaught) {
  for (const std::string entry :
       {"<Decorator ID=\"Inverter\"/>", "<Action ID=\"AlwaysSuccess\"/>",
        "<Condition ID=\"ScriptCondition\"/>", "<Control ID=\"ManualSelector\"/>"}) {
    const GateRun run = gate_with_nodes("  " + entry + "\n");
    EXPECT_NE(run.error_in("nodes.xml", "ref-duplicate-id"), nullptr) << entry << run.text();
  }
}

TEST(BuiltinRegistration, TheRobotsOwnNodesAndV3NamesAreNotBuiltIns) {
  for (const std::string entry :
       {"<Control ID=\"SequenceStar\"/>", "<Decorator ID=\"BlackboardCheckInt\"/>",
        "<Control ID=\"Vote\"/>", ""}) {
    const GateRun run = gate_with_nodes(entry.empty() ? "" : "  " + entry + "\n");
    EXPECT_EQ(run.first("ref-duplicate-id"), nullptr) << entry << run.text();
    EXPECT_TRUE(run.passed()) << entry << run.text();
  }
}

}  // namespace
}  // namespace uabt::testing
