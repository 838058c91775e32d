// Differential sweep: random missions (sweep_mission.hpp) proved by both engines. Every
// counterexample is replayed on the runtime by prove itself (a replay that disagrees is an
// internal ProveError); the engines must give the same verdicts and the same shortest
// violation ticks. UABT_SWEEP_MISSIONS=N (default 40) and UABT_SWEEP_FIRST=S run a longer
// sweep by hand.
#include <chrono>
#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>

#include "prove_support.hpp"
#include "sweep_mission.hpp"

namespace uabt::testing {
namespace {

using prove::Verdict;

unsigned env_or(const char* name, unsigned fallback) {
  const char* v = std::getenv(name);
  return v ? static_cast<unsigned>(std::strtoul(v, nullptr, 10)) : fallback;
}

std::string describe(unsigned seed, const SweepMission& m) {
  std::string s = "seed " + std::to_string(seed) + "\n";
  for (const auto& [path, text] : m.files) s += "--- " + path + "\n" + text + "\n";
  return s;
}

// A prove answer, or why the engine gave none: "declined" (what it does not model, said by
// name), "internal" (a counterexample its replay disagrees with: a bug).
struct Proof {
  std::optional<prove::Result> result;
  std::string error;
  bool internal = false;
};

Proof prove_with(const Gated& g, const std::string& engine, std::uint64_t depth = 0) {
  Proof p;
  try {
    p.result = g.prove(engine, depth);
  } catch (const prove::ProveError& e) {
    p.error = e.what();
    p.internal = p.error.find("internal error") != std::string::npos;
  }
  return p;
}

struct Tally {
  int missions = 0, gated = 0, explicit_answered = 0, both = 0, violated = 0, proved = 0;
  int temporal = 0;  // answered guarantees that read persisted, occurred, prevOcc or FTP
  std::set<std::string> kinds;
};

// Proves one random mission with both engines; a disagreement is a test failure that prints
// the mission.
void sweep_one(unsigned seed, bool symbolic, std::uint64_t depth, Tally& tally,
               bool temporal = false, bool mixed = false) {
  const SweepMission m(seed, temporal, mixed);
  ++tally.missions;
  const TempMission dir(m.files);
  const Gated g(dir.dir(), m.style, false);
  if (!g.ok()) {
    if (std::getenv("UABT_SWEEP_VERBOSE") && g.outcome)
      std::cout << "not gated " << seed << ": " << format_text(g.outcome->report.findings) << "\n";
    return;
  }
  ++tally.gated;
  tally.kinds.insert(m.kinds.begin(), m.kinds.end());
  const auto t0 = std::chrono::steady_clock::now();
  const Proof e = prove_with(g, "explicit");
  if (std::getenv("UABT_SWEEP_VERBOSE"))
    std::cout << "explicit "
              << std::chrono::duration_cast<std::chrono::milliseconds>(
                     std::chrono::steady_clock::now() - t0)
                     .count()
              << " ms " << (e.result ? e.result->states : 0) << " states\n";
  EXPECT_FALSE(e.internal) << e.error << "\n" << describe(seed, m);
  if (std::getenv("UABT_SWEEP_VERBOSE") && !e.result)
    std::cout << "explicit " << seed << ": " << e.error << "\n";
  if (!e.result || !e.result->complete) return;
  ++tally.explicit_answered;
  for (const auto& a : e.result->answers) {
    tally.violated += a.verdict == Verdict::violated;
    tally.proved += a.verdict == Verdict::proved;
    bool reads_past = false;
    for (const char* f : {"persisted(", "occurred(", "prevOcc(", "FTP"})
      reads_past = reads_past || a.text.find(f) != std::string::npos;
    tally.temporal += reads_past && a.verdict != Verdict::unsupported;
  }
  if (!symbolic) return;
  const Proof s = prove_with(g, "symbolic", depth);
  EXPECT_FALSE(s.internal) << s.error << "\n" << describe(seed, m);
  if (!s.result) {
    if (std::getenv("UABT_SWEEP_VERBOSE"))
      std::cout << "symbolic " << seed << ": " << s.error << "\n";
    return;
  }
  ++tally.both;
  const auto &x = e.result->answers, &y = s.result->answers;
  ASSERT_EQ(x.size(), y.size()) << describe(seed, m);
  for (std::size_t i = 0; i < x.size(); ++i) {
    // A proof k-induction and IC3/PDR could not finish within their bounds, or a violation
    // beyond the symbolic depth, is `bounded`: not an answer that disagrees.
    if (y[i].verdict == Verdict::bounded &&
        (x[i].verdict == Verdict::proved ||
         (x[i].verdict == Verdict::violated && depth != 0 && x[i].depth > depth)))
      continue;
    EXPECT_EQ(prove::verdict_name(x[i].verdict), std::string(prove::verdict_name(y[i].verdict)))
        << x[i].requirement << "\n"
        << describe(seed, m);
    if (x[i].verdict == Verdict::violated && y[i].verdict == Verdict::violated) {
      EXPECT_EQ(x[i].depth, y[i].depth) << x[i].requirement << "\n" << describe(seed, m);
    }
  }
}

// Sweeps `seeds`, the symbolic engine on those `symbolic_on` accepts, and prints the tally.
Tally sweep(const std::string& label, const std::vector<unsigned>& seeds,
            const std::function<bool(unsigned)>& symbolic_on, std::uint64_t depth, bool temporal,
            bool mixed = false) {
  Tally tally;
  for (unsigned seed : seeds) {
    const auto start = std::chrono::steady_clock::now();
    sweep_one(seed, symbolic_on(seed), depth, tally, temporal, mixed);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                        std::chrono::steady_clock::now() - start)
                        .count();
    if (std::getenv("UABT_SWEEP_VERBOSE")) std::cout << "seed " << seed << ": " << ms << " ms\n";
  }
  std::cout << label << ": " << tally.missions << " missions, " << tally.gated << " gated, "
            << tally.explicit_answered << " proved explicitly, " << tally.both
            << " by both engines, " << tally.violated << " violated and " << tally.proved
            << " proved guarantees, " << tally.temporal
            << " answered guarantees read temporal functions\n";
  return tally;
}

// Found by the sweep: a domain variable only a Script writes was taken for the environment's
// and chosen afresh every tick, while the runtime keeps what the Script wrote. The explicit
// engine's counterexample then did not replay ("violates it at tick 2 in the model but its
// replay violates it at tick 1") and the symbolic engine reported a violation no run has.
TEST(ProveSweep, AVariableAScriptWritesIsTheMissions) {
  const TempMission m({{"mission.xml", R"(<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence>
      <Script code="x = x + 1"/>
      <Act0/>
    </Sequence>
  </BehaviorTree>
</root>
)"},
                       {"domain.fret", "integer x in [0, 3]\n"},
                       {"requirements.fret",
                        "Low: Mission shall always satisfy x <= 1\n"
                        "Within: if x = 1 Mission shall within 1 ticks satisfy x = 0\n"},
                       {"world.json", R"({"initial": "x = 0", "actions": {
                          "Act0": {"ticks": 2, "results": ["success"]}}})"}});
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  for (const char* engine : {"explicit", "symbolic"}) {
    const prove::Result r = g.prove(engine);
    EXPECT_EQ(answer(r, "Low").verdict, Verdict::proved) << engine;
    const prove::Answer& within = answer(r, "Within");
    ASSERT_EQ(within.verdict, Verdict::violated) << engine;
    ASSERT_TRUE(within.counterexample);
    EXPECT_EQ(within.counterexample->tick, 2u) << engine;
    // The replay: x is 1 at both ticks, what the Script wrote at tick 1.
    ASSERT_EQ(within.counterexample->rows.size(), 2u);
    for (const auto& row : within.counterexample->rows) {
      ASSERT_EQ(row.values.size(), 1u);
      EXPECT_EQ(row.values[0].first, "x");
      EXPECT_EQ(row.values[0].second.to_string(), "1") << engine << " tick " << row.tick;
    }
    // x starts at world.json's 0 and no event sets it: the Script alone writes it.
    EXPECT_NE(within.counterexample->scenario.find("\"initial\": {\n    \"x\": 0\n  }"),
              std::string::npos)
        << within.counterexample->scenario;
    EXPECT_EQ(within.counterexample->scenario.find("\"events\""), std::string::npos)
        << within.counterexample->scenario;
  }
}

// Proves sweep mission `seed` with the explicit engine (each counterexample is replayed on the
// runtime by prove itself: a replay that disagrees is an internal error) and returns the
// counterexample of `id`, whose replay rows the caller checks.
prove::Counterexample sweep_counterexample(unsigned seed, const std::string& id,
                                           std::uint64_t tick) {
  const SweepMission m(seed);
  const TempMission dir(m.files);
  const Gated g(dir.dir(), m.style, false);
  EXPECT_TRUE(g.ok()) << describe(seed, m);
  if (!g.ok()) return {};
  const Proof e = prove_with(g, "explicit");
  EXPECT_TRUE(e.result) << e.error << "\n" << describe(seed, m);
  if (!e.result) return {};
  const prove::Answer& a = answer(*e.result, id);
  EXPECT_EQ(a.verdict, Verdict::violated) << describe(seed, m);
  EXPECT_TRUE(a.counterexample) << describe(seed, m);
  if (!a.counterexample) return {};
  EXPECT_EQ(a.counterexample->tick, tick);
  return *a.counterexample;
}

std::vector<std::string> actions_at(const prove::Counterexample& cex, std::uint64_t tick) {
  for (const auto& row : cex.rows)
    if (row.tick == tick) return row.actions;
  ADD_FAILURE() << "no row for tick " << tick;
  return {};
}

// Found by the sweep (seed 1774): a Parallel runs Act2 next to a reactive adaptable node whose
// alternative (a SequenceWithMemory) runs another Act2. The SequenceWithMemory's wake-up
// re-tick ticks the Parallel's Act2 twice in tick 1. The counterexample gave each run's
// `ticks` as engine ticks, while the simulated world (as BehaviorTree.CPP) counts the action's
// own ticks, so on replay the Parallel's Act2 ended at tick 3 where the proof had it still
// running ("violates it at tick 3 in the model but its replay does not violate it").
TEST(ProveSweep, AnActionTickedTwiceInOneTickReplaysItsRun) {
  const prove::Counterexample cex = sweep_counterexample(1774, "P1", 3);
  ASSERT_EQ(cex.rows.size(), 3u);
  EXPECT_EQ(actions_at(cex, 1),
            (std::vector<std::string>{"C started", "C success", "Act2 started", "Act2 started"}));
  // The alternative switches away and halts its Act2; the Parallel's Act2 runs on.
  EXPECT_EQ(actions_at(cex, 3), (std::vector<std::string>{"Act2 running", "Act2 halted"}));
  // The Parallel's Act2 has run 4 ticks of its own in 3 engine ticks (it ends after the run);
  // the halted one 2 (it does not end before its halt).
  const auto runs = nlohmann::json::parse(cex.scenario)["actions"]["Act2"]["runs"];
  ASSERT_EQ(runs.size(), 2u) << cex.scenario;
  EXPECT_EQ(runs[0]["ticks"], 5) << cex.scenario;
  EXPECT_EQ(runs[1]["ticks"], 3) << cex.scenario;
}

// Found by the sweep (seed 964): WhileDoElse(Act0, Act0). The condition Act0 starts over at
// tick 3 and runs, so the WhileDoElse does not tick the do-branch's Act0 (started at tick 2)
// until tick 4: two ticks of its own over three engine ticks. The counterexample said 3 ticks,
// and on replay that Act0 was still running at tick 4.
TEST(ProveSweep, AnActionItsParentDoesNotTickForATickReplaysItsRun) {
  const prove::Counterexample cex = sweep_counterexample(964, "P2", 4);
  ASSERT_EQ(cex.rows.size(), 4u);
  // The do-branch's Act0 runs on, not ticked, while the condition's Act0 starts over.
  EXPECT_EQ(actions_at(cex, 3), (std::vector<std::string>{"Act0 running", "Act0 started"}));
  EXPECT_EQ(actions_at(cex, 4),
            (std::vector<std::string>{"Act0 success", "Act0 success", "Act0 started"}));
  // The do-branch's Act0 (the second start) ran 2 ticks of its own, as its contract says.
  const auto runs = nlohmann::json::parse(cex.scenario)["actions"]["Act0"]["runs"];
  ASSERT_EQ(runs.size(), 4u) << cex.scenario;
  EXPECT_EQ(runs[1]["ticks"], 2) << cex.scenario;
}

// By default 40 missions (and one the sweep once caught), each proved explicitly, and the symbolic
// engine (BMC, k-induction, IC3/PDR: seconds to minutes on some of these missions) on the few whose
// symbolic proof takes well under a second, so that the test runs in seconds. A longer sweep by
// hand: UABT_SWEEP_FIRST=41 UABT_SWEEP_MISSIONS=3000 [UABT_SWEEP_SYMBOLIC=0|1] [UABT_SWEEP_DEPTH=k]
// (UABT_SWEEP_SYMBOLIC=1: the symbolic engine on every mission; UABT_SWEEP_VERBOSE=1: times).
TEST(ProveSweep, EnginesAgreeAndEveryCounterexampleReplays) {
  const unsigned first = env_or("UABT_SWEEP_FIRST", 1), count = env_or("UABT_SWEEP_MISSIONS", 40);
  const bool by_default = std::getenv("UABT_SWEEP_MISSIONS") == nullptr;
  const std::set<unsigned> quick_symbolic = {7, 13, 17, 19, 25};
  // The symbolic engine's depth (0: its own bound, 40 ticks and IC3/PDR).
  const std::uint64_t depth = env_or("UABT_SWEEP_DEPTH", 3);
  const bool symbolic = env_or("UABT_SWEEP_SYMBOLIC", 0) != 0;
  std::vector<unsigned> seeds;
  for (unsigned seed = first; seed < first + count; ++seed) seeds.push_back(seed);
  // The mission whose counterexample did not replay (a variable only a Script writes).
  if (by_default) seeds.push_back(183);
  const Tally tally = sweep(
      "sweep", seeds,
      [&](unsigned seed) { return symbolic || (by_default && quick_symbolic.contains(seed)); },
      depth, false);
  if (!by_default) return;
  // The default sweep exercises both verdicts, both engines, and every node kind.
  EXPECT_EQ(tally.gated, 41);
  EXPECT_GE(tally.explicit_answered, 30);
  EXPECT_EQ(tally.both, 5);
  EXPECT_GE(tally.violated, 40);
  EXPECT_GE(tally.proved, 40);
  EXPECT_EQ(tally.kinds.size(), 22u);
}

// The same sweep over guarantees that read FRET's temporal functions and FTP
// (SweepMission(seed, true)): the explicit engine's monitor state and the symbolic engine's
// monitor table must agree on every verdict and shortest violation, and every counterexample
// replays on the runtime, whose monitor reads the functions tick by tick.
// UABT_SWEEP_TEMPORAL_MISSIONS=N (default 30) runs a longer sweep by hand.
TEST(ProveSweep, EnginesAgreeOnFretTemporalFunctions) {
  const unsigned count = env_or("UABT_SWEEP_TEMPORAL_MISSIONS", 30);
  const bool by_default = std::getenv("UABT_SWEEP_TEMPORAL_MISSIONS") == nullptr;
  const std::set<unsigned> quick_symbolic = {4, 7, 9, 13, 17, 19, 25};
  const bool symbolic = env_or("UABT_SWEEP_SYMBOLIC", 0) != 0;
  std::vector<unsigned> seeds;
  for (unsigned seed = 1; seed <= count; ++seed) seeds.push_back(seed);
  const Tally tally = sweep(
      "temporal sweep", seeds,
      [&](unsigned seed) { return symbolic || (by_default && quick_symbolic.contains(seed)); }, 3,
      true);
  if (!by_default) return;
  EXPECT_EQ(tally.gated, 30);
  EXPECT_GE(tally.explicit_answered, 20);
  EXPECT_EQ(tally.both, 7);
  EXPECT_GE(tally.violated, 20);
  EXPECT_GE(tally.proved, 20);
  EXPECT_GE(tally.temporal, 15);
}

}  // namespace
}  // namespace uabt::testing

namespace uabt::testing {
namespace {

// The sweep over atoms that compare the environment's real r and wide integer w with the
// mission's own x (SweepMission(seed, false, true)): in guards, scripts, effects, an assumption
// and guarantees. The explicit engine cuts r and w in each state it explores (it left every
// such mission to the symbolic engine before); the engines must agree on every verdict and
// shortest violation, and every counterexample replays. UABT_SWEEP_MIXED_MISSIONS=N (default 30)
// runs a longer sweep by hand.
TEST(ProveSweep, EnginesAgreeOnAtomsMixingTheEnvironmentAndTheMissionsState) {
  const unsigned first = env_or("UABT_SWEEP_FIRST", 1);
  const unsigned count = env_or("UABT_SWEEP_MIXED_MISSIONS", 30);
  const bool by_default = std::getenv("UABT_SWEEP_MIXED_MISSIONS") == nullptr;
  const std::set<unsigned> quick_symbolic = {4, 9, 10, 16, 19, 25};
  const bool symbolic = env_or("UABT_SWEEP_SYMBOLIC", 0) != 0;
  std::vector<unsigned> seeds;
  for (unsigned seed = first; seed < first + count; ++seed) seeds.push_back(seed);
  const Tally tally = sweep(
      "mixed sweep", seeds,
      [&](unsigned seed) { return symbolic || (by_default && quick_symbolic.contains(seed)); }, 3,
      false, true);
  if (!by_default) return;
  // Before, the explicit engine answered none of these: each reads r or w in a mixed atom.
  EXPECT_EQ(tally.gated, 30);
  EXPECT_GE(tally.explicit_answered, 20);
  EXPECT_EQ(tally.both, 6);
  EXPECT_GE(tally.violated, 20);
  EXPECT_GE(tally.proved, 20);
}

}  // namespace
}  // namespace uabt::testing
