// The explicit engine's merged monitor reads (Options::merge_monitor_reads): branches of the
// monitors' reads that meet again are followed once, and a branch whose assumption monitors
// allow no more than a sibling's (prove::AssumptionOrder) is not followed at all. Nothing may be
// lost: the same verdicts and the same shortest violations as following every branch.
#include <random>

#include "bench/prove_families.hpp"
#include "prove/assumption_order.hpp"
#include "prove_support.hpp"
#include "sweep_mission.hpp"

namespace uabt::testing {
namespace {

std::size_t property_index(const prove::Model& m, const std::string& id) {
  for (std::size_t i = 0; i < m.properties.size(); ++i)
    if (m.properties[i].requirement->id == id) return i;
  ADD_FAILURE() << "no property " << id;
  return 0;
}

// The property's words after stepping its monitor through `ticks` (one input vector a tick).
std::vector<std::uint64_t> stepped(const prove::Property& p,
                                   const std::vector<std::vector<bool>>& ticks) {
  std::vector<std::uint64_t> words = p.layout->initial();
  std::vector<char> scratch;
  for (const auto& inputs : ticks) {
    bool bits[prove::Property::kMaxAtoms] = {};
    for (std::size_t i = 0; i < inputs.size(); ++i) bits[i] = inputs[i];
    p.layout->step(bits, words, scratch);
  }
  return words;
}

TEST(AssumptionOrder, AFlagNotYetSeenCoversItOnceSeenAndNotTheOtherWayRound) {
  const TempMission m({{"mission.xml", R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree"><Sequence><Check/><Act0/></Sequence></BehaviorTree>
</root>
)"},
                       {"domain.fret", "boolean Check, Late\n"},
                       {"requirements.fret",
                        "Keep: upon Check Environment shall always satisfy Check\n"
                        "Soon: upon Late Environment shall within 2 ticks satisfy !Late\n"
                        "G: Mission shall always satisfy Check | !Act0.running\n"},
                       {"world.json", R"({"actions": {"Act0": {"ticks": 1}}})"}});
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  prove::Model model(*g.outcome->mission, *g.doc, g.world);
  prove::AssumptionOrder order(model);

  const std::size_t keep = property_index(model, "Keep");
  const prove::Property& kp = model.properties[keep];
  ASSERT_TRUE(kp.layout);
  ASSERT_EQ(kp.layout->inputs(), 1u);
  const auto unseen = stepped(kp, {{false}});
  const auto seen = stepped(kp, {{true}});
  ASSERT_NE(unseen, seen);
  // Before Check is seen the environment may clear it; after, it may not.
  EXPECT_TRUE(order.covers(keep, unseen.data(), seen.data()));
  EXPECT_FALSE(order.covers(keep, seen.data(), unseen.data()));
  EXPECT_TRUE(order.covers(keep, seen.data(), seen.data()));

  // An obligation pending allows less than none: `Late` must clear within 2 ticks.
  const std::size_t soon = property_index(model, "Soon");
  const prove::Property& sp = model.properties[soon];
  ASSERT_TRUE(sp.layout);
  ASSERT_EQ(sp.atom_exprs.size(), 2u);
  ASSERT_EQ(fretish::to_fretish(*sp.atom_exprs[0]), "Late");
  ASSERT_EQ(fretish::to_fretish(*sp.atom_exprs[1]), "!Late");
  const auto idle = stepped(sp, {{false, true}});
  const auto pending = stepped(sp, {{true, false}});
  ASSERT_NE(idle, pending);
  EXPECT_TRUE(order.covers(soon, idle.data(), pending.data()));
  EXPECT_FALSE(order.covers(soon, pending.data(), idle.data()));
}

// Dust is read only by the assumption in tick 1 (the guarantee's `!A | Dust` stops at `!A`), so
// it is offered at its loosest: not yet seen, which leaves it free to be false in tick 2, when
// Act0 has set A and the guarantee reads Dust. Offering the tightest value (Dust seen, so it
// must stay set) would hide the violation.
TEST(MergedReads, AFlagOnlyAnAssumptionReadsIsOfferedAtItsLoosest) {
  const TempMission m({{"mission.xml", R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree"><Sequence><Act0/><Act1/></Sequence></BehaviorTree>
</root>
)"},
                       {"domain.fret", "boolean Dust, A\n"},
                       {"requirements.fret",
                        "GD: Mission shall always satisfy !A | Dust\n"
                        "K6: upon Dust Environment shall always satisfy Dust\n"},
                       {"world.json", R"({"initial": "!A", "actions": {
  "Act0": {"ticks": 2, "results": ["success"], "on_success": "A = true"},
  "Act1": {"ticks": 2, "results": ["success"]}}})"}});
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  for (const bool merge : {true, false}) {
    prove::Options o;
    o.engine = "explicit";
    o.merge_monitor_reads = merge;
    const prove::Result r = prove::prove(*g.outcome->mission, *g.doc, g.world, o);
    const prove::Answer& a = answer(r, "GD");
    ASSERT_EQ(a.verdict, prove::Verdict::violated) << merge;
    ASSERT_TRUE(a.counterexample);
    EXPECT_EQ(a.counterexample->tick, 2u) << merge;
  }
}

// An offer of loosest values that the assumption's read did not take (`!Armed | V` stops at
// `!Armed`) narrows nothing else: in the sequence where ActX fails, the Fallback ticks V with
// both values, and V = true starts Done at tick 1.
TEST(MergedReads, AnOfferTheAssumptionDidNotTakeDoesNotNarrowTheTreesRead) {
  const TempMission m({{"mission.xml", R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence><Fallback><ActX/><V/></Fallback><Done/></Sequence>
  </BehaviorTree>
</root>
)"},
                       {"domain.fret", "boolean V, Armed\n"},
                       {"requirements.fret",
                        "G: Mission shall always satisfy !Done.running\n"
                        "Keep: Environment shall always satisfy !Armed | V\n"},
                       {"world.json", R"({"initial": "!Armed", "actions": {
  "ActX": {"ticks": 1, "results": ["success", "failure"], "on_success": "Armed = Armed"},
  "Done": {"ticks": 2, "results": ["success"]}}})"}});
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result r = g.prove("explicit");
  const prove::Answer& a = answer(r, "G");
  ASSERT_EQ(a.verdict, prove::Verdict::violated);
  ASSERT_TRUE(a.counterexample);
  EXPECT_EQ(a.counterexample->tick, 1u);
}

// BehaVerify's checklist with `KeepK: upon CheckK Environment shall always satisfy CheckK`: the
// guarantee is proved, over a few states per flag. Following every branch, the monitors hold
// one state per set of flags seen set (2,050 states at N = 10).
TEST(MergedReads, TheRecheckedChecklistWithItsAssumptionsIsProvedInStatesLinearInN) {
  TempMission scratch({});
  std::vector<std::uint64_t> states;
  for (const int n : {10, 20, 40}) {
    SCOPED_TRACE(n);
    const auto family =
        bench::generate_recheck(scratch.dir() / ("kept" + std::to_string(n)), n, true);
    const Gated g(family.dir);
    ASSERT_TRUE(g.ok());
    const prove::Result r = g.prove("explicit");
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(answer(r, "Ready").verdict, prove::Verdict::proved);
    states.push_back(r.states);
  }
  // Doubling N doubles the states, give or take a constant (not 2^N).
  EXPECT_LE(states[1], 2 * states[0] + 16);
  EXPECT_LE(states[2], 2 * states[1] + 16);

  // At N = 6 the answer is the same without the merging, over more states.
  const auto family = bench::generate_recheck(scratch.dir() / "kept6", 6, true);
  const Gated g(family.dir);
  ASSERT_TRUE(g.ok());
  prove::Options every;
  every.engine = "explicit";
  every.merge_monitor_reads = false;
  const prove::Result all = prove::prove(*g.outcome->mission, *g.doc, g.world, every);
  const prove::Result merged = g.prove("explicit");
  EXPECT_EQ(answer(all, "Ready").verdict, prove::Verdict::proved);
  EXPECT_EQ(answer(merged, "Ready").verdict, prove::Verdict::proved);
  EXPECT_LT(merged.states, all.states);
}

// Random missions (sweep_mission.hpp) with assumptions whose monitors keep state (a flag once
// set, an obligation pending, a flag that must drop next tick, a flag only they read): with and
// without the merging, every verdict, every shortest violation and completeness agree, and the
// merging never keeps more states. UABT_MERGE_MISSIONS=N runs a longer sweep by hand.
TEST(MergedReads, AgreeWithFollowingEveryBranchOnRandomMissions) {
  const char* env = std::getenv("UABT_MERGE_MISSIONS");
  const unsigned count = env ? static_cast<unsigned>(std::strtoul(env, nullptr, 10)) : 30;
  const std::vector<std::string> assumptions = {
      "K1: upon E Environment shall always satisfy E\n",
      "K2: upon !E Environment shall within 2 ticks satisfy E\n",
      "K3: upon E Environment shall next satisfy !E\n",
      "K4: Environment shall always satisfy E -> !B\n",
      "K5: upon A Environment shall always satisfy !E\n",
  };
  unsigned compared = 0, fewer = 0, violated = 0, proved = 0;
  for (unsigned seed = 1; seed <= count; ++seed) {
    SweepMission m(seed);
    std::mt19937 rng(seed);
    const std::size_t first = rng() % assumptions.size();
    m.files["requirements.fret"] += assumptions[first];
    if (rng() % 2) m.files["requirements.fret"] += assumptions[(first + 1) % assumptions.size()];
    // A flag of the environment only an assumption reads (its loosest value is the only one
    // offered), or a guarantee too, before it or after it (the branches meet again).
    m.files["domain.fret"] += "boolean Dust\n";
    const std::string keep = "K6: upon Dust Environment shall always satisfy Dust\n";
    const std::string reads = rng() % 2 ? "GD: Mission shall always satisfy !A | !Dust\n"
                                        : "GD: Mission shall always satisfy !A | Dust\n";
    const unsigned order = rng() % 3;
    m.files["requirements.fret"] += order == 0 ? keep : order == 1 ? keep + reads : reads + keep;
    const TempMission dir(m.files);
    const Gated g(dir.dir(), m.style, false);
    if (!g.ok()) continue;
    prove::Options o;
    o.engine = "explicit";
    o.max_states = 20'000;
    prove::Result merged, all;
    try {
      merged = prove::prove(*g.outcome->mission, *g.doc, g.world, o);
      o.merge_monitor_reads = false;
      all = prove::prove(*g.outcome->mission, *g.doc, g.world, o);
    } catch (const prove::ProveError& e) {
      const std::string what = e.what();
      ASSERT_EQ(what.find("internal error"), std::string::npos) << "seed " << seed << ": " << what;
      continue;
    }
    if (!all.complete) continue;  // beyond the limit: nothing to compare
    ++compared;
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + m.files["requirements.fret"]);
    EXPECT_TRUE(merged.complete);
    EXPECT_LE(merged.states, all.states);
    fewer += merged.states < all.states;
    ASSERT_EQ(merged.answers.size(), all.answers.size());
    for (std::size_t i = 0; i < all.answers.size(); ++i) {
      const prove::Answer &a = all.answers[i], &b = merged.answers[i];
      EXPECT_EQ(std::string(prove::verdict_name(b.verdict)), prove::verdict_name(a.verdict))
          << a.requirement;
      EXPECT_EQ(b.counterexample.has_value(), a.counterexample.has_value()) << a.requirement;
      if (a.counterexample && b.counterexample) {
        EXPECT_EQ(b.counterexample->tick, a.counterexample->tick) << a.requirement;
      }
      violated += a.verdict == prove::Verdict::violated;
      proved += a.verdict == prove::Verdict::proved;
    }
  }
  std::cout << "merged reads: " << compared << " missions compared, " << fewer
            << " with fewer states, " << violated << " violated and " << proved
            << " proved guarantees\n";
  if (env) return;
  EXPECT_GE(compared, 15u);
  EXPECT_GE(fewer, 5u);
  EXPECT_GE(violated, 20u);
  EXPECT_GE(proved, 20u);
}

}  // namespace
}  // namespace uabt::testing
