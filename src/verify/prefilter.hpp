#pragma once
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "smt/types.hpp"

namespace uabt::verify::detail {

// What a guard's top-level conjuncts say about one variable: a polarity, a set of enum
// literals, or an interval. A guard implies its signature, so guards with conflicting
// signatures are disjoint without asking the solver.
struct VariableConstraint {
  enum class Kind { boolean, values, interval } kind = Kind::boolean;
  bool polarity = true;
  std::vector<bool> allowed;  // values: allowed literal indices
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_strict = false, upper_strict = false;
};

struct Signature {
  std::map<std::string, VariableConstraint> constraints;
  bool contradictory = false;  // the conjuncts themselves clash
};

Signature signature_of(const fretish::Expr& guard, const smt::Typing& typing);

// The two signatures cannot hold together (some variable's constraints do not intersect).
bool disjoint(const Signature& a, const Signature& b);

// For each signature, the others it may meet (not `disjoint`), in increasing order. Indexed by
// the variable most signatures constrain (enum values and booleans by value, intervals by a
// sweep over their lower ends), so a partition of K guards costs O(K log K) rather than K^2
// comparisons.
std::vector<std::vector<std::size_t>> meeting_candidates(const std::vector<const Signature*>& sigs);

// A comparison `variable op number` (either side), normalised so the variable is on the left.
struct Bound {
  std::string variable;
  fretish::ExprKind op = fretish::ExprKind::eq;  // eq ne lt le gt ge
  double value = 0.0;  // exact for the literals accepted (≤ 15 significant digits)
  std::string text;    // the literal as written (with sign)
  bool integer_variable = false;
};

// nullopt unless `e` is such a comparison with an exactly comparable literal.
std::optional<Bound> bound_of(const fretish::Expr& e, const smt::Typing& typing);

}  // namespace uabt::verify::detail
