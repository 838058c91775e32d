// The explicit engine's on-demand environment (ARCHITECTURE §10.1): values chosen when first read,
// numeric variables branched over the cells their atoms draw, and proofs that cannot be vacuous.
#include <nlohmann/json.hpp>

#include "fretish/parse.hpp"
#include "monitor/monitor.hpp"
#include "prove/cells.hpp"
#include "prove_support.hpp"
#include "runtime/script/program.hpp"

namespace uabt::testing {
namespace {

using prove::Verdict;
using runtime::ScriptValue;
using verify::detail::Fraction;

constexpr auto kReactive = compile::SelectionStyle::reactive;

fretish::Variable variable(fretish::VarType type, std::string lower, std::string upper) {
  fretish::Variable v;
  v.name = "x";
  v.type = type;
  v.lower = std::move(lower);
  v.upper = std::move(upper);
  return v;
}

std::vector<std::string> texts(const std::vector<ScriptValue>& values) {
  std::vector<std::string> out;
  for (const auto& v : values) out.push_back(v.to_string());
  return out;
}

TEST(Cells, ARealIsCutAtEveryBreakpointWithRoundValuesInside) {
  const auto values =
      prove::cell_values(variable(fretish::VarType::real, "0", "30"), {Fraction(10), Fraction(15)});
  // Points 0, 10, 15, 30 and one value inside each open interval, an integer near its middle.
  EXPECT_EQ(texts(values),
            (std::vector<std::string>{"0.0", "5.0", "10.0", "12.0", "15.0", "22.0", "30.0"}));
}

TEST(Cells, AnIntervalWithoutAnIntegerGetsItsMiddle) {
  const auto values = prove::cell_values(variable(fretish::VarType::real, "0.1", "0.2"), {});
  EXPECT_EQ(texts(values), (std::vector<std::string>{"0.1", "0.15", "0.2"}));
}

TEST(Cells, IntegerCellsHoldIntegersOnly) {
  auto v = variable(fretish::VarType::integer, "1", "10");
  EXPECT_EQ(texts(prove::cell_values(v, {Fraction(5)})),
            (std::vector<std::string>{"1", "3", "5", "7", "10"}));
  // A breakpoint between two integers is no cell of its own; (1, 2.5) holds only 2.
  EXPECT_EQ(texts(prove::cell_values(v, {*Fraction::parse("2.5")})),
            (std::vector<std::string>{"1", "2", "6", "10"}));
  // Adjacent breakpoints leave no integer between them.
  EXPECT_EQ(texts(prove::cell_values(v, {Fraction(4), Fraction(5)})),
            (std::vector<std::string>{"1", "2", "4", "5", "7", "10"}));
}

TEST(Cells, AnUnboundedRealGetsAValueBeyondEachEnd) {
  const auto values = prove::cell_values(variable(fretish::VarType::real, "", ""), {Fraction(0)});
  EXPECT_EQ(texts(values), (std::vector<std::string>{"-1.0", "0.0", "1.0"}));
}

fretish::ExprPtr expression(const std::string& text) {
  std::vector<Finding> findings;
  auto e = fretish::parse_expression(text, fretish::TextOrigin{"t", 1, 1}, findings);
  EXPECT_TRUE(e) << text;
  return e;
}

// The names the scripts below read: a script is cut by its reading, which the domain types.
const fretish::Domain& script_domain() {
  static const fretish::Domain domain = [] {
    fretish::Domain d;
    std::vector<Finding> findings;
    fretish::parse_domain_file(
        "integer battery, depth, reserve, level\nreal slope, wind\n"
        "enum terrain in {sand, rocks, mud, ice, flat}\n",
        "domain.fret", findings)
        .variables.swap(d.variables);
    EXPECT_TRUE(findings.empty());
    return d;
  }();
  return domain;
}

TEST(Cuts, LinearAtomsOverOneVariableGiveBreakpoints) {
  prove::Cuts cuts({"slope", "battery"});
  cuts.add(*expression("slope < 10 & 2 * slope + 1 >= 31 & !(battery - 40 > 0)"), "here");
  EXPECT_EQ(cuts.breaks("slope"), (std::set<Fraction>{Fraction(10), Fraction(15)}));
  EXPECT_EQ(cuts.breaks("battery"), (std::set<Fraction>{Fraction(40)}));
  EXPECT_EQ(cuts.uncut("slope"), "");
  EXPECT_EQ(cuts.uncut("battery"), "");
}

TEST(Cuts, AnAtomOverTwoVariablesOrACopyCannotBeCut) {
  prove::Cuts cuts({"slope", "battery", "wind"});
  cuts.add(*expression("slope > battery"), "requirements.fret:3:1");
  EXPECT_NE(cuts.uncut("slope").find("requirements.fret:3:1"), std::string::npos)
      << cuts.uncut("slope");
  EXPECT_NE(cuts.uncut("battery"), "");
  const auto copy = runtime::script::Program::parse("reserve = wind * 2");
  cuts.add(copy, script_domain(), "an effect");
  EXPECT_NE(cuts.uncut("wind").find("reserve = wind * 2"), std::string::npos) << cuts.uncut("wind");
}

TEST(Cuts, ScriptComparisonsWithConstantsGiveBreakpoints) {
  prove::Cuts cuts({"wind", "battery"});
  cuts.add(runtime::script::Program::parse("@wind < 15 && battery > 10 && 'flat' == terrain"),
           script_domain(), "a guard");
  EXPECT_EQ(cuts.breaks("wind"), (std::set<Fraction>{Fraction(15)}));
  EXPECT_EQ(cuts.breaks("battery"), (std::set<Fraction>{Fraction(10)}));
  EXPECT_EQ(cuts.uncut("wind"), "");
}

// A script is cut where the engine changes its truth, by the one reading of scripts: BT.CPP's
// `==` on a real holds within float epsilon (2^-23) of equal, so its cells end there, and a
// comparison chain is every link's atom.
TEST(Cuts, AScriptIsCutWhereTheEngineChangesItsTruth) {
  prove::Cuts cuts({"slope", "wind"});
  cuts.add(runtime::script::Program::parse("slope == 0.5"), script_domain(), "a guard");
  cuts.add(runtime::script::Program::parse("-15 <= wind <= 15"), script_domain(), "a guard");
  EXPECT_EQ(cuts.breaks("slope"),
            (std::set<Fraction>{*Fraction::parse("0.49999988079071044921875"),
                                *Fraction::parse("0.50000011920928955078125")}));
  EXPECT_EQ(cuts.breaks("wind"), (std::set<Fraction>{Fraction(-15), Fraction(15)}));
  EXPECT_EQ(cuts.uncut("slope"), "");
  EXPECT_EQ(cuts.uncut("wind"), "");
}

// A long run of an integer's comparisons with numerals is cut only where the run's truth can
// change (the ends of the union of its ranges), in a requirement and in a generated Fallback of
// ScriptConditions alike; a short run is cut at every numeral, and a real variable's comparisons
// are never merged as integers.
TEST(Cuts, ALongRunOfAnIntegersComparisonsIsCutAtTheEndsOfItsRanges) {
  std::string fretish_run, script_run;
  for (int k = 0; k < 20; ++k) {
    fretish_run += (k ? " | depth = " : "depth = ") + std::to_string(k);
    script_run += (k ? " || depth == " : "depth == ") + std::to_string(k);
  }
  prove::Cuts from_requirement({"depth", "wind"}, {}, {"depth"});
  from_requirement.add(*expression("flag & (" + fretish_run +
                                   " | 40 <= depth & depth <= 50 | depth > 60 | wind < 3)"),
                       "requirements.fret:2:5");
  // `40 <= depth & depth <= 50` is a conjunction, not a comparison: cut as written (40, 50).
  EXPECT_EQ(
      from_requirement.breaks("depth"),
      (std::set<Fraction>{Fraction(0), Fraction(19), Fraction(40), Fraction(50), Fraction(61)}));
  EXPECT_EQ(from_requirement.breaks("wind"), (std::set<Fraction>{Fraction(3)}));
  EXPECT_EQ(from_requirement.uncut("depth"), "");

  // The ScriptConditions of a generated Fallback: one disjunction, one condition each.
  std::vector<runtime::script::Program> conditions;
  for (int k = 0; k < 20; ++k)
    conditions.push_back(runtime::script::Program::parse("depth == " + std::to_string(k)));
  conditions.push_back(runtime::script::Program::parse("40 == depth"));
  conditions.push_back(runtime::script::Program::parse("depth >= 41 && depth < 61"));
  std::vector<const runtime::script::Program*> programs;
  for (const auto& c : conditions) programs.push_back(&c);
  prove::Cuts from_fallback({"depth"}, {}, {"depth"});
  from_fallback.add_any_of(programs, script_domain(), "a selection Fallback");
  EXPECT_EQ(
      from_fallback.breaks("depth"),
      (std::set<Fraction>{Fraction(0), Fraction(19), Fraction(40), Fraction(41), Fraction(61)}));
  EXPECT_EQ(from_fallback.uncut("depth"), "");
  prove::Cuts few({"depth"}, {}, {"depth"});
  few.add_any_of({programs.begin(), programs.begin() + 3}, script_domain(), "a selection Fallback");
  EXPECT_EQ(few.breaks("depth"), (std::set<Fraction>{Fraction(0), Fraction(1), Fraction(2)}));

  prove::Cuts short_run({"depth"}, {}, {"depth"});
  short_run.add(*expression("depth = 1 | depth = 2 | depth = 3"), "requirements.fret:3:5");
  EXPECT_EQ(short_run.breaks("depth"), (std::set<Fraction>{Fraction(1), Fraction(2), Fraction(3)}));

  prove::Cuts real_run({"depth"});  // a real: every numeral is a breakpoint
  real_run.add(*expression(fretish_run), "requirements.fret:4:5");
  EXPECT_EQ(real_run.breaks("depth").size(), 20u);
}

// An atom that compares an environment variable with the mission's own state is cut in each
// state at hand: the Cuts keep it whole, to be cut when the variable is chosen.
TEST(Cuts, AnAtomWithTheMissionsStateIsCutInTheStateAtHand) {
  prove::Cuts cuts({"battery", "slope"}, {"reserve", "level"});
  cuts.add(*expression("battery >= reserve + 20 & 2 * battery < 3 * level - 1 & slope < 10"),
           "requirements.fret:4:1");
  cuts.add(runtime::script::Program::parse("battery > @reserve"), script_domain(), "a guard");
  EXPECT_EQ(cuts.uncut("battery"), "");
  EXPECT_EQ(cuts.breaks("slope"), (std::set<Fraction>{Fraction(10)}));
  const auto& mixed = cuts.mixed("battery");
  ASSERT_EQ(mixed.size(), 3u);
  // battery - reserve - 20 >= 0: the breakpoint is reserve + 20.
  EXPECT_EQ(mixed[0].terms, (std::vector<std::pair<std::string, Fraction>>{{"reserve", -1}}));
  EXPECT_EQ(mixed[0].b, Fraction(-20));
  EXPECT_EQ(mixed[0].where, "the atom `battery >= reserve + 20` (requirements.fret:4:1)");
  // 2 battery - 3 level + 1 < 0: battery - 3/2 level + 1/2, the breakpoint 3/2 level - 1/2.
  EXPECT_EQ(mixed[1].terms,
            (std::vector<std::pair<std::string, Fraction>>{{"level", Fraction::of(-3, 2)}}));
  EXPECT_EQ(mixed[1].b, Fraction::of(1, 2));
  EXPECT_EQ(mixed[2].terms, (std::vector<std::pair<std::string, Fraction>>{{"reserve", -1}}));
  // An assumption's atom is read with the tick's starting state.
  cuts.add(*expression("battery <= reserve + 70"), "domain.fret:3:8", true);
  EXPECT_TRUE(cuts.mixed("battery").back().at_tick_start);
}

TEST(Cuts, WhatTheStateAtHandCannotCutStaysUncut) {
  const auto uncut = [](const std::string& atom) {
    prove::Cuts cuts({"battery", "slope"}, {"reserve"});
    cuts.add(*expression(atom), "requirements.fret:2:5");
    return cuts.uncut("battery");
  };
  // Not linear in the variable, or related to another variable of the environment.
  EXPECT_EQ(uncut("battery * reserve > 30"),
            "the atom `battery * reserve > 30` (requirements.fret:2:5) does not compare it with "
            "a constant or with the mission's own state");
  EXPECT_NE(uncut("battery > slope + reserve"), "");
  // An effect that copies the variable into the mission's state.
  prove::Cuts cuts({"battery"}, {"reserve"});
  cuts.add(runtime::script::Program::parse("reserve = battery - 5"), script_domain(), "an effect");
  EXPECT_NE(cuts.uncut("battery").find("reserve = battery - 5"), std::string::npos)
      << cuts.uncut("battery");
}

// Why the explicit engine refuses the mission in `dir` ("" and a failure when it does not).
std::string explicit_refusal(const std::filesystem::path& dir) {
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  try {
    prove_dir(dir, explicit_engine);
  } catch (const prove::ProveError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the explicit engine cut an atom over two variables of the environment";
  return "";
}

// A guard compares the battery with a reserve the mission's effects raise; the guarantee reads
// both after the tick. The breakpoint is where the reserve is when the guard reads the battery
// (10), and again where the effect leaves it before the monitor reads them (30): a battery in
// (10, 30) passes the guard and violates the guarantee. The explicit engine, which left such a
// mission to the symbolic engine, now proves it, with the symbolic engine's verdict.
std::map<std::string, std::string> reserve_mission(const std::string& guard) {
  std::map<std::string, std::string> files;
  files["mission.xml"] = mission_with("<Sequence><ScriptCondition code=\"" + guard +
                                      "\"/><Adaptable ID=\"work\"/></Sequence>");
  files["alternatives/work/bump.xml"] = alternative_tree("bump", "<Bump/>");
  files["alternatives/work/rest.xml"] = alternative_tree("rest", "<Rest/>");
  files["domain.fret"] =
      "real battery in [0, 100]\n"
      "integer reserve in [0, 50]\n"
      "integer load in [-1000000, 1000000]\n"
      "assume spare: battery <= reserve + 80\n";
  files["requirements.fret"] =
      "Bump: In work if load > 100 * reserve - 500 Mission shall satisfy selected_alt = bump\n"
      "Rest: In work Mission shall satisfy selected_alt = rest\n"
      "Charged: Mission shall always satisfy Bump.success -> battery >= reserve\n"
      "Light: Mission shall always satisfy Rest.success -> load <= 100 * reserve - 500\n";
  files["world.json"] =
      R"({"initial": "reserve = 10", "actions": {"Bump": {"ticks": 1, "results": ["success"],)"
      R"( "on_success": "reserve = reserve < 30 ? 30 : 10"}, "Rest": {"ticks": 1, "results":)"
      R"( ["success"]}}})";
  return files;
}

TEST(OnDemand, AnAtomWithTheMissionsStateIsCutInTheStateAtHand) {
  TempMission m(reserve_mission("battery &gt; reserve"));
  prove::Options explicit_engine, symbolic_engine;
  explicit_engine.engine = "explicit";
  symbolic_engine.engine = "symbolic";
  const prove::Result e = prove_dir(m.dir(), explicit_engine);
  EXPECT_TRUE(e.complete);
  const prove::Answer& charged = answer(e, "Charged");
  ASSERT_EQ(charged.verdict, Verdict::violated);
  EXPECT_EQ(charged.depth, 1u);
  ASSERT_TRUE(charged.counterexample);
  // A value inside the cell (10, 30), written as people write it; the replay (prove's own)
  // violates it too.
  const auto scenario = nlohmann::json::parse(charged.counterexample->scenario);
  const double battery = scenario["initial"]["battery"].get<double>();
  EXPECT_GT(battery, 10.0) << charged.counterexample->scenario;
  EXPECT_LT(battery, 30.0) << charged.counterexample->scenario;
  EXPECT_EQ(scenario["initial"]["battery"].dump(), "20") << charged.counterexample->scenario;
  // The wide integer compared with 100 reserve - 500: at most 500 (reserve 10) or 2500.
  EXPECT_EQ(answer(e, "Light").verdict, Verdict::proved);
  // auto takes the explicit engine now.
  EXPECT_EQ(prove_dir(m.dir()).engine, "explicit");
  const prove::Result s = prove_dir(m.dir(), symbolic_engine);
  ASSERT_EQ(e.answers.size(), s.answers.size());
  for (std::size_t i = 0; i < e.answers.size(); ++i) {
    EXPECT_EQ(e.answers[i].verdict, s.answers[i].verdict) << e.answers[i].requirement;
    if (e.answers[i].verdict == Verdict::violated) {
      EXPECT_EQ(e.answers[i].depth, s.answers[i].depth) << e.answers[i].requirement;
    }
  }
  // With `>=` the guard's breakpoint itself (10) passes it and violates the guarantee.
  TempMission at(reserve_mission("battery &gt;= reserve"));
  const prove::Result at_result = prove_dir(at.dir(), explicit_engine);
  const prove::Answer& at_breakpoint = answer(at_result, "Charged");
  ASSERT_EQ(at_breakpoint.verdict, Verdict::violated);
  ASSERT_TRUE(at_breakpoint.counterexample);
  EXPECT_EQ(
      nlohmann::json::parse(at_breakpoint.counterexample->scenario)["initial"]["battery"].dump(),
      "10");
}

// The same mission where Bump may fail, and its failure is explored first: the battery's cell
// is cut again only on the second outcome, success, whose tick the engine resumes at Bump's
// outcome instead of ticking it again from its start. The resumed tick must still watch the
// battery chosen before that point, or the cell (10, 90) is never cut at 30 and the violation
// is missed.
TEST(OnDemand, ACellIsCutAgainInATickResumedAtAnActionsOutcome) {
  auto files = reserve_mission("battery &gt; reserve");
  files["world.json"] =
      R"({"initial": "reserve = 10", "actions": {"Bump": {"ticks": 1, "results": ["failure",)"
      R"( "success"], "on_success": "reserve = reserve < 30 ? 30 : 10"}, "Rest": {"ticks": 1,)"
      R"( "results": ["success"]}}})";
  TempMission m(files);
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  const prove::Result e = prove_dir(m.dir(), explicit_engine);
  const prove::Answer& charged = answer(e, "Charged");
  ASSERT_EQ(charged.verdict, Verdict::violated);
  EXPECT_EQ(charged.depth, 1u);
  ASSERT_TRUE(charged.counterexample);
  EXPECT_EQ(nlohmann::json::parse(charged.counterexample->scenario)["initial"]["battery"].dump(),
            "20")
      << charged.counterexample->scenario;
}

// An atom that relates the variable to another of the environment still goes to the symbolic
// engine, and the reason names it.
TEST(OnDemand, AnAtomWithAnotherEnvironmentVariableStillGoesToTheSymbolicEngine) {
  auto files = reserve_mission("battery &gt; reserve");
  files["domain.fret"] += "real solar in [0, 100]\n";
  files["requirements.fret"] +=
      "Sun: Mission shall always satisfy solar < battery + reserve | Bump.success\n";
  TempMission m(files);
  const std::string why = explicit_refusal(m.dir());
  EXPECT_NE(why.find("cannot cut real"), std::string::npos) << why;
  EXPECT_NE(why.find("the atom `solar < battery + reserve` (requirements.fret:5:"),
            std::string::npos)
      << why;
}

TEST(Cuts, AnEnumComparedWithItsValuesNamesThem) {
  prove::Cuts cuts({}, {}, {}, {{"terrain", {"sand", "rocks", "mud", "ice"}}});
  cuts.add(*expression("terrain = rocks | !(sand != terrain)"), "requirements.fret:2:1");
  cuts.add(runtime::script::Program::parse("terrain == 'mud' && 'rocks' != @terrain"),
           script_domain(), "a guard");
  EXPECT_EQ(cuts.named("terrain"), (std::set<std::string, std::less<>>{"mud", "rocks", "sand"}));
  EXPECT_EQ(cuts.uncut("terrain"), "");
}

TEST(Cuts, AnEnumReadAnyOtherWayIsNotCut) {
  const auto uncut = [](auto add) {
    prove::Cuts cuts({}, {}, {}, {{"terrain", {"sand", "rocks"}}});
    add(cuts);
    return cuts.uncut("terrain");
  };
  // Compared with another variable, copied by a script, compared by order, read as a condition.
  EXPECT_NE(uncut([](prove::Cuts& c) { c.add(*expression("terrain = seen_terrain"), "r:1:1"); })
                .find("`terrain` is read outside an atom that compares it with one of its values "
                      "(r:1:1)"),
            std::string::npos);
  EXPECT_NE(uncut([](prove::Cuts& c) {
              c.add(runtime::script::Program::parse("last := terrain"), script_domain(),
                    "an effect");
            }).find("last := terrain"),
            std::string::npos);
  EXPECT_NE(uncut([](prove::Cuts& c) {
              c.add(runtime::script::Program::parse("terrain < 'sand'"), script_domain(),
                    "a guard");
            }),
            "");
  EXPECT_NE(uncut([](prove::Cuts& c) { c.add_truth_read("terrain", "condition terrain"); }), "");
  // A value the enum does not declare names no cell.
  EXPECT_NE(uncut([](prove::Cuts& c) { c.add(*expression("terrain = lava"), "r:1:1"); }), "");
}

TEST(Cells, AnEnumKeepsItsNamedValuesAndTheFirstUnnamedOneInDeclarationOrder) {
  fretish::Variable terrain = variable(fretish::VarType::enumeration, "", "");
  terrain.enum_values = {"dust", "sand", "rocks", "mud", "ice"};
  EXPECT_EQ(texts(prove::enum_cell_values(terrain, {"rocks", "ice"})),
            (std::vector<std::string>{"dust", "rocks", "ice"}));
  EXPECT_EQ(texts(prove::enum_cell_values(terrain, {"dust", "sand", "rocks", "mud", "ice"})),
            (std::vector<std::string>{"dust", "sand", "rocks", "mud", "ice"}));
  EXPECT_EQ(texts(prove::enum_cell_values(terrain, {})), (std::vector<std::string>{"dust"}));
}

// The exploration mission with its terrain widened to `values` values: the guards name three,
// the guarantee none of the others. `copy`: a script of the tree also copies the terrain, which
// reads every value apart.
std::map<std::string, std::string> wide_terrain(int values, bool copy) {
  auto files = mission_files("exploration");
  std::string names = "sand, rocks, unknown";
  for (int i = 3; i < values; ++i) names += ", t" + std::to_string(i);
  files["domain.fret"] =
      "integer battery in [0, 100]\nreal slope in [-45, 45]\nenum terrain in {" + names + "}\n";
  files["requirements.fret"] +=
      "Known: Mission shall always satisfy terrain = sand | terrain = rocks | terrain = unknown\n";
  if (copy) {
    const std::string root = "<BehaviorTree ID=\"MainTree\">";
    auto& xml = files["mission.xml"];
    const auto at = xml.find(root);
    EXPECT_NE(at, std::string::npos);
    xml.insert(xml.find('<', at + root.size()), "<Sequence><Script code=\"seen := terrain\"/>");
    xml.insert(xml.find("</BehaviorTree>", at), "</Sequence>");
  }
  files["world.json"] = R"({"actions": {}})";
  return files;
}

// Values no atom names are one cell: the search over 4,000 terrains is the search over four,
// and the counterexample shows the first unnamed value.
TEST(OnDemand, EnumValuesNoAtomNamesAreOneCell) {
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  TempMission narrow(wide_terrain(4, false)), wide(wide_terrain(4000, false));
  const prove::Result n = prove_dir(narrow.dir(), explicit_engine);
  const prove::Result w = prove_dir(wide.dir(), explicit_engine);
  EXPECT_EQ(w.states, n.states);
  EXPECT_EQ(w.transitions, n.transitions);
  for (const prove::Result* r : {&n, &w}) {
    const prove::Answer& known = answer(*r, "Known");
    ASSERT_EQ(known.verdict, Verdict::violated);
    EXPECT_EQ(known.depth, 1u);
    ASSERT_TRUE(known.counterexample);
    EXPECT_EQ(nlohmann::json::parse(known.counterexample->scenario)["initial"]["terrain"], "t3");
  }
  // A script that copies the terrain tells every value apart: each is taken.
  TempMission copied(wide_terrain(40, true));
  const prove::Result c = prove_dir(copied.dir(), explicit_engine);
  EXPECT_EQ(answer(c, "Known").verdict, Verdict::violated);
  EXPECT_GT(c.transitions, n.transitions * 5) << c.transitions << " against " << n.transitions;
}

// msl_curiosity with Req1's guard `OnDust & <depth>` over an integer depth.
std::map<std::string, std::string> deep_dust(const std::string& depth) {
  auto files = mission_files("msl_curiosity");
  files["domain.fret"] += "integer depth in [0, 100000]\n";
  auto& requirements = files["requirements.fret"];
  const std::string guard = "if OnDust Mission";
  const auto at = requirements.find(guard);
  EXPECT_NE(at, std::string::npos);
  requirements.replace(at, guard.size(), "if OnDust & (" + depth + ") Mission");
  return files;
}

// The compiler writes a guard's disjuncts as the ScriptConditions of a Fallback in the
// selection tree. No property sees those nodes, so 40 disjuncts `depth = k` are the cells of
// the one range they make: the search is the search over `0 <= depth & depth <= 39`.
TEST(OnDemand, ALongDisjunctionOfAGuardIsTheCellsOfItsRange) {
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  std::string run;
  for (int k = 0; k < 40; ++k) run += (k ? " | depth = " : "depth = ") + std::to_string(k);
  TempMission disjuncts(deep_dust(run)), range(deep_dust("0 <= depth & depth <= 39"));
  const prove::Result d = prove_dir(disjuncts.dir(), explicit_engine);
  const prove::Result r = prove_dir(range.dir(), explicit_engine);
  EXPECT_EQ(d.states, r.states);
  EXPECT_EQ(d.transitions, r.transitions);
  ASSERT_EQ(d.answers.size(), r.answers.size());
  ASSERT_FALSE(d.answers.empty());
  for (std::size_t i = 0; i < d.answers.size(); ++i) {
    EXPECT_EQ(d.answers[i].verdict, r.answers[i].verdict) << i;
    EXPECT_EQ(d.answers[i].depth, r.answers[i].depth) << i;
  }
}

TEST(Numbers, PrintAsPeopleWriteThem) {
  // What counterexample tables, the HTML timeline and run's violation lines show.
  monitor::Symbols symbols;
  auto text = [&](double x) {
    return monitor::value_of(monitor::Val::of_number(x), symbols).to_string();
  };
  EXPECT_EQ(text(50), "50");
  EXPECT_EQ(text(10), "10");
  EXPECT_EQ(text(9.5), "9.5");
  EXPECT_EQ(text(0.1), "0.1");
  EXPECT_EQ(text(-3), "-3");
  EXPECT_EQ(text(12.5), "12.5");
  EXPECT_EQ(text(1e22), "1e+22");
}

// planetary_landing with a world and guarantees: a real (wind), an integer (battery) and an
// enum (terrain), all environment variables that only meet constants.
std::map<std::string, std::string> landing_with_guarantees() {
  auto files = mission_files("planetary_landing");
  files["requirements.fret"] +=
      "HoverOnlyInWind: Mission shall always satisfy landing.selected = hover_and_wait -> wind "
      ">= 15\n"
      "NeverHover: Mission shall always satisfy landing.selected != hover_and_wait\n"
      "LowTouchdown: Mission shall always satisfy landing.selected = direct_touchdown -> battery "
      "<= 10\n";
  files["world.json"] =
      R"({"actions": {"JettisonHeatShield": {"ticks": 1, "results": ["success"]},
                      "DeployParachute": {"ticks": 1, "results": ["success"]},
                      "ClassifyTerrain": {"ticks": 1, "results": ["success"]}}})";
  return files;
}

TEST(OnDemand, RealsAreProvedByTheExplicitEngine) {
  TempMission m(landing_with_guarantees());
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  // Reactive: the guards are re-checked every tick (in the sequence style a started hover runs
  // on after the wind drops, and HoverOnlyInWind is violated).
  const prove::Result r = prove_dir(m.dir(), explicit_engine, kReactive);
  EXPECT_EQ(r.engine, "explicit");
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(answer(r, "HoverOnlyInWind").verdict, Verdict::proved);
  EXPECT_EQ(answer(r, "LowTouchdown").verdict, Verdict::proved);
  const prove::Answer& never = answer(r, "NeverHover");
  ASSERT_EQ(never.verdict, Verdict::violated);
  ASSERT_TRUE(never.counterexample);
  // The counterexample picks a value inside each cell, written as the domain writes numbers.
  const auto scenario = nlohmann::json::parse(never.counterexample->scenario);
  const double wind = scenario["initial"]["wind"].get<double>();
  const std::int64_t battery = scenario["initial"]["battery"].get<std::int64_t>();
  EXPECT_GE(wind, 15.0);
  EXPECT_GT(battery, 10);
  bool shown = false;
  for (const auto& [name, value] : never.counterexample->rows.back().values)
    shown = shown || name == "landing.selected";
  EXPECT_TRUE(shown);
  // auto takes the explicit engine for such a world.
  EXPECT_EQ(prove_dir(m.dir(), {}, kReactive).engine, "explicit");
}

TEST(OnDemand, TheSymbolicEngineAgreesOnReals) {
  TempMission m(landing_with_guarantees());
  prove::Options explicit_engine, symbolic_engine;
  explicit_engine.engine = "explicit";
  symbolic_engine.engine = "symbolic";
  for (const auto style : {compile::SelectionStyle::sequence, kReactive}) {
    const prove::Result e = prove_dir(m.dir(), explicit_engine, style);
    const prove::Result s = prove_dir(m.dir(), symbolic_engine, style);
    ASSERT_EQ(e.answers.size(), s.answers.size());
    for (std::size_t i = 0; i < e.answers.size(); ++i) {
      EXPECT_EQ(e.answers[i].verdict, s.answers[i].verdict) << e.answers[i].requirement;
      if (e.answers[i].verdict == Verdict::violated) {
        EXPECT_EQ(e.answers[i].depth, s.answers[i].depth) << e.answers[i].requirement;
      }
    }
  }
}

TEST(OnDemand, AnAtomRelatingTwoRealsGoesToTheSymbolicEngineAndSaysWhy) {
  auto files = landing_with_guarantees();
  files["domain.fret"] += "real gust in [0, 40]\n";
  files["requirements.fret"] += "Gusty: Mission shall always satisfy gust >= wind | gust < wind\n";
  TempMission m(files);
  const std::string why = explicit_refusal(m.dir());
  EXPECT_NE(why.find("cannot cut real"), std::string::npos) << why;
  EXPECT_NE(why.find("requirements.fret:13:"), std::string::npos) << why;
}

// A pre-flight checklist whose N sensor flags the environment may flip before every tick: the
// tick reads them in order and stops at the first that fails, so the search branches N + 1
// ways per tick, never 2^N.
std::map<std::string, std::string> flags_mission(int n) {
  std::string domain = "boolean";
  std::string checks;
  for (int i = 1; i <= n; ++i) {
    domain += std::string(i == 1 ? " " : ", ") + "Ok" + std::to_string(i);
    checks += "<Fallback><Ok" + std::to_string(i) + "/><Repair name=\"repair" + std::to_string(i) +
              "\" item=\"" + std::to_string(i) + "\"/></Fallback>\n";
  }
  std::map<std::string, std::string> files;
  files["domain.fret"] = domain + "\n";
  files["mission.xml"] =
      mission_with("<KeepRunningUntilFailure><ForceSuccess><Sequence>\n" + checks +
                   "<Adaptable ID=\"go\"/>\n</Sequence></ForceSuccess></KeepRunningUntilFailure>");
  files["alternatives/go/launch.xml"] = alternative_tree("launch", "<Launch/>");
  files["requirements.fret"] =
      "Go: In go Mission shall satisfy selected_alt = launch\n"
      "CheckedLaunch: Mission shall always satisfy Launch.running -> Ok1\n"
      "RepairOnlyBroken: Mission shall always satisfy repair1.running -> !Ok1\n";
  // Repair 1 may take three ticks, so it runs on in its second tick without re-reading Ok1.
  std::string actions = R"("Launch": {"ticks": 1, "results": ["success"]})";
  for (int i = 1; i <= n; ++i)
    actions += ", \"Repair(item=" + std::to_string(i) + ")\": {\"ticks\": [1, " +
               (i == 1 ? "3" : "2") + "], \"results\": [\"success\"]}";
  files["world.json"] = "{\"actions\": {" + actions + "}}";
  return files;
}

TEST(OnDemand, FreeFlagsBranchOnlyWhereTheTickReadsThem) {
  TempMission m(flags_mission(40));
  prove::Options explicit_engine;
  explicit_engine.engine = "explicit";
  const prove::Result r = prove_dir(m.dir(), explicit_engine);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(answer(r, "CheckedLaunch").verdict, Verdict::proved);
  // Repair1 may run on for a second tick after the environment fixed the flag.
  const prove::Answer& repair = answer(r, "RepairOnlyBroken");
  ASSERT_EQ(repair.verdict, Verdict::violated);
  EXPECT_EQ(repair.depth, 2u);
  // A state is the repair in progress (none, one of 40, or repair 1 in its second tick) and the
  // monitors' words, never the flags: a few per sensor, not 2^40.
  EXPECT_LE(r.states, 2u * (40u + 2u));
  EXPECT_LT(r.transitions, 3u * 40u * 40u);
}

TEST(OnDemand, FreeFlagsAgreeWithTheSymbolicEngine) {
  TempMission m(flags_mission(3));
  prove::Options explicit_engine, symbolic_engine;
  explicit_engine.engine = "explicit";
  symbolic_engine.engine = "symbolic";
  const prove::Result e = prove_dir(m.dir(), explicit_engine);
  const prove::Result s = prove_dir(m.dir(), symbolic_engine);
  ASSERT_EQ(e.answers.size(), s.answers.size());
  for (std::size_t i = 0; i < e.answers.size(); ++i) {
    EXPECT_EQ(e.answers[i].verdict, s.answers[i].verdict) << e.answers[i].requirement;
    EXPECT_EQ(e.answers[i].depth,
              s.answers[i].verdict == Verdict::violated ? s.answers[i].depth : e.answers[i].depth);
  }
}

// --- Vacuity -------------------------------------------------------------------------------

std::map<std::string, std::string> drilling_with(const std::string& world,
                                                 const std::string& extra_domain = "") {
  auto files = mission_files("sample_drilling");
  files["alternatives/drilling/rotary.xml"] = kFixedRotary;
  files["world.json"] = world;
  files["domain.fret"] += extra_domain;
  return files;
}

const char* kDrillingActions =
    R"("actions": {"Drill": {"ticks": 1, "results": ["success"]},
                   "CoolDown": {"ticks": 1, "results": ["success"], "on_success": "IsBitCool = true"}})";

TEST(Vacuity, AnInitialConditionNoStateSatisfiesIsAnErrorAtTheExpression) {
  TempMission m(drilling_with(std::string(R"({"initial": "depth > 20", )") + kDrillingActions + "}",
                              "integer depth in [0, 10]\n"));
  const prove::Result r = prove_dir(m.dir());
  ASSERT_TRUE(r.vacuity);
  EXPECT_NE(r.vacuity->message.find("`depth > 20`"), std::string::npos) << r.vacuity->message;
  EXPECT_EQ(r.vacuity->location.file, "world.json");
  EXPECT_EQ(r.vacuity->location.line, 1);
  EXPECT_EQ(r.vacuity->location.column, 14);
  for (const auto& a : r.answers) EXPECT_EQ(a.verdict, Verdict::vacuous) << a.requirement;
  EXPECT_FALSE(r.passed());
  const auto findings = gate::findings_of(r);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].check, "prove-vacuous");
  EXPECT_EQ(findings[0].severity, Severity::error);
}

TEST(Vacuity, TheSymbolicEngineRefusesAnEmptyFirstTickToo) {
  TempMission m(drilling_with(std::string(R"({"initial": "depth > 20", )") + kDrillingActions + "}",
                              "integer depth in [0, 10]\n"));
  prove::Options symbolic_engine;
  symbolic_engine.engine = "symbolic";
  const prove::Result r = prove_dir(m.dir(), symbolic_engine);
  ASSERT_TRUE(r.vacuity);
  EXPECT_EQ(r.vacuity->location.file, "world.json");
  for (const auto& a : r.answers) EXPECT_EQ(a.verdict, Verdict::vacuous) << a.requirement;
  EXPECT_FALSE(r.passed());
}

TEST(Vacuity, AnAssumptionTheMissionBreaksIsADeadlock) {
  // The bit starts hot and the assumption says it stays hot, but CoolDown cools it: after the
  // tick that cools it, no state satisfies the assumption.
  TempMission m(drilling_with(
      R"({"initial": "!IsBitCool", "actions": {"Drill": {"ticks": 2, "results": ["success"]},
          "CoolDown": {"ticks": 1, "results": ["success"], "on_success": "IsBitCool = true"}}})",
      "assume hot: !IsBitCool\n"));
  for (const char* engine : {"explicit", "symbolic"}) {
    prove::Options options;
    options.engine = engine;
    const prove::Result r = prove_dir(m.dir(), options);
    ASSERT_TRUE(r.vacuity) << engine;
    EXPECT_NE(r.vacuity->message.find("deadlock"), std::string::npos) << r.vacuity->message;
    EXPECT_NE(r.vacuity->message.find("after tick 1"), std::string::npos) << r.vacuity->message;
    EXPECT_NE(r.vacuity->message.find("hot"), std::string::npos) << r.vacuity->message;
    EXPECT_EQ(r.vacuity->location.file, "domain.fret");
    EXPECT_FALSE(r.passed());
  }
}

TEST(Vacuity, ATriggerThatNeverHoldsIsProvedWithAWarning) {
  // The bit starts cool and nothing heats it: the trigger never holds.
  auto files = drilling_with(std::string(R"({"initial": "IsBitCool", )") + kDrillingActions + "}");
  files["requirements.fret"] +=
      "CoolsDown: Mission shall always satisfy !IsBitCool -> CoolDown.running\n"
      "CoolsSoon: upon !IsBitCool Mission shall within 2 ticks satisfy IsBitCool\n";
  TempMission m(files);
  const prove::Result r = prove_dir(m.dir());
  EXPECT_FALSE(r.vacuity);
  const prove::Answer& soon = answer(r, "CoolsSoon");
  ASSERT_EQ(soon.verdict, Verdict::proved);
  EXPECT_TRUE(soon.has_trigger);
  EXPECT_EQ(soon.first_trigger, 0u);
  bool warned = false;
  for (const auto& f : gate::findings_of(r))
    if (f.check == "prove-trigger-unreachable") {
      warned = true;
      EXPECT_EQ(f.requirements, std::vector<std::string>{"CoolsSoon"});
      EXPECT_EQ(f.severity, Severity::warning);
    }
  EXPECT_TRUE(warned);
  // A guarantee without mode or condition has no trigger to miss.
  EXPECT_FALSE(answer(r, "CoolBit").has_trigger);
}

TEST(Vacuity, AReachableTriggerSaysWhenItFirstHolds) {
  const prove::Result r =
      prove_dir(mission_dir("msl_curiosity"), {}, compile::SelectionStyle::reactive);
  EXPECT_FALSE(r.vacuity);
  const prove::Answer& hold = answer(r, "HoldOnUnknown");
  ASSERT_EQ(hold.verdict, Verdict::proved);
  EXPECT_TRUE(hold.has_trigger);
  EXPECT_EQ(hold.first_trigger, 1u);
  for (const auto& f : gate::findings_of(r)) EXPECT_NE(f.check, "prove-trigger-unreachable");
}

}  // namespace
}  // namespace uabt::testing
