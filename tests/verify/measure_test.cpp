// Exact measure of real-valued guards (ARCHITECTURE §5): shares against hand-computed lengths and
// areas, against brute force on integer versions of the same guards, and regions that contain
// every witness the verifier reports.
#include <gtest/gtest.h>

#include <random>

#include "verify/fraction.hpp"
#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

using verify::detail::Fraction;

const verify::Coverage& only_coverage(const verify::Result& r) {
  return r.coverage.at(0);
}

std::string share_of(const verify::Coverage& c, const std::string& requirement) {
  for (const auto& a : c.alternatives)
    if (a.requirement == requirement) return a.share.text;
  return "missing";
}

std::vector<std::string> texts(const std::vector<verify::Region>& regions) {
  std::vector<std::string> out;
  for (const auto& r : regions) out.push_back(r.text());
  return out;
}

// Whether a state lies in a region, decided constraint by constraint with the evaluator.
bool contains(const load::Mission& m, const verify::Region& region, const State& state) {
  for (const auto& c : region.constraints) {
    switch (c.kind) {
      case verify::RegionConstraint::Kind::interval: {
        const Value* v = find_value(state, c.variable);
        if (v == nullptr) return false;
        const double x =
            v->kind == Value::Kind::integer ? static_cast<double>(v->integer) : v->real;
        if (x < c.lower_value || (x == c.lower_value && !c.lower_closed)) return false;
        if (x > c.upper_value || (x == c.upper_value && !c.upper_closed)) return false;
        break;
      }
      case verify::RegionConstraint::Kind::values: {
        const Value* v = find_value(state, c.variable);
        if (v == nullptr) return false;
        const std::string text =
            v->kind == Value::Kind::boolean ? (v->boolean ? "true" : "false") : v->to_string();
        if (std::find(c.values.begin(), c.values.end(), text) == c.values.end()) return false;
        break;
      }
      case verify::RegionConstraint::Kind::linear:
        if (!smt::evaluate(*expr(c.text), m.domain, state)) return false;
        break;
    }
  }
  return true;
}

// Every gap and overlap finding's witness lies in a listed region of the same requirements.
void expect_findings_in_regions(const load::Mission& m, const verify::Result& r) {
  const auto& c = only_coverage(r);
  for (const Finding* f : findings_of(r, "guard-gap")) {
    bool found = false;
    for (const auto& region : c.gap_regions) found = found || contains(m, region, f->witness);
    std::string listed;
    for (const auto& region : c.gap_regions) listed += "\n  " + region.text();
    std::string at;
    for (const auto& [n, v] : f->witness) at += n + "=" + v.to_string() + " ";
    EXPECT_TRUE(found) << "gap witness " << at << "outside every listed gap region:" << listed;
  }
  for (const Finding* f : findings_of(r, "guard-overlap")) {
    bool found = false;
    for (const auto& region : c.overlap_regions)
      found = found || (region.requirements == f->requirements && contains(m, region, f->witness));
    EXPECT_TRUE(found) << "overlap witness of " << f->requirements[0] << "/" << f->requirements[1]
                       << " outside every listed overlap region";
  }
}

TEST(Fraction, ExactArithmeticAndOverflow) {
  const Fraction third = Fraction(1) / Fraction(3);
  EXPECT_EQ((third + third + third).text(), "1");
  EXPECT_EQ((Fraction(3) / Fraction(-12)).text(), "-1/4");
  EXPECT_EQ(Fraction::parse("-0.125")->text(), "-1/8");
  EXPECT_EQ(Fraction::parse("2.5e1")->text(), "25");
  EXPECT_EQ(Fraction::parse("0.375")->decimal(), "0.375");
  EXPECT_EQ(third.decimal(), "1/3");
  EXPECT_LT(third, Fraction::of(1, 2));
  const Fraction big = Fraction::of(static_cast<__int128>(1) << 100, 1);
  EXPECT_THROW(big * big, verify::detail::FractionOverflow);
  EXPECT_FALSE(Fraction::parse("1e60").has_value());
}

TEST(Measure, OneRealVariableByHand) {
  const auto m = make_mission(
      "R1: In nav if x < 3 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if x >= 2 & x <= 6 Mission shall satisfy selected_alt = b\n",
      "real x in [0, 10]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_FALSE(c.counted);
  EXPECT_EQ(c.measure.text, "10");
  EXPECT_EQ(share_of(c, "R1"), "3/10");  // [0, 3)
  EXPECT_EQ(share_of(c, "R2"), "3/10");  // [3, 6]
  EXPECT_EQ(c.gap_share.text, "2/5");    // (6, 10]
  EXPECT_EQ(c.overlap_share.text, "1/10");
  EXPECT_EQ(texts(c.gap_regions), std::vector<std::string>{"x in (6, 10]"});
  EXPECT_EQ(texts(c.overlap_regions), std::vector<std::string>{"x in [2, 3)"});
  EXPECT_EQ(c.overlap_regions[0].requirements, (std::vector<std::string>{"R1", "R2"}));
  EXPECT_EQ(c.overlap_regions[0].share.text, "1/10");
  expect_findings_in_regions(m, r);
}

// A share is measured from the set's members only, grouped by combination of real cells: here
// a boolean times 101 cells of x, so members span several 64-bit words and two discrete states
// per cell.
TEST(Measure, ManyCellsWithADiscreteVariableAreMeasuredExactly) {
  std::string reqs;
  for (int k = 0; k < 70; ++k)
    reqs += "R" + std::to_string(k) + ": In nav if B & x >= " + std::to_string(k) + " & x < " +
            std::to_string(k + 1) + " Mission shall satisfy selected_alt = a" + std::to_string(k) +
            "\n";
  reqs += "Low: In nav if !B | x < 0.5 Mission shall satisfy selected_alt = low\n";
  const auto r = verify_checked(make_mission(reqs, "boolean B\nreal x in [0, 100]\n"));
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(c.measure.text, "200");  // two values of B, x over a length of 100
  EXPECT_EQ(share_of(c, "R0"), "1/200");
  EXPECT_EQ(share_of(c, "R69"), "1/200");
  EXPECT_EQ(share_of(c, "Low"), "1/2");      // !B; B & x < 0.5 is R0's first
  EXPECT_EQ(c.gap_share.text, "3/20");       // B & x in [70, 100]
  EXPECT_EQ(c.overlap_share.text, "1/400");  // B & x in [0, 0.5): R0 and Low
}

TEST(Measure, BoundaryOverlapAndGapAreListedWithShareZero) {
  const auto overlap = make_mission(
      "R1: In nav if wind <= 15 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if wind >= 15 Mission shall satisfy selected_alt = b\n",
      "real wind in [0, 40]\n");
  const auto r1 = verify_checked(overlap);
  const auto& c1 = only_coverage(r1);
  ASSERT_TRUE(c1.measured);
  EXPECT_EQ(c1.overlap_share.text, "0");
  EXPECT_EQ(texts(c1.overlap_regions), std::vector<std::string>{"wind = 15"});
  EXPECT_EQ(findings_of(r1, "guard-overlap").size(), 1u);
  expect_findings_in_regions(overlap, r1);

  const auto gap = make_mission(
      "R1: In nav if wind < 15 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if wind > 15 Mission shall satisfy selected_alt = b\n",
      "real wind in [0, 40]\n");
  const auto r2 = verify_checked(gap);
  const auto& c2 = only_coverage(r2);
  EXPECT_EQ(c2.gap_share.text, "0");
  EXPECT_EQ(share_of(c2, "R1"), "3/8");
  EXPECT_EQ(texts(c2.gap_regions), std::vector<std::string>{"wind = 15"});
  expect_findings_in_regions(gap, r2);
}

TEST(Measure, TwoVariableLinearAtomGivesExactPolygons) {
  const auto m = make_mission(
      "R1: In nav if x + y > 10 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if x < 2 Mission shall satisfy selected_alt = b\n",
      "real x in [0, 10]\nreal y in [0, 10]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(c.measure.text, "100");
  EXPECT_EQ(share_of(c, "R1"), "1/2");      // the triangle above x + y = 10
  EXPECT_EQ(share_of(c, "R2"), "9/50");     // ∫0..2 (10 - x) dx = 18
  EXPECT_EQ(c.overlap_share.text, "1/50");  // ∫0..2 x dx = 2
  EXPECT_EQ(c.gap_share.text, "8/25");      // 100 - 50 - 18 = 32
  ASSERT_FALSE(c.overlap_regions.empty());
  EXPECT_EQ(c.overlap_regions[0].text(), "x in [0, 2) & x + y > 10");
  expect_findings_in_regions(m, r);
}

// The gap finding states its region as the coverage table does: the box, and the domain's
// sloped assumption (8 * pressure <= depth + 80) where it cuts the box. The box alone would
// take in pressure up to 20 at depth 0, which the assumption rules out above 10.
TEST(Measure, GapFindingStatesTheRegionASlopedAssumptionCuts) {
  const auto m = make_mission(
      "Shallow: In dive if depth < 50 & pressure < 5 Mission shall satisfy selected_alt = slow\n"
      "Deep: In dive if depth >= 50 Mission shall satisfy selected_alt = fast\n",
      "real depth in [0, 100]\nreal pressure in [0, 20]\n"
      "assume slope: 8 * pressure <= depth + 80\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(c.gap_share.text, "65/256");
  const auto gaps = findings_of(r, "guard-gap");
  ASSERT_EQ(gaps.size(), 1u);
  std::vector<std::string> uncovered;
  for (const auto& note : gaps[0]->notes)
    if (note.rfind("uncovered: ", 0) == 0) uncovered.push_back(note);
  EXPECT_EQ(uncovered,
            (std::vector<std::string>{
                "uncovered: depth in [0, 50) & pressure in [5, 20] & depth - 8*pressure > -80",
                "uncovered: depth in [0, 50) & depth - 8*pressure = -80"}));
  EXPECT_EQ(texts(c.gap_regions),
            (std::vector<std::string>{"depth in [0, 50) & pressure in [5, 20] & depth - "
                                      "8*pressure > -80",
                                      "depth in [0, 50) & depth - 8*pressure = -80"}));
  expect_findings_in_regions(m, r);
}

TEST(Measure, OverlapOnALineHasMeasureZeroAndIsListed) {
  const auto m = make_mission(
      "R1: In nav if 2 * x - y >= 4 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if 2 * x - y <= 4 Mission shall satisfy selected_alt = b\n",
      "real x in [0, 10]\nreal y in [0, 10]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(c.overlap_share.text, "0");
  EXPECT_EQ(c.gap_share.text, "0");
  // 2x - y >= 4 within the square: the trapezoid (2,0) (10,0) (10,10) (7,10): area 55.
  EXPECT_EQ(share_of(c, "R1"), "11/20");
  ASSERT_FALSE(c.overlap_regions.empty());
  for (const auto& region : c.overlap_regions) {
    EXPECT_EQ(region.share.text, "0");
    EXPECT_NE(region.text().find("x - 0.5*y = 2"), std::string::npos) << region.text();
  }
  expect_findings_in_regions(m, r);
}

TEST(Measure, MixedSpaceIsTheSumOverDiscretePoints) {
  const auto m = make_mission(
      "R1: In nav if terrain = flat & wind < 20 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if battery > 10 & wind >= 20 Mission shall satisfy selected_alt = b\n",
      "real wind in [0, 40]\ninteger battery in [0, 100]\nenum terrain in {flat, slope}\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(c.measure.text, "8080");  // 101 batteries x 2 terrains x 40
  EXPECT_EQ(share_of(c, "R1"), "1/4");
  EXPECT_EQ(share_of(c, "R2"), "45/101");  // 90 x 2 x 20 / 8080
  EXPECT_EQ(c.gap_share.text, "123/404");  // 2460 / 8080
  EXPECT_EQ(c.overlap_share.text, "0");
  EXPECT_EQ(texts(c.gap_regions),
            (std::vector<std::string>{"wind in [0, 20) & terrain = slope",
                                      "wind in [20, 40] & battery in [0, 10]"}));
  expect_findings_in_regions(m, r);
}

TEST(Measure, RealAgainstIntegerAtomBreaksAtEveryValue) {
  // wind > battery: for each battery b, wind in (b, 4]: Σ (4 - b) over b = 0..4 = 10 of 20.
  const auto m = make_mission(
      "R1: In nav if wind > battery Mission shall satisfy selected_alt = a\n"
      "R2: In nav Mission shall satisfy selected_alt = d\n",
      "real wind in [0, 4]\ninteger battery in [0, 4]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.measured) << c.not_measured_reason;
  EXPECT_EQ(share_of(c, "R1"), "1/2");
  EXPECT_EQ(share_of(c, "R2"), "1/2");
}

TEST(Measure, NonlinearAtomIsNotMeasuredButBounded) {
  const auto m = make_mission(
      "R1: In nav if x < 5 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if x * y > 50 Mission shall satisfy selected_alt = b\n",
      "real x in [0, 10]\nreal y in [0, 10]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  EXPECT_FALSE(c.measured);
  EXPECT_TRUE(c.bounded);
  EXPECT_NE(c.not_measured_reason.find("`x * y > 50` is not linear"), std::string::npos)
      << c.not_measured_reason;
  // R1 is exact: 1/2. The gap (x >= 5 & x*y <= 50) is 50(1 + ln 2) - 50 - ... in (0, 1/2).
  EXPECT_EQ(c.alternatives[0].share_lower.text, "1/2");
  EXPECT_EQ(c.alternatives[0].share_upper.text, "1/2");
  EXPECT_EQ(c.gap_share_lower.text, "0");
  EXPECT_EQ(c.gap_share_upper.text, "1/2");
  // The true gap share, 0.5 - (50 - 50 ln 2)/100 ≈ 0.3466, lies within.
  EXPECT_LE(c.gap_share_lower.value, 0.3466);
  EXPECT_GE(c.gap_share_upper.value, 0.3466);
}

TEST(Measure, ThreeVariablesInOneAtomAreNotMeasured) {
  const auto m =
      make_mission("R1: In nav if x + y + z > 1 Mission shall satisfy selected_alt = a\n",
                   "real x in [0, 1]\nreal y in [0, 1]\nreal z in [0, 1]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  EXPECT_FALSE(c.measured);
  EXPECT_NE(c.not_measured_reason.find("more than two variables"), std::string::npos);
  EXPECT_EQ(c.alternatives[0].share_lower.text, "0");
  EXPECT_EQ(c.alternatives[0].share_upper.text, "1");
}

TEST(Measure, UnboundedRealIsNotMeasured) {
  const auto m =
      make_mission("R1: In nav if x > 1 Mission shall satisfy selected_alt = a\n", "real x\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  EXPECT_FALSE(c.measured);
  EXPECT_FALSE(c.bounded);
  EXPECT_NE(c.not_measured_reason.find("no lower bound"), std::string::npos);
}

// Random guards over x, y in [0, 10] with integer constants. The integer version declares
// x, y as integers over [0, 10 N] and multiplies every constant by N; its share, counted by
// brute force, tends to the real share: they differ by at most the share of the integer points
// on a boundary (lines and breakpoints), which is O(1/N).
TEST(Measure, MatchesBruteForceOnIntegerVersionsOfTheSameGuards) {
  std::mt19937 rng(15);
  const char* const ops[] = {"<", "<=", ">", ">="};
  auto atom = [&](int scale) {
    const int kind = static_cast<int>(rng() % 4);
    const std::string op = ops[rng() % 4];
    const int c = static_cast<int>(rng() % 11);
    switch (kind) {
      case 0: return "x " + op + " " + std::to_string(c * scale);
      case 1: return "y " + op + " " + std::to_string(c * scale);
      case 2: return "x + y " + op + " " + std::to_string(2 * c * scale);
      default: return "x - y " + op + " " + std::to_string((c - 5) * scale);
    }
  };
  constexpr int kN = 20;
  for (int round = 0; round < 12; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const auto seed = rng();
    std::string real_reqs, int_reqs;
    for (int scale : {1, kN}) {
      rng.seed(seed);
      std::string reqs;
      for (int k = 0; k < 3; ++k)
        reqs += "R" + std::to_string(k) + ": In nav if " + atom(scale) + " & " + atom(scale) +
                " Mission shall satisfy selected_alt = a" + std::to_string(k) + "\n";
      (scale == 1 ? real_reqs : int_reqs) = reqs;
    }
    const auto real = make_mission(real_reqs, "real x in [0, 10]\nreal y in [0, 10]\n");
    const auto integer =
        make_mission(int_reqs, "integer x in [0, " + std::to_string(10 * kN) +
                                   "]\ninteger y in [0, " + std::to_string(10 * kN) + "]\n");
    const auto rr = verify_checked(real);
    const auto& c = only_coverage(rr);
    ASSERT_TRUE(c.measured) << c.not_measured_reason;
    expect_findings_in_regions(real, rr);
    // Brute force over the integer points.
    const auto& sel = integer.selections_for("nav");
    std::vector<double> selected(sel.size(), 0);
    double gap = 0, overlap = 0, total = 0;
    for (int x = 0; x <= 10 * kN; ++x)
      for (int y = 0; y <= 10 * kN; ++y) {
        const State s{{"x", Value::of_int(x)}, {"y", Value::of_int(y)}};
        ++total;
        int first = -1, holding = 0;
        for (std::size_t k = 0; k < sel.size(); ++k) {
          if (!guard_holds(integer, *sel[k], s)) continue;
          if (first < 0) first = static_cast<int>(k);
          ++holding;
        }
        if (first < 0)
          ++gap;
        else
          selected[first] += 1;
        if (holding >= 2) ++overlap;
      }
    // Points on a boundary (at most 6 atoms, each through at most 10 N + 1 grid points) and the
    // grid's own edge make the difference; a wrong cell or polygon would be far larger.
    const double tolerance = 8.0 * (10.0 * kN + 1) / total;
    for (std::size_t k = 0; k < sel.size(); ++k)
      EXPECT_NEAR(c.alternatives[k].share.value, selected[k] / total, tolerance) << sel[k]->id;
    EXPECT_NEAR(c.gap_share.value, gap / total, tolerance);
    EXPECT_NEAR(c.overlap_share.value, overlap / total, tolerance);
  }
}

// The discrete case keeps counting and agrees with the shares.
TEST(Measure, DiscreteSharesAreCountsOverStates) {
  const auto m = make_mission(
      "R1: In nav if battery < 3 Mission shall satisfy selected_alt = a\n"
      "R2: In nav if battery < 5 & OnDust Mission shall satisfy selected_alt = b\n",
      "boolean OnDust\ninteger battery in [0, 9]\n");
  const auto r = verify_checked(m);
  const auto& c = only_coverage(r);
  ASSERT_TRUE(c.counted);
  ASSERT_TRUE(c.measured);
  EXPECT_EQ(c.measure.text, "20");
  EXPECT_EQ(share_of(c, "R1"), "3/10");
  EXPECT_EQ(share_of(c, "R2"), "1/10");
  EXPECT_EQ(c.gap_share.text, "3/5");
  EXPECT_EQ(c.overlap_share.text, "3/20");
  EXPECT_EQ(texts(c.overlap_regions), std::vector<std::string>{"OnDust & battery in [0, 2]"});
  expect_findings_in_regions(m, r);
}

}  // namespace
}  // namespace uabt::testing
