// A tree script that divides by zero used to pass: it is checked as a guard's division is.
#include <gtest/gtest.h>

#include <string>

#include "hardening_support.hpp"

namespace uabt::testing {
namespace {

// The good mission whose on_dust alternative checks `code` before it moves.
GateRun gate_with_script(const std::string& code) {
  auto files = good_mission_files();
  files["domain.fret"] =
      "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n"
      "integer wind in [0, 15]\ninteger battery in [0, 100]\n";
  files["alternatives/navigation/on_dust.xml"] =
      alternative_tree("on_dust", "<Sequence>\n      <ScriptCondition code=\"" + code +
                                      "\"/>\n      <MoveForward/>\n    </Sequence>");
  TempMission m(files);
  return run_real_gate(m.dir());
}

std::string findings_of(const GateRun& run, const std::string& check) {
  std::string out;
  if (run.outcome)
    for (const Finding& f : run.findings())
      if (f.check == check) out += format_text({f});
  return out;
}

// The division is named as read: wind is an integer, and BT.CPP divides it as a double.
TEST(ScriptDivision, ALiteralZeroDivisorIsAnError) {
  const GateRun run = gate_with_script("wind / 0 &gt; 1");
  ASSERT_TRUE(run.outcome) << run.load_error;
  EXPECT_FALSE(run.passed()) << run.text();
  const Finding* f = run.error_in("alternatives/navigation/on_dust.xml", "arith-division-by-zero");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->message,
            "'wind / 0.0' in the script `wind / 0 > 1` of ScriptCondition divides by zero: "
            "BehaviorTree.CPP's script then gives infinity or fails");
  EXPECT_EQ(f->location.line, 4);
  EXPECT_EQ(f->location.column, 7);
}

// A negated zero is a zero written out too: one finding, named after the division as written.
TEST(ScriptDivision, ANegatedLiteralZeroDivisorIsOneError) {
  const GateRun run = gate_with_script("wind / -0.0 &gt; 1");
  ASSERT_TRUE(run.outcome) << run.load_error;
  EXPECT_FALSE(run.passed()) << run.text();
  EXPECT_EQ(findings_of(run, "guard-division-by-zero"), "") << run.text();
  const Finding* f = run.error_in("alternatives/navigation/on_dust.xml", "arith-division-by-zero");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->message,
            "'wind / -0.0' in the script `wind / -0.0 > 1` of ScriptCondition divides by zero: "
            "BehaviorTree.CPP's script then gives infinity or fails");
}

TEST(ScriptDivision, ADivisorZeroInEveryStateIsAnError) {
  const GateRun run = gate_with_script("wind / (battery - battery) &gt; 1");
  ASSERT_TRUE(run.outcome) << run.load_error;
  EXPECT_FALSE(run.passed()) << run.text();
  const Finding* f = run.error_in("alternatives/navigation/on_dust.xml", "guard-division-by-zero");
  ASSERT_NE(f, nullptr) << run.text();
  EXPECT_EQ(f->message.substr(0, f->message.rfind(" (")),
            "'wind * 1.0 / (battery - battery)' in the script `wind / (battery - battery) > 1` of "
            "ScriptCondition divides by zero when battery - battery = 0, which the domain allows");
  EXPECT_NE(f->message.find("BehaviorTree.CPP's script then gives infinity or fails"),
            std::string::npos)
      << f->message;
  EXPECT_FALSE(f->witness.empty());
}

TEST(ScriptDivision, ADivisorTheDomainAllowsToBeZeroIsAnError) {
  const GateRun run = gate_with_script("wind / battery &gt; 1");
  EXPECT_FALSE(run.passed()) << run.text();
  EXPECT_NE(findings_of(run, "guard-division-by-zero").find("battery=0"), std::string::npos)
      << run.text();
}

TEST(ScriptDivision, AnAssignedValueIsCheckedToo) {
  const GateRun run = gate_with_script("gust := wind / (battery - battery)");
  EXPECT_FALSE(run.passed()) << run.text();
  EXPECT_NE(run.error_in("alternatives/navigation/on_dust.xml", "guard-division-by-zero"), nullptr)
      << run.text();
}

TEST(ScriptDivision, ADivisorThatCannotBeZeroWhereItIsUsedPasses) {
  for (const std::string code :
       {"wind / 4 &gt; 1", "battery &gt; 0 &amp;&amp; wind / battery &gt; 1"}) {
    const GateRun run = gate_with_script(code);
    EXPECT_EQ(findings_of(run, "guard-division-by-zero"), "") << code;
    EXPECT_EQ(findings_of(run, "arith-division-by-zero"), "") << code;
  }
  const GateRun run = gate_with_script("battery &gt; 0 &amp;&amp; wind / battery &gt; 1");
  EXPECT_TRUE(run.passed()) << run.text();
}

}  // namespace
}  // namespace uabt::testing
