// Every reference uabt takes on a Z3 term it gives back. A term nobody releases keeps all the
// terms under it alive until its context is deleted, and deleting a context with leaked terms
// is slow: before smt/assign.hpp the symbolic engine left about 4,900 references a run on
// msl_curiosity and spent 0.45 s deleting its context.
//
// This executable counts the references uabt's code takes and releases: it defines Z3_inc_ref
// and Z3_dec_ref, which the linker binds the project's calls (the z3++ header is inline code
// compiled into it) to before libz3's, and forwards each call to libz3. Z3's own references
// inside libz3 are not counted.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <z3++.h>
#include <z3.h>

#include <atomic>

#include "campaign/campaign.hpp"
#include "gate/gate.hpp"
#include "smt/assign.hpp"
#include "test_support.hpp"

namespace {

std::atomic<long> taken{0}, released{0};

template <typename F>
F next_definition(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (f == nullptr) std::abort();  // no libz3 behind this executable: nothing can be counted
  return reinterpret_cast<F>(f);
}

}  // namespace

extern "C" void Z3_inc_ref(Z3_context c, Z3_ast a) {
  static const auto libz3 = next_definition<void (*)(Z3_context, Z3_ast)>("Z3_inc_ref");
  ++taken;
  libz3(c, a);
}

extern "C" void Z3_dec_ref(Z3_context c, Z3_ast a) {
  static const auto libz3 = next_definition<void (*)(Z3_context, Z3_ast)>("Z3_dec_ref");
  ++released;
  libz3(c, a);
}

namespace uabt {
namespace {

// References taken and not released while `f` ran, and how many were taken.
struct Balance {
  long taken = 0, unreleased = 0;
};
template <typename F>
Balance balance_of(F&& f) {
  const long t0 = taken, r0 = released;
  f();
  return {taken - t0, (taken - t0) - (released - r0)};
}

load::Mission load_mission(const std::string& name) {
  std::string error;
  auto m = load::load_mission(uabt::testing::mission_dir(name), {}, error);
  EXPECT_TRUE(m) << error;
  return std::move(*m);
}

// smt::assign releases the term it replaces, whatever z3++'s move assignment does; the
// references counted show that the counting itself works.
TEST(Z3References, AnExpressionAssignedThroughAssignIsReleased) {
  const Balance b = balance_of([] {
    z3::context ctx;
    z3::expr e = ctx.bool_const("a");
    for (int i = 0; i < 10; ++i)
      smt::assign(e, e || ctx.bool_const(("b" + std::to_string(i)).c_str()));
  });
  EXPECT_GT(b.taken, 20);
  EXPECT_EQ(b.unreleased, 0);
}

TEST(Z3References, TheGateReleasesEveryTermItBuilds) {
  for (const char* name : {"msl_curiosity", "sample_drilling", "planetary_landing"}) {
    const Balance b = balance_of([&] {
      gate::Options options;
      gate::Outcome outcome = gate::run_gate(load_mission(name), options, "test");
      EXPECT_TRUE(outcome.compiled_xml.size() > 0) << name;
    });
    EXPECT_GT(b.taken, 20) << name;
    EXPECT_EQ(b.unreleased, 0) << name;
  }
}

TEST(Z3References, TheSymbolicEngineReleasesEveryTermItBuilds) {
  for (const char* name : {"msl_curiosity", "sample_drilling"}) {
    const Balance b = balance_of([&] {
      gate::Options options;
      options.prove.engine = "symbolic";
      const gate::Outcome outcome = gate::run_gate(load_mission(name), options, "test");
      ASSERT_TRUE(outcome.report.proofs) << name;
    });
    EXPECT_GT(b.taken, 10000) << name;
    EXPECT_EQ(b.unreleased, 0) << name;
  }
}

TEST(Z3References, SolvedCampaignTargetsReleaseEveryTermTheyBuild) {
  const load::Mission m = load_mission("msl_curiosity");
  campaign::Options solving;
  solving.solve_every_node = true;
  const Balance b = balance_of([&] {
    const campaign::Campaign c = campaign::build_campaign(m, solving);
    EXPECT_FALSE(c.targets.empty());
  });
  EXPECT_GT(b.taken, 20);
  EXPECT_EQ(b.unreleased, 0);
}

}  // namespace
}  // namespace uabt
