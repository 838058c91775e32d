#pragma once
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fretish/expr.hpp"

namespace uabt::fretish {

// A long disjunction of comparisons of one integer variable with numerals (`depth = 0 |
// depth = 1 | …`) is, as a whole, the union of the ranges its comparisons allow: the SMT
// encoder lowers it as those ranges (`0 <= depth <= 59999`), an equivalent formula Z3 decides at
// once where 60,000 disjuncts cost it seconds a question. A run shorter than this is lowered as
// written, so the witnesses of ordinary guards stay as they were.
inline constexpr std::size_t kMinRangeRun = 16;

// The integers from `lo` to `hi`; a missing bound is unbounded.
struct IntegerRange {
  std::optional<__int128> lo, hi;
};

// The integers x with `x op c` (op a relation; x on the left).
std::vector<IntegerRange> ranges_of(ExprKind op, __int128 c);

// The union of `ranges`, sorted, with overlapping and adjacent ranges merged.
std::vector<IntegerRange> merged(std::vector<IntegerRange> ranges);

// An integer numeral of at most 18 digits, possibly negated.
std::optional<__int128> integer_numeral(const Expr& e);

// `x op n` or `n op x` with an integer numeral n: the identifier x and the ranges it allows.
struct IntegerComparison {
  const Expr* variable = nullptr;
  std::vector<IntegerRange> ranges;
};
std::optional<IntegerComparison> integer_comparison(const Expr& e);

// A disjunction's arguments split into the integer comparisons `merge` accepts, gathered per
// variable as the ranges they allow (not yet merged), and the `rest`. The encoder (which
// lowers the ranges) and the explicit engine's cuts (which cut at their ends) share it.
struct IntegerRuns {
  std::map<std::string, std::vector<IntegerRange>> ranges;
  std::vector<const Expr*> rest;
};
IntegerRuns integer_runs(
    const Expr& disjunction,
    const std::function<bool(const Expr& argument, const IntegerComparison& comparison)>& merge);

}  // namespace uabt::fretish
