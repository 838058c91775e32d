// Division by a number written out is linear: the symbolic engine models it with the concrete
// evaluators' meaning (reals divide exactly; integers truncate toward zero, and `mod` keeps the
// dividend's sign), and answers as the explicit engine does. Division by anything else is
// still declined, by name.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "prove_support.hpp"

namespace uabt::testing {
namespace {

using prove::Verdict;

// The vehicle dives to 400 m at its first tick; the pressure the environment reports is
// bounded by the depth it is at (hydrostatic): at most 10 at the surface, 60 at 400 m.
std::map<std::string, std::string> dive_mission() {
  return {{"mission.xml", mission_with("    <Sequence><Dive/><Hold/></Sequence>")},
          {"domain.fret",
           "real pressure in [0, 100]\n"
           "real depth in [0, 400]\n"
           "assume hydrostatic: pressure <= depth / 8 + 10\n"},
          {"requirements.fret",
           "Rated: Mission shall always satisfy pressure <= 60\n"
           "Shallow: Mission shall always satisfy pressure <= 40\n"},
          {"world.json", R"({"initial": "depth = 0", "actions": {
             "Dive": {"ticks": 1, "results": ["success"], "on_success": "depth = 400"},
             "Hold": {"ticks": 3, "results": ["success"]}}})"}};
}

// Answers of both engines, verdict by verdict and violation tick by violation tick.
void expect_agreement(const prove::Result& x, const prove::Result& s) {
  ASSERT_EQ(x.answers.size(), s.answers.size());
  for (std::size_t i = 0; i < x.answers.size(); ++i) {
    SCOPED_TRACE(x.answers[i].requirement);
    EXPECT_EQ(prove::verdict_name(x.answers[i].verdict),
              std::string(prove::verdict_name(s.answers[i].verdict)));
    if (x.answers[i].verdict == Verdict::violated) {
      EXPECT_EQ(x.answers[i].depth, s.answers[i].depth);
    }
  }
}

TEST(Division, TheSymbolicEngineProvesAndRefutesUnderADividedAssumptionAsTheExplicitOne) {
  TempMission m(dive_mission());
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result x = g.prove("explicit"), s = g.prove("symbolic");
  EXPECT_EQ(answer(s, "Rated").verdict, Verdict::proved);
  const prove::Answer& shallow = answer(s, "Shallow");
  ASSERT_EQ(shallow.verdict, Verdict::violated);
  EXPECT_EQ(shallow.depth, 2u);  // at 400 m, once Dive has succeeded
  expect_agreement(x, s);
}

// An integer quotient truncates toward zero: tilt / 8 >= -1 allows tilt from -15 (floor would
// stop at -8). The explicit engine took the quotient for a real one and cut tilt's range at
// -8 alone, where no value of the cell below it (-19 stood for it) kept the assumption: it
// proved Upright. It now enumerates tilt.
TEST(Division, AnIntegerQuotientTruncatesTowardZeroInBothEngines) {
  TempMission m({{"mission.xml", mission_with("    <Hold/>")},
                 {"domain.fret",
                  "integer tilt in [-30, 20]\n"
                  "assume level: tilt / 8 >= -1\n"},
                 {"requirements.fret", "Upright: Mission shall always satisfy tilt >= -8\n"},
                 {"world.json", R"({"actions": {"Hold": {"ticks": 2, "results": ["success"]}}})"}});
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result x = g.prove("explicit"), s = g.prove("symbolic");
  for (const prove::Result* r : {&x, &s}) {
    SCOPED_TRACE(r->engine);
    const prove::Answer& upright = answer(*r, "Upright");
    ASSERT_EQ(upright.verdict, Verdict::violated);
    EXPECT_EQ(upright.depth, 1u);
    const auto scenario = nlohmann::json::parse(upright.counterexample->scenario);
    const int tilt = scenario["initial"]["tilt"].get<int>();
    EXPECT_GE(tilt, -15) << upright.counterexample->scenario;
    EXPECT_LE(tilt, -9) << upright.counterexample->scenario;
  }
  expect_agreement(x, s);
}

// `mod` by a numeral keeps the dividend's sign: tilt mod 4 != -3 rules out -3, -7, -11, ...
// (a Euclidean remainder would be 1 there) and nothing else.
TEST(Division, AnIntegerRemainderKeepsTheDividendsSignInBothEngines) {
  TempMission m({{"mission.xml", mission_with("    <Hold/>")},
                 {"domain.fret",
                  "integer tilt in [-30, 20]\n"
                  "assume grid: tilt mod 4 != -3\n"},
                 {"requirements.fret",
                  "OffGrid: Mission shall always satisfy tilt != -11\n"
                  "Ten: Mission shall always satisfy tilt != -10\n"},
                 {"world.json", R"({"actions": {"Hold": {"ticks": 2, "results": ["success"]}}})"}});
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result x = g.prove("explicit"), s = g.prove("symbolic");
  for (const prove::Result* r : {&x, &s}) {
    SCOPED_TRACE(r->engine);
    EXPECT_EQ(answer(*r, "OffGrid").verdict, Verdict::proved);
    const prove::Answer& ten = answer(*r, "Ten");
    ASSERT_EQ(ten.verdict, Verdict::violated);
    EXPECT_EQ(ten.depth, 1u);
  }
  expect_agreement(x, s);
}

// A script in the tree means what BT.CPP computes, in both engines: `/` divides integers as
// doubles (tilt / 2 > 1 holds from tilt = 3), and `==` on a real holds within float epsilon of
// equal, so a level that is not exactly 0.5 can pass `level == 0.5`.
TEST(Division, AScriptDividesAndComparesAsTheEngineRunsIt) {
  TempMission m(
      {{"mission.xml", mission_with("    <Sequence><ScriptCondition name=\"Half\" code=\"tilt / 2 "
                                    "&gt; 1\"/><ScriptCondition name=\"Level\" code=\"level == "
                                    "0.5\"/><Hold/></Sequence>")},
       {"domain.fret", "integer tilt in [-30, 20]\nreal level in [0, 1]\n"},
       {"requirements.fret",
        "Steep: Mission shall always satisfy Half.success -> tilt >= 3\n"
        "Exact: Mission shall always satisfy Level.success -> level = 0.5\n"},
       {"world.json", R"({"actions": {"Hold": {"ticks": 2, "results": ["success"]}}})"}});
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  const prove::Result x = g.prove("explicit"), s = g.prove("symbolic");
  for (const prove::Result* r : {&x, &s}) {
    SCOPED_TRACE(r->engine);
    EXPECT_EQ(answer(*r, "Steep").verdict, Verdict::proved);
    const prove::Answer& exact = answer(*r, "Exact");
    ASSERT_EQ(exact.verdict, Verdict::violated);
    EXPECT_EQ(exact.depth, 1u);
    const auto scenario = nlohmann::json::parse(exact.counterexample->scenario);
    const double level = scenario["initial"]["level"].get<double>();
    EXPECT_NE(level, 0.5) << exact.counterexample->scenario;
    EXPECT_LE(std::abs(level - 0.5), 1.2e-7) << exact.counterexample->scenario;
  }
  expect_agreement(x, s);
}

// A divisor that is not a number written out is declined with the reason it always had.
TEST(Division, ADivisorThatIsNotANumeralIsStillDeclined) {
  auto files = dive_mission();
  files["domain.fret"] =
      "real pressure in [0, 100]\n"
      "real depth in [0, 400]\n"
      "real density in [1, 2]\n"
      "assume hydrostatic: pressure <= depth / density + 10\n";
  TempMission m(files);
  Gated g(m.dir());
  ASSERT_TRUE(g.ok()) << format_text(g.outcome->report.findings);
  try {
    g.prove("symbolic");
    ADD_FAILURE() << "proved";
  } catch (const prove::ProveError& e) {
    EXPECT_NE(std::string(e.what()).find("assumption hydrostatic: 'depth / density' (division, "
                                         "modulo and powers are not modelled)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace uabt::testing
