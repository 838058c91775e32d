// Coverage counts against brute force with the independent evaluator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "verify/mission_builder.hpp"
#include "verify/space.hpp"

namespace uabt::testing {
namespace {

// Every state of a small domain: booleans, enums and bounded integers, in declaration order.
std::vector<State> all_states(const fretish::Domain& d) {
  std::vector<State> states{{}};
  for (const auto& v : d.variables) {
    std::vector<Value> values;
    switch (v.type) {
      case fretish::VarType::boolean: values = {Value::of_bool(false), Value::of_bool(true)}; break;
      case fretish::VarType::enumeration:
        for (const auto& l : v.enum_values) values.push_back(Value::of_enum(l));
        break;
      case fretish::VarType::integer:
        for (long i = std::stol(v.lower); i <= std::stol(v.upper); ++i)
          values.push_back(Value::of_int(i));
        break;
      case fretish::VarType::real: throw std::logic_error("not enumerable");
    }
    std::vector<State> next;
    for (const auto& s : states)
      for (const auto& value : values) {
        State t = s;
        t.emplace_back(v.name, value);
        next.push_back(std::move(t));
      }
    states = std::move(next);
  }
  return states;
}

void expect_brute_force_counts(const load::Mission& m) {
  const verify::Result r = verify_checked(m);
  const auto& selections = m.selections_for(m.adaptables.at(0).id);
  const verify::Coverage& cov = r.coverage.at(0);
  ASSERT_TRUE(cov.counted) << cov.not_counted_reason;
  std::uint64_t states = 0, gap = 0, overlap = 0;
  std::vector<std::uint64_t> selected(selections.size()), enabled(selections.size());
  for (const State& s : all_states(m.domain)) {
    if (!smt::satisfies_domain(m.domain, s)) continue;
    ++states;
    int first = -1, guards_holding = 0;
    for (std::size_t k = 0; k < selections.size(); ++k) {
      if (!guard_holds(m, *selections[k], s)) continue;
      ++enabled[k];
      if (first < 0) first = static_cast<int>(k);
      if (selections[k]->guard) ++guards_holding;
    }
    if (first < 0)
      ++gap;
    else
      ++selected[first];
    if (guards_holding >= 2) ++overlap;
  }
  EXPECT_EQ(cov.states, states);
  EXPECT_EQ(cov.gap_states, gap);
  EXPECT_EQ(cov.overlap_states, overlap);
  for (std::size_t k = 0; k < selections.size(); ++k) {
    SCOPED_TRACE(selections[k]->id);
    EXPECT_EQ(cov.alternatives.at(k).states, selected[k]);
    EXPECT_EQ(cov.alternatives.at(k).enabled_states, enabled[k]);
    EXPECT_EQ(cov.alternatives.at(k).reachable, selected[k] > 0);
  }
  // Findings agree with the counts.
  EXPECT_EQ(findings_of(r, "guard-gap").empty(), gap == 0);
  EXPECT_EQ(findings_of(r, "guard-overlap").empty(), overlap == 0);
}

const char* const kSmallDomain =
    "boolean OnDust, OnRocks\nenum terrain in {dust, rocks, sand, mud}\ninteger battery in [0, "
    "9]\n";

TEST(Coverage, MixedGuardsMatchBruteForce) {
  expect_brute_force_counts(make_mission(
      "R1: In nav if OnDust & battery >= 3 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if terrain = rocks | OnRocks Mission shall satisfy selected_alt = b\n"
      "R3: In nav if battery mod 3 = 1 & terrain != mud Mission shall satisfy selected_alt = c\n"
      "R4: In nav if (OnDust xor OnRocks) -> battery < 5 Mission shall satisfy selected_alt = d\n",
      kSmallDomain));
}

TEST(Coverage, AssumptionsAndDefaultMatchBruteForce) {
  expect_brute_force_counts(make_mission(
      "R1: In nav if OnDust Mission shall satisfy selected_alt = a\n"
      "R2: In nav if OnRocks & battery > 4 Mission shall satisfy selected_alt = b\n"
      "R3: In nav if terrain = sand Mission shall satisfy selected_alt = c\n"
      "Safe: In nav Mission shall satisfy selected_alt = d\n",
      std::string(kSmallDomain) +
          "assume one_terrain: !(OnDust & OnRocks)\nassume dust_flag: OnDust <-> terrain = dust\n"
          "assume low_on_mud: terrain = mud -> battery < 2\n"));
}

TEST(Coverage, ArithmeticGuardsMatchBruteForce) {
  // Counting is over the variables the guards use, so the domain declares only those.
  expect_brute_force_counts(make_mission(
      "R1: In nav if battery * battery - 4 * battery > 5 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if ite(OnDust, battery / 2, battery - 7) = 2 Mission shall satisfy selected_alt "
      "= b\n"
      "R3: In nav if absInt(battery - 5) < 2 | maxInt(battery, 8) = 8 Mission shall satisfy "
      "selected_alt = c\n",
      "boolean OnDust\ninteger battery in [0, 9]\n"));
}

TEST(Coverage, OnlyTheGuardsVariablesAndLinkedAssumptionsAreCounted) {
  const load::Mission m = make_mission(
      "R1: In nav if OnDust Mission shall satisfy selected_alt = a\n"
      "R2: In nav if !OnDust Mission shall satisfy selected_alt = b\n",
      "boolean OnDust, Linked, Unrelated\nreal slope in [0, 1]\n"
      "assume link: OnDust -> Linked\nassume other: Unrelated | slope > 0.5\n");
  const verify::Result r = verify_checked(m);
  const auto& cov = r.coverage.at(0);
  ASSERT_TRUE(cov.counted) << cov.not_counted_reason;
  EXPECT_EQ(cov.variables, (std::vector<std::string>{"OnDust", "Linked"}));
  EXPECT_EQ(cov.states, 3u);
  EXPECT_EQ(cov.alternatives.at(0).states, 1u);
  EXPECT_EQ(cov.alternatives.at(1).states, 2u);
}

TEST(Coverage, NotCountedWhenRealUnboundedOrTooLarge) {
  const auto reason = [](const std::string& guard, const std::string& dom) {
    const verify::Result r =
        verify_checked(make_mission("R1: In nav if " + guard +
                                        " Mission shall satisfy selected_alt = a\n"
                                        "Safe: In nav Mission shall satisfy selected_alt = b\n",
                                    dom));
    EXPECT_FALSE(r.coverage.at(0).counted);
    EXPECT_TRUE(r.coverage.at(0).alternatives.at(0).reachable);
    return r.coverage.at(0).not_counted_reason;
  };
  EXPECT_NE(reason("slope > 2", "real slope in [0, 10]\n").find("real variable slope"),
            std::string::npos);
  EXPECT_NE(reason("n > 2", "integer n\n").find("no lower bound"), std::string::npos);
  EXPECT_NE(reason("a + b > 2", "integer a in [0, 4095]\ninteger b in [0, 4096]\n").find("2^24"),
            std::string::npos);
}

// Counting gives each distinct atom a truth table over the whole space: 1,500 atoms over an
// integer of 100,001 values would take minutes and gigabytes, so the shares are not counted
// and the reason says why; the solver's checks are made as always.
TEST(Coverage, NotCountedWhenAtomsTimesStatesExceedTheEvaluationLimit) {
  std::string guard = "depth = 0";
  for (int k = 1; k < 1500; ++k) guard += " | depth = " + std::to_string(k);
  const verify::Result r =
      verify_checked(make_mission("R1: In nav if " + guard +
                                      " Mission shall satisfy selected_alt = a\n"
                                      "Safe: In nav Mission shall satisfy selected_alt = b\n",
                                  "integer depth in [0, 100000]\n"));
  const auto& cov = r.coverage.at(0);
  EXPECT_FALSE(cov.counted);
  EXPECT_EQ(cov.not_counted_reason,
            "the guards' 1500 atoms over 100001 states are more than the 2^27 evaluations uabt "
            "counts");
  EXPECT_TRUE(cov.alternatives.at(0).reachable);
  EXPECT_TRUE(cov.alternatives.at(1).reachable);
}

TEST(Coverage, LargestCountedSpaceIsCountedExactly) {
  // 4096 * 4096 = 2^24 states: the limit itself is still counted.
  const verify::Result r = verify_checked(
      make_mission("R1: In nav if a < 1024 Mission shall satisfy selected_alt = x\n"
                   "R2: In nav if b >= 2048 Mission shall satisfy selected_alt = y\n",
                   "integer a in [0, 4095]\ninteger b in [0, 4095]\n"));
  const auto& cov = r.coverage.at(0);
  ASSERT_TRUE(cov.counted) << cov.not_counted_reason;
  EXPECT_EQ(cov.states, 1ull << 24);
  EXPECT_EQ(cov.alternatives.at(0).states, 1024ull * 4096);
  EXPECT_EQ(cov.overlap_states, 1024ull * 2048);
  EXPECT_EQ(cov.gap_states, 3072ull * 2048);
}

TEST(Coverage, DivisionByZeroInSomeStateIsNotGuessed) {
  const verify::Result r = verify_checked(
      make_mission("R1: In nav if 10 / battery > 2 Mission shall satisfy selected_alt = a\n"
                   "Safe: In nav Mission shall satisfy selected_alt = b\n",
                   "integer battery in [0, 9]\n"));
  EXPECT_FALSE(r.coverage.at(0).counted);
  // The guard has no value where battery = 0: the node is not verified, its share not guessed.
  EXPECT_EQ(r.coverage.at(0).not_counted_reason,
            "not verified: the guard of R1 divides by zero in a state of the domain "
            "(requirements.fret:1)");
  // Guarded division has a value everywhere.
  const verify::Result guarded = verify_checked(make_mission(
      "R1: In nav if battery != 0 & 10 / battery > 2 Mission shall satisfy selected_alt = a\n"
      "Safe: In nav Mission shall satisfy selected_alt = b\n",
      "integer battery in [0, 9]\n"));
  EXPECT_TRUE(guarded.coverage.at(0).counted);
  EXPECT_EQ(guarded.coverage.at(0).alternatives.at(0).states, 3u);  // 1, 2, 3
}

TEST(RunValues, ARealLiesAtABreakpointWhenItIsTheBreakpointsNearestDouble) {
  // The run computes in doubles: 0.3333333333333333 is where 1/3 is for every guard it reads.
  using verify::detail::Fraction;
  using verify::detail::side_of;
  const Fraction third = Fraction::of(1, 3);
  const double at = 1.0 / 3.0;
  EXPECT_EQ(side_of(Value::of_real(at, "0.3333333333333333"), third), 0);
  EXPECT_EQ(side_of(Value::of_real(std::nextafter(at, 1.0), "0.33333333333333337"), third), 1);
  EXPECT_EQ(side_of(Value::of_real(std::nextafter(at, 0.0), "0.33333333333333326"), third), -1);
  // An integer compares exactly, also beyond 2^53.
  EXPECT_EQ(side_of(Value::of_int(INT64_MAX), Fraction(static_cast<long long>(INT64_MAX - 1))), 1);
  EXPECT_EQ(side_of(Value::of_int(7), Fraction(7)), 0);
  // No place at all for what is no number.
  EXPECT_FALSE(side_of(Value::of_real(std::nan(""), "nan"), third).has_value());
  EXPECT_FALSE(side_of(Value::of_bool(true), third).has_value());
}

TEST(CoverageMap, NeighbouringEnumValuesOfOneOutcomeAreNamedWhereTheyAreDrawn) {
  // rocks and mud select the same alternative, so the map draws them as one shape; its
  // description must name both, not drop the variable.
  const load::Mission m = make_mission(
      "Sand: In nav if terrain = sand Mission shall satisfy selected_alt = slow\n"
      "Other: In nav Mission shall satisfy selected_alt = fast\n",
      "enum terrain in {sand, rocks, mud}\n");
  const verify::Result r = verify_checked(m);
  ASSERT_TRUE(r.coverage.at(0).map.has_value());
  std::vector<std::string> wheres;
  for (const auto& panel : r.coverage.at(0).map->panels)
    for (const auto& shape : panel.shapes) wheres.push_back(shape.where);
  EXPECT_EQ(wheres, (std::vector<std::string>{"terrain = sand", "terrain in {rocks, mud}"}));
}

}  // namespace
}  // namespace uabt::testing
