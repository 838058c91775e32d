// The symbolic engine against the explicit-state one: same verdicts and shortest violation
// ticks on the shipped missions and on random ones, the one-tick transition against
// Engine::tick() on random reachable states, and worlds only the symbolic engine can take.
#include <nlohmann/json.hpp>
#include <random>

#include "prove/explore.hpp"
#include "prove/model.hpp"
#include "prove/symbolic.hpp"
#include "prove/symbolic_tick.hpp"
#include "prove_support.hpp"
#include "random_mission.hpp"
#include "runtime/runner.hpp"
#include "smt/assign.hpp"
#include "style_missions.hpp"

namespace uabt::testing {
namespace {

using prove::Verdict;

void expect_same_answers(const prove::Result& a, const prove::Result& b, const std::string& what) {
  ASSERT_EQ(a.answers.size(), b.answers.size()) << what;
  for (std::size_t i = 0; i < a.answers.size(); ++i) {
    const prove::Answer &x = a.answers[i], &y = b.answers[i];
    EXPECT_EQ(prove::verdict_name(x.verdict), std::string(prove::verdict_name(y.verdict)))
        << what << ": " << x.requirement;
    if (x.verdict == Verdict::violated && y.verdict == Verdict::violated) {
      EXPECT_EQ(x.counterexample->tick, y.counterexample->tick) << what << ": " << x.requirement;
    }
  }
}

TEST(SymbolicAgreement, CuriositySequenceAndReactive) {
  for (auto style : {compile::SelectionStyle::sequence, compile::SelectionStyle::reactive}) {
    const Gated g(mission_dir("msl_curiosity"), style);
    ASSERT_TRUE(g.ok());
    const prove::Result e = g.prove("explicit"), s = g.prove("symbolic");
    EXPECT_EQ(s.engine, "symbolic");
    expect_same_answers(e, s, "msl_curiosity");
    // The expected answers themselves (README): only the paper's sequence style lets a drive
    // run on over an unknown terrain (HoldOnUnknown, at tick 3).
    const bool sequence = style == compile::SelectionStyle::sequence;
    for (const auto& a : s.answers) {
      const bool violated = sequence && a.requirement == "HoldOnUnknown";
      EXPECT_EQ(a.verdict, violated ? Verdict::violated : Verdict::proved) << a.requirement;
    }
    if (sequence) {
      EXPECT_EQ(answer(s, "HoldOnUnknown").depth, 3u);
    }
  }
}

// IC3/PDR takes over after 2-induction: deeper induction and BMC only for what is still open
// (with 6 depths first, msl_curiosity took 3-4 times as long).
TEST(SymbolicAgreement, CuriosityIsProvedAfterTwoInductionDepths) {
  const Gated g(mission_dir("msl_curiosity"), compile::SelectionStyle::reactive);
  ASSERT_TRUE(g.ok());
  const prove::Result s = g.prove("symbolic");
  ASSERT_EQ(s.answers.size(), 4u);
  for (const auto& a : s.answers) EXPECT_EQ(a.verdict, Verdict::proved) << a.requirement;
  EXPECT_EQ(s.induction_k, 2u);
  EXPECT_EQ(s.depth, 2u);
}

// What 2-induction leaves open of msl_curiosity (three guarantees) IC3/PDR proves in one
// query for all of them, with a few frames (it took one full query per guarantee).
TEST(SymbolicAgreement, CuriosityIsProvedByOneIcQueryForAllOpenGuarantees) {
  const Gated g(mission_dir("msl_curiosity"), compile::SelectionStyle::reactive);
  ASSERT_TRUE(g.ok());
  prove::Model m(*g.outcome->mission, *g.doc, g.world);
  const prove::SymbolicSearch s = prove::symbolic_search(m, {});
  EXPECT_EQ(s.pdr_queries, 1u);
  std::size_t by_pdr = 0;
  for (std::size_t p = 0; p < m.properties.size(); ++p) {
    EXPECT_TRUE(s.proved[p]) << m.properties[p].requirement->id;
    by_pdr += s.by_pdr[p];
  }
  EXPECT_EQ(by_pdr, 3u);
}

// The symbolic engine spends a budget of Z3's resource count (deterministic, unlike a clock),
// not unbounded time: a search that would need more stops, keeps what it found (a violation
// BMC reached is real) and leaves every other guarantee bounded at the depth BMC checked, with
// a note saying so. sample_drilling needs about 2 million units: 20,000 decide nothing,
// 1 million find CoolBit's violation at tick 1 but not OneTool's proof, the default both.
TEST(SymbolicBudget, ASearchStopsAtItsBudgetAndKeepsOnlyWhatItDecided) {
  const Gated g(mission_dir("sample_drilling"));
  ASSERT_TRUE(g.ok());
  auto prove_with = [&](std::uint64_t resources) {
    prove::Options o;
    o.engine = "symbolic";
    o.symbolic_resources = resources;
    return prove::prove(*g.outcome->mission, *g.doc, g.world, o);
  };
  auto notes = [](const prove::Result& r) {
    std::string out;
    for (const auto& n : r.notes) out += n + "\n";
    return out;
  };
  const prove::Result none = prove_with(20'000);
  EXPECT_FALSE(none.complete);
  EXPECT_EQ(answer(none, "CoolBit").verdict, Verdict::bounded);
  EXPECT_EQ(answer(none, "OneTool").verdict, Verdict::bounded);
  EXPECT_EQ(answer(none, "OneTool").depth, 0u);
  EXPECT_NE(notes(none).find("the symbolic engine spent its budget (20000 of Z3's resource "
                             "units) at tick 1\n"),
            std::string::npos)
      << notes(none);
  const prove::Result some = prove_with(1'000'000);
  EXPECT_EQ(answer(some, "CoolBit").verdict, Verdict::violated);
  EXPECT_EQ(answer(some, "CoolBit").counterexample->tick, 1u);
  EXPECT_EQ(answer(some, "OneTool").verdict, Verdict::bounded);
  EXPECT_NE(notes(some).find("spent its budget"), std::string::npos) << notes(some);
  const prove::Result all = prove_with(prove::Options{}.symbolic_resources);
  EXPECT_EQ(answer(all, "CoolBit").verdict, Verdict::violated);
  EXPECT_EQ(answer(all, "OneTool").verdict, Verdict::proved);
  EXPECT_EQ(notes(all).find("spent its budget"), std::string::npos) << notes(all);
  // What a bounded symbolic answer tells the user: which engine stopped where, and what to try.
  const auto findings = gate::findings_of(none);
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings[0].check, "prove-bounded");
  EXPECT_EQ(findings[0].notes.at(0),
            "the symbolic engine checked every run up to tick 0 but could not prove it for longer "
            "runs; try --engine explicit, or shrink the world to decide it");
}

// The missions of prove_test.cpp: sample_drilling (Repeat, wake-up re-ticks) and its
// variants, as shipped and with one drilling cycle instead of the Repeat.
TEST(SymbolicAgreement, DrillingMissions) {
  const char* fixed_rotary = R"(<root BTCPP_format="4" main_tree_to_execute="rotary">
  <BehaviorTree ID="rotary">
    <Sequence><Fallback><IsBitCool/><CoolDown/></Fallback><Drill mode="rotary"/></Sequence>
  </BehaviorTree>
</root>
)";
  auto base = mission_files("sample_drilling");
  std::vector<std::map<std::string, std::string>> variants(5, base);
  variants[1]["alternatives/drilling/rotary.xml"] = fixed_rotary;
  variants[2]["requirements.fret"] += "HardOnly: Environment shall always satisfy HardRock\n";
  variants[3].erase("world.json");
  variants[4]["world.json"] = R"({"initial": "!IsBitCool", "actions": {
      "Drill": {"ticks": [2, 3], "results": ["success"], "on_success": "IsBitCool = false"},
      "CoolDown": {"ticks": [1, 2], "results": ["success"], "on_success": "IsBitCool = true"}}})";
  for (std::size_t i = 0, n = variants.size(); i < n; ++i) {
    auto once = variants[i];
    std::string& xml = once["mission.xml"];
    xml.replace(xml.find("<Repeat num_cycles=\"3\">"), 24, "<Sequence>");
    xml.replace(xml.find("</Repeat>"), 9, "</Sequence>");
    variants.push_back(std::move(once));
  }
  // The repaired mission with its Repeat (variant 1) needs a minute of IC3/PDR to prove CoolBit
  // symbolically, too long for every test run; its one-cycle form (variant 6) stays, and the
  // other Repeat variants still prove OneTool through the Repeat.
  variants.erase(variants.begin() + 1);
  int violated = 0;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    TempMission m(variants[i]);
    const Gated g(m.dir());
    ASSERT_TRUE(g.ok()) << i;
    const prove::Result e = g.prove("explicit"), s = g.prove("symbolic");
    EXPECT_EQ(s.engine, "symbolic");
    expect_same_answers(e, s, "variant " + std::to_string(i));
    violated += answer(s, "CoolBit").verdict == Verdict::violated;
  }
  EXPECT_GE(violated, 4);
  EXPECT_EQ(variants.size(), 9u);
}

// A Repeat whose count is not a literal of at least 0 is declined, naming the node.
TEST(SymbolicAgreement, RepeatForeverIsDeclinedWithItsPlace) {
  auto files = mission_files("sample_drilling");
  std::string& xml = files["mission.xml"];
  xml.replace(xml.find("num_cycles=\"3\""), 14, "num_cycles=\"-1\"");
  TempMission m(files);
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  try {
    g.prove("symbolic");
    FAIL() << "the symbolic engine took Repeat num_cycles=-1";
  } catch (const prove::ProveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Repeat"), std::string::npos) << what;
    EXPECT_NE(what.find("compiled.xml:"), std::string::npos) << what;
  }
}

TEST(SymbolicAgreement, HundredRandomMissions) {
  int checked = 0, violated = 0, proved = 0;
  std::set<std::string> kinds;
  for (unsigned seed = 1; checked < 100 && seed < 400; ++seed) {
    RandomMission r(seed);
    TempMission m(r.files);
    const Gated g(m.dir());
    if (!g.ok()) continue;
    const prove::Result e = g.prove("explicit");
    if (!e.complete) continue;
    const prove::Result s = g.prove("symbolic");
    expect_same_answers(e, s,
                        "seed " + std::to_string(seed) + "\n" + r.files["mission.xml"] +
                            r.files["world.json"] + "\n" + r.files["requirements.fret"]);
    for (const auto& a : s.answers) {
      violated += a.verdict == Verdict::violated;
      proved += a.verdict == Verdict::proved;
    }
    kinds.insert(r.kinds.begin(), r.kinds.end());
    ++checked;
  }
  EXPECT_EQ(checked, 100);
  // Both answers occur, and every node kind of the subset was exercised.
  EXPECT_GT(violated, 20);
  EXPECT_GT(proved, 20);
  EXPECT_EQ(kinds.size(), 17u);
}

// --- One tick: the symbolic transition with every choice fixed is Engine::tick().

struct Returned : runtime::Observer {
  std::vector<runtime::NodeStatus> last;
  std::vector<std::vector<runtime::NodeStatus>> ticks;  // every return, in order
  void on_status_change(runtime::NodeId, runtime::NodeStatus, runtime::NodeStatus) override {}
  void on_node_ticked(runtime::NodeId n, runtime::NodeStatus s) override {
    last[n] = s;
    ticks[n].push_back(s);
  }
};

std::int64_t int_of(const z3::expr& e) {
  const z3::expr v = e.simplify();
  int64_t i = 0;
  EXPECT_TRUE(v.is_numeral_i64(i)) << v;
  return i;
}

// Random runs of the explicit model: before each tick random environment values and action
// outcomes; the symbolic tick evaluated on the same state and choices must give the same
// statuses, counters, blackboard, action progress, observables and monitor states.
void check_ticks(const Gated& g, unsigned seed, int runs, int ticks) {
  prove::Model m(*g.outcome->mission, *g.doc, g.world);
  z3::context ctx;
  prove::SymbolicTick sym(m, ctx);
  Returned returned;
  m.engine->add_observer(&returned);
  std::mt19937 rng(seed);
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const auto& leaves = m.choice->leaves();
  for (int run = 0; run < runs; ++run) {
    m.fresh.restore(*m.engine);
    m.choice->set_elapsed(std::vector<std::int64_t>(leaves.size(), 0));
    std::vector<std::uint64_t> monitors;
    for (const auto& p : m.properties) {
      if (!p.layout) continue;
      const auto w = p.layout->initial();
      monitors.insert(monitors.end(), w.begin(), w.end());
    }
    for (int t = 0; t < ticks; ++t) {
      const bool first = t == 0;
      // The state before the tick, as terms.
      const auto before = runtime::EngineState::save(*m.engine);
      prove::SymState s = sym.fresh();
      for (std::size_t n = 0; n < before.status.size(); ++n) {
        smt::assign(s.status[n], ctx.int_val(static_cast<int>(before.status[n])));
        smt::assign(s.counter[n], ctx.int_val(before.counters[3 * n]));
      }
      for (std::size_t l = 0; l < leaves.size(); ++l)
        smt::assign(s.elapsed[l], ctx.int_val(static_cast<int64_t>(m.choice->elapsed()[l])));
      for (std::size_t v = 0; v < m.vars.size(); ++v)
        if (sym.tracked(v))
          smt::assign(s.values[v],
                      prove::constant_of(ctx, m.engine->blackboard().value(m.vars[v].slot),
                                         sym.type(v), sym.codes()));
      for (std::size_t p = 0; p < m.properties.size(); ++p) {
        const auto& prop = m.properties[p];
        if (!prop.layout) continue;
        std::vector<std::uint64_t> w(monitors.begin() + prop.offset,
                                     monitors.begin() + prop.offset + prop.layout->words());
        smt::assign(s.monitor[p], ctx.int_val(static_cast<int>(*sym.table(p)->index_of(w))));
      }
      s.started = {ctx.bool_val(!first)};
      s.done = {ctx.bool_val(false)};
      s.wake = {ctx.bool_val(before.wake_up)};
      // Every reachable state lies in what k-induction and IC3/PDR assume of any state.
      EXPECT_TRUE(sym.domain(s).simplify().is_true()) << "seed " << seed << " tick " << t + 1;
      // Random environment values and outcomes the contracts allow.
      prove::TickInputs in = sym.inputs("x.");
      for (std::size_t v = 0; v < m.vars.size(); ++v) {
        if (!m.vars[v].relevant || (!first && !m.vars[v].env)) continue;
        const auto& value = m.vars[v].values[pick(m.vars[v].values.size())];
        m.engine->blackboard().value(m.vars[v].slot) = value;
        smt::assign(in.values[v], prove::constant_of(ctx, value, sym.type(v), sym.codes()));
      }
      std::vector<monitor::Val> scratch_frame;
      if (first && m.initial && !m.holds(*m.initial, scratch_frame)) break;
      bool assumed = true;  // the domain's assumptions hold on the values before the tick
      for (auto& a : m.assumptions) assumed = assumed && m.holds(*a, scratch_frame);
      // The concrete tick, its choices at random; what each action did, in order, is the
      // symbolic tick's outcomes.
      returned.last.assign(m.engine->node_count(), runtime::NodeStatus::idle);
      returned.ticks.assign(m.engine->node_count(), {});
      std::vector<std::uint32_t> prefix;
      for (int k = 0; k < 64; ++k) prefix.push_back(static_cast<std::uint32_t>(pick(1000)));
      m.choice->chooser.start(prefix);
      m.observables->begin_tick();
      runtime::NodeStatus root;
      try {
        root = m.engine->tick();
      } catch (const runtime::TickException&) {
        break;  // a tick error: the explicit engine drops this step too
      }
      for (std::size_t l = 0; l < leaves.size(); ++l) {
        const auto* c = leaves[l].contract;
        std::size_t k = 0;
        for (runtime::NodeStatus st : returned.ticks[leaves[l].node]) {
          std::int32_t o = -1;
          if (st != runtime::NodeStatus::running) {
            const std::vector<runtime::NodeStatus> free = {runtime::NodeStatus::success,
                                                           runtime::NodeStatus::failure};
            const auto& results = c ? c->results : free;
            o = static_cast<std::int32_t>(std::find(results.begin(), results.end(), st) -
                                          results.begin());
          }
          ASSERT_LT(k, in.outcomes[l].size());
          smt::assign(in.outcomes[l][k++], ctx.int_val(o));
        }
        for (; k < in.outcomes[l].size(); ++k) smt::assign(in.outcomes[l][k], ctx.int_val(-1));
      }
      const prove::TickEncoding enc = sym.encode(s, in, first);
      const std::string where = "seed " + std::to_string(seed) + " run " + std::to_string(run) +
                                " tick " + std::to_string(t + 1);
      EXPECT_EQ(int_of(enc.root), static_cast<int>(root)) << where;
      const auto after = runtime::EngineState::save(*m.engine);
      for (std::size_t n = 0; n < after.status.size(); ++n) {
        EXPECT_EQ(int_of(enc.next.status[n]), static_cast<int>(after.status[n]))
            << where << " node " << m.engine->instance_path(static_cast<runtime::NodeId>(n));
        EXPECT_EQ(int_of(enc.next.counter[n]), after.counters[3 * n]) << where << " node " << n;
        EXPECT_EQ(int_of(enc.returned[n]), static_cast<int>(returned.last[n]))
            << where << " node " << n;
      }
      for (std::size_t l = 0; l < leaves.size(); ++l)
        EXPECT_EQ(int_of(enc.next.elapsed[l]), m.choice->elapsed()[l]) << where << " leaf " << l;
      EXPECT_EQ(enc.next.wake[0].simplify().is_true(), after.wake_up) << where;
      EXPECT_TRUE(enc.overflow.simplify().is_false()) << where;
      EXPECT_TRUE(enc.error.simplify().is_false()) << where;  // the tick did not throw
      // Properties read the values after the tick (before the environment's next choice).
      std::vector<monitor::Val> frame;
      m.observables->fill(frame);
      m.fill_state(frame);
      bool allowed = assumed;
      std::size_t base = 0;  // enc.inputs holds the atoms of each monitored property
      for (std::size_t p = 0; p < m.properties.size(); ++p) {
        const auto& prop = m.properties[p];
        if (!prop.layout) continue;
        bool inputs[prove::Property::kMaxAtoms] = {};
        prop.read_atoms(frame, inputs, static_cast<std::uint64_t>(t + 1));
        for (std::size_t k = 0; k < prop.atoms.size(); ++k)
          EXPECT_EQ(enc.inputs[base + k].simplify().is_true(), inputs[k])
              << where << " " << prop.requirement->id << " input " << k;
        base += prop.atoms.size();
        std::vector<std::uint64_t> w(monitors.begin() + prop.offset,
                                     monitors.begin() + prop.offset + prop.layout->words());
        std::vector<char> scratch;
        const bool now = prop.layout->step(inputs, w, scratch);
        std::copy(w.begin(), w.end(), monitors.begin() + prop.offset);
        EXPECT_EQ(int_of(enc.next.monitor[p]), *sym.table(p)->index_of(w)) << where;
        const bool done = runtime::is_completed(root);
        const bool fails = !now && (monitor::verdict_is_final_once_violated(prop.shape) || done);
        if (prop.assumption) {
          allowed = allowed && !fails;
        } else {
          EXPECT_EQ(enc.fails[p].simplify().is_true(), fails)
              << where << " " << prop.requirement->id;
          // Its trigger as the explicit engine reads it (first_trigger).
          EXPECT_EQ(enc.triggered[p].simplify().is_true(),
                    prop.has_trigger() && prop.triggered(scratch))
              << where << " " << prop.requirement->id;
        }
      }
      for (std::size_t v = 0; v < m.vars.size(); ++v) {
        if (!sym.tracked(v)) continue;
        EXPECT_EQ(sym.value(z3::model(ctx), enc.next.values[v], v).to_string(),
                  m.vars[v].env ? m.vars[v].values.front().to_string()
                                : m.engine->blackboard().value(m.vars[v].slot).to_string())
            << where << " " << m.vars[v].name;
      }
      EXPECT_EQ(enc.valid.simplify().is_true(), allowed) << where;
      if (runtime::is_completed(root) || !allowed) break;
      // The environment's variables go back to their first value, as between explicit states.
      for (const auto& v : m.vars)
        if (v.relevant && v.env) m.engine->blackboard().value(v.slot) = v.values.front();
    }
  }
}

// A decision structure (optimized), ticked once (IfThenElse) or re-checked every tick
// (WhileDoElse, a node declared reactive): both engines read the same `.selected` and node
// statuses, and the symbolic tick equals the engine's.
TEST(SymbolicAgreement, OptimizedSelectionsInBothReactivities) {
  for (const bool reactive : {false, true}) {
    auto files = lunar_traverse();
    files["mission.xml"] = with_reactivity(files["mission.xml"], reactive);
    TempMission m(files);
    const Gated g(m.dir(), compile::SelectionStyle::optimized);
    ASSERT_TRUE(g.ok());
    const std::string xml = g.outcome->compiled_xml;
    EXPECT_NE(
        xml.find(reactive ? "<WhileDoElse name=\"traverse\">" : "<IfThenElse name=\"traverse\">"),
        std::string::npos)
        << xml;
    const prove::Result e = g.prove("explicit"), s = g.prove("symbolic");
    EXPECT_EQ(s.engine, "symbolic");
    expect_same_answers(e, s, reactive ? "reactive" : "plain");
    EXPECT_EQ(answer(s, "CrawlSelected").verdict, Verdict::proved);
    EXPECT_EQ(answer(s, "WaitInShadow").verdict, reactive ? Verdict::proved : Verdict::violated);
    check_ticks(g, 5, 40, 12);
  }
}

// Two nodes with one ID (sample_drilling's drills without their names): `Drill.running` is any
// of them for both engines.
TEST(SymbolicAgreement, ALabelTwoNodesShareMeansAnyOfThem) {
  TempMission unnamed(unnamed_drills());
  const Gated g(unnamed.dir()), shipped(mission_dir("sample_drilling"));
  ASSERT_TRUE(g.ok() && shipped.ok());
  const prove::Result e = g.prove("explicit");
  expect_same_answers(e, g.prove("symbolic"), "unnamed drills");
  expect_same_answers(e, shipped.prove("explicit"), "unnamed against named drills");
}

TEST(SymbolicTick, EqualsEngineTickOnCuriosity) {
  for (auto style : {compile::SelectionStyle::sequence, compile::SelectionStyle::reactive}) {
    const Gated g(mission_dir("msl_curiosity"), style);
    ASSERT_TRUE(g.ok());
    check_ticks(g, 7, 40, 12);
  }
}

TEST(SymbolicTick, EqualsEngineTickWithWakeUps) {
  const Gated g(mission_dir("sample_drilling"));
  ASSERT_TRUE(g.ok());
  check_ticks(g, 11, 60, 14);
}

// Every node kind of the subset occurs in these trees: an encoding that breaks any one kind
// (a swapped branch, a missed halt, a wrong counter) makes some tick differ.
TEST(SymbolicTick, EqualsEngineTickOnRandomMissions) {
  int checked = 0;
  std::set<std::string> kinds;
  for (unsigned seed = 1000; checked < 60 && seed < 1300; ++seed) {
    RandomMission r(seed);
    TempMission m(r.files);
    const Gated g(m.dir());
    if (!g.ok()) continue;
    kinds.insert(r.kinds.begin(), r.kinds.end());
    check_ticks(g, seed, 10, 8);
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << r.files["mission.xml"] << r.files["world.json"];
      return;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 60);
  EXPECT_EQ(kinds.size(), 17u);
}

// --- Wide worlds: what the explicit engine refuses.

std::map<std::string, std::string> wide_mission() {
  return {{"mission.xml", mission_with(R"(    <ReactiveSequence>
      <ScriptCondition code="speed &lt; 9.5"/>
      <IfThenElse>
        <ScriptCondition code="x &gt;= 2"/>
        <Act0/>
        <Sequence><Script code="y = x + 1"/><Act1/></Sequence>
      </IfThenElse>
    </ReactiveSequence>)")},
          {"domain.fret",
           "integer x in [0, 100000]\ninteger y in [0, 100001]\nreal speed in [0, 10]\n"},
          {"requirements.fret",
           "Slow: Mission shall always satisfy Act1.running -> speed < 9.5\n"
           "Small: Mission shall always satisfy x < 4\n"},
          {"world.json", R"({"initial": "x = 0", "actions": {
             "Act0": {"ticks": [1, 2], "results": ["success", "failure"]},
             "Act1": {"ticks": 2, "results": ["success"]}}})"}};
}

TEST(SymbolicWide, AnswersWhereTheExplicitEngineRefuses) {
  TempMission m(wide_mission());
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  EXPECT_THROW(g.prove("explicit"), prove::ProveError);
  const prove::Result r = g.prove("auto");
  EXPECT_EQ(r.engine, "symbolic");
  EXPECT_EQ(answer(r, "Slow").verdict, Verdict::proved);
  const prove::Answer& small = answer(r, "Small");
  ASSERT_EQ(small.verdict, Verdict::violated);
  // x is the environment's (no action or script writes it): it may jump to 4 before tick 2 at the
  // earliest, since the first tick starts at x = 0.
  EXPECT_EQ(small.counterexample->tick, 2u);
  // The scenario replays on the runtime to the same violation.
  runtime::Scenario s = runtime::parse_scenario(small.counterexample->scenario, "cex.json");
  runtime::Runner runner(*g.doc, s);
  const runtime::RunResult run = runner.run();
  EXPECT_EQ(run.ticks, 2u);
  const runtime::ScriptValue* x = runner.engine().blackboard().get("x");
  ASSERT_NE(x, nullptr);
  EXPECT_GE(x->integer, 4);
  const auto scenario = nlohmann::json::parse(small.counterexample->scenario);
  EXPECT_TRUE(scenario["initial"]["speed"].is_number_float());
}

TEST(SymbolicWide, UnmodelledNodeIsDeclinedWithItsPlace) {
  auto files = wide_mission();
  files["mission.xml"] =
      mission_with("    <RetryUntilSuccessful num_attempts=\"2\"><Act0/></RetryUntilSuccessful>");
  TempMission m(files);
  const Gated g(m.dir());
  ASSERT_TRUE(g.ok());
  try {
    g.prove("symbolic");
    FAIL() << "no error";
  } catch (const prove::ProveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("RetryUntilSuccessful"), std::string::npos) << what;
    EXPECT_NE(what.find("compiled.xml:4:5: RetryUntilSuccessful"), std::string::npos) << what;
  }
  // x meets only constants here (`x < 4`, `x = 0`): the explicit engine cuts its range into
  // cells and answers, so auto does not need the symbolic engine.
  const prove::Result r = g.prove("auto");
  EXPECT_EQ(r.engine, "explicit");
  EXPECT_EQ(answer(r, "Small").verdict, Verdict::violated);
  EXPECT_EQ(answer(r, "Small").depth, 2u);
}

}  // namespace
}  // namespace uabt::testing
