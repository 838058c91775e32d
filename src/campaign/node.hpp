#pragma once
// One adaptable node of a campaign model: its enumerated space (the coverage stage's cells),
// where each guard holds, what each state selects, and its targets as sets of states; or, when
// the space cannot be enumerated, its targets solved with Z3 one by one (solved.cpp).
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/number_text.hpp"
#include "base/text.hpp"
#include "campaign/campaign.hpp"
#include "fretish/selection.hpp"
#include "smt/evaluate.hpp"
#include "verify/bits.hpp"
#include "verify/fraction.hpp"
#include "verify/space.hpp"

namespace uabt::campaign {

class SolvedQuestions;  // solved.cpp

struct Model::Node {
  std::string adaptable;
  std::vector<const fretish::SelectionRequirement*> reqs;  // priority order
  smt::Typing typing;
  std::unique_ptr<verify::detail::Space> space;
  verify::detail::Bits domain;                 // states that satisfy the assumptions
  std::vector<verify::detail::Bits> enabled;   // per requirement: its guard holds (in domain)
  std::vector<verify::detail::Bits> selected;  // per requirement: it is the one selected
  std::vector<std::string> atom_text;          // distinct atoms of the guards, by FRETISH text
  std::vector<const fretish::Expr*> atom_expr;
  std::vector<std::vector<std::size_t>> req_atoms;  // per requirement: its atoms
  // An atom and one that holds exactly where it does (or where it does not: `wind >= 15` and
  // `wind < 15`) are one condition: one column of the signature, with a polarity.
  std::vector<std::size_t> column;
  std::vector<bool> inverted;
  std::size_t words = 1;            // 64-bit words of a signature
  std::vector<std::uint64_t> sigs;  // per state: the columns' values, `words` words
  std::vector<int> sel;             // per state: requirement selected, -1 gap, -2 outside

  // A target of this node: the states that reach it, or (MC/DC) the pairs that do.
  struct Local {
    std::size_t target = 0;  // index into the model's targets
    verify::detail::Bits states;
    bool pair = false;    // MC/DC: reached by a pair of states, `pairs`
    bool select = false;  // reached by a run that selects the alternative of `req`
    std::size_t req = 0, atom = 0;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs;
    // A single-state target: its states as a FRETISH condition on the node's variables (within
    // the domain), for the world model's search (Model::reach_condition).
    std::string condition;
  };
  std::vector<Local> locals;

  // The guards' variables (closed under the assumptions that link them) and those assumptions:
  // set by build() once the guards type-check (`prepared`).
  bool prepared = false;
  std::set<std::string> names;
  std::vector<const fretish::Expr*> linked;

  // A node whose space is not enumerated: each target solved with Z3, its witnesses the only
  // states known; membership is decided by evaluating the conditions on a state.
  struct Goal {
    enum class Kind { select, guard, pair, boundary } kind = Kind::select;
    std::size_t target = 0;  // index into the model's targets
    std::size_t req = 0, atom = 0;
    bool value = false;  // guard: the value it must take
    // boundary: the variable lies in (lo, hi), or equals lo when `point`; a missing end is
    // infinite
    std::string variable;
    bool point = false;
    std::optional<verify::detail::Fraction> lo, hi;
    // a line of two real variables: sign(variable + slope·variable2 + offset) = `sign`
    bool line = false;
    std::string variable2;
    verify::detail::Fraction slope, offset;
    int sign = 0;
    std::vector<std::size_t> witness;  // indices into `states`
  };
  struct Solved {
    std::string why;  // why the space is not enumerated
    const fretish::Domain* domain = nullptr;
    std::vector<State> states;             // every witness
    std::optional<State> first;            // a state of the domain
    std::vector<std::size_t> column_atom;  // per column: the atom that stands for it
    std::vector<Goal> goals;
    std::shared_ptr<SolvedQuestions> questions;  // the solver, to solve a goal again
  };
  std::unique_ptr<Solved> solved;

  bool build(const load::Mission& mission, std::string& reason);
  void decision_targets(std::vector<Target>& all);
  void mcdc_targets(std::vector<Target>& all);
  void boundary_targets(std::vector<Target>& all);
  void add(std::vector<Target>& all, Target t, verify::detail::Bits states);

  bool atom_holds(std::uint64_t state, std::size_t atom) const;
  // FRETISH conditions on the node's variables (reach_conditions.cpp): requirement k is the
  // one selected; the states whose atoms all have the values they have in `state` (a state of
  // the space) or in `values` (a solved node's).
  std::string selects_condition(std::size_t k) const;
  std::string signature_condition(std::uint64_t state) const;
  std::string signature_condition(const State& values) const;
  // A solved node's single-state goal as a condition.
  std::string goal_condition(const Goal& goal) const;
  // The state's signature as bytes, for hashing (bit c of the bytes is column c).
  std::string key(std::uint64_t state) const;
  State state_values(std::uint64_t state) const;
  // `state`, or when it is excluded another state of the domain where every atom has the
  // same value (nullopt: none is left).
  std::optional<std::uint64_t> substitute(std::uint64_t state,
                                          const std::set<std::uint64_t>& excluded) const;
  // The state (in the domain) an assignment lies in.
  std::optional<std::uint64_t> state_index(const State& state) const;

  // Solves the targets of `criteria` with Z3 (solved.cpp); `why` says why the space is not
  // enumerated. False (with `failure`, and no target added) when a condition does not lower or
  // a witness does not fit a scenario.
  bool solve(const load::Mission& mission, const std::set<Criterion>& criteria,
             const std::string& why, std::vector<Target>& all, std::string& failure);
  // A solved node: the state restricted to the node's variables when it assigns them all
  // within their ranges and satisfies the assumptions; nullopt otherwise.
  std::optional<State> solved_state(const State& state) const;
  // A solved node: the requirement a state of the domain selects (-1: none).
  int solved_selection(const State& state) const;
  bool solved_holds(const fretish::Expr& condition, const State& state) const;
  // A solved node: whether a state of the domain reaches a single-state goal.
  bool solved_reaches(const Goal& goal, const State& state) const;
  // A solved node: solves goal `goal` again away from the excluded states (its witness is
  // replaced); false when no other state reaches it.
  bool solved_retry(std::size_t goal, const std::set<std::uint64_t>& excluded) const;
  // A solved node: two states of the domain are an MC/DC pair of the goal's atom.
  bool solved_pair(const Goal& goal, const State& s, const State& u) const;
};

// "run-03": `base` numbered `n`, with as many digits as `total` has (two at least).
inline std::string numbered(const std::string& base, std::size_t n, std::size_t total) {
  std::string digits = std::to_string(n);
  const std::size_t width = std::max<std::size_t>(2, std::to_string(total).size());
  while (digits.size() < width) digits = "0" + digits;
  return base + "-" + digits;
}

// A number inside (lo, hi) that reads well: an integer, else the fewest decimals (up to six).
inline std::optional<verify::detail::Fraction> simple_inside(const verify::detail::Fraction& lo,
                                                             const verify::detail::Fraction& hi) {
  using verify::detail::Fraction;
  Fraction scale(1);
  for (int digits = 0; digits <= 6; ++digits) {
    const Fraction candidate = Fraction::of((lo * scale).floor() + 1, 1) / scale;
    if (candidate < hi) return candidate;
    scale = scale * Fraction(10);
  }
  return std::nullopt;
}

// `state` in the domain's declaration order, undeclared names last by name: how every
// scenario and target lists a state.
inline State in_domain_order(const fretish::Domain& domain, State state) {
  auto rank = [&](const std::string& name) {
    for (std::size_t k = 0; k < domain.variables.size(); ++k)
      if (domain.variables[k].name == name) return k;
    return domain.variables.size();
  };
  std::stable_sort(state.begin(), state.end(), [&](const auto& a, const auto& b) {
    const auto ra = rank(a.first), rb = rank(b.first);
    return ra != rb ? ra < rb : (ra == domain.variables.size() && a.first < b.first);
  });
  return state;
}

// A real as a scenario writes it: the short decimal when there is one, else the nearest double
// (1/3 as 0.3333333333333333), which a scenario can carry and where the tree's arithmetic, a
// double's as in BehaviorTree.CPP, lies where 1/3 does.
inline Value real_value(const verify::detail::Fraction& x) {
  const std::string decimal = x.decimal();
  if (decimal.find('/') == std::string::npos) return Value::of_real(x.to_double(), decimal);
  return Value::of_real(x.to_double(), number_text(x.to_double()));
}

// A number as a FRETISH condition reads it: "2.5", "(-3)", "(1/3)".
inline std::string number_condition(const verify::detail::Fraction& x) {
  const std::string text = x.decimal();
  return text.find_first_of("-/") == std::string::npos ? text : "(" + text + ")";
}

// The targets' ids and texts, and why one is unreachable: one wording for the enumerated
// nodes (model.cpp) and the solved ones (solved.cpp), which tests compare.
inline Target new_target(const std::string& adaptable, Criterion criterion, const std::string& id,
                         std::string text) {
  Target t;
  t.adaptable = adaptable;
  t.criterion = criterion;
  t.id = adaptable + "/" + criterion_name(criterion) + "/" + id;
  t.text = std::move(text);
  return t;
}
inline Target select_target(const std::string& adaptable, const fretish::SelectionRequirement& r) {
  return new_target(adaptable, Criterion::decision, "select/" + r.alternative,
                    adaptable + " selects " + r.alternative + " (" + r.id + ")");
}
// No state selects r's alternative: its guard holds nowhere, or only where `earlier` do too.
inline std::string unselectable(const fretish::SelectionRequirement& r, bool guard_holds,
                                const std::vector<std::string>& earlier) {
  if (!guard_holds)
    return r.guard ? "the guard of " + r.id + " holds in no state of the domain"
                   : "the domain has no state";
  return "wherever the guard of " + r.id + " holds, an earlier requirement (" +
         join(earlier, ", ") + ") holds too and is selected first";
}
inline Target guard_target(const std::string& adaptable, const fretish::SelectionRequirement& r,
                           const std::string& guard, bool value) {
  const std::string word = value ? "true" : "false";
  return new_target(adaptable, Criterion::decision, "guard/" + r.id + "/" + word,
                    "the guard of " + r.id + " (" + guard + ") is " + word);
}
inline std::string guard_never(bool value) {
  return value ? "the guard holds in no state of the domain"
               : "the guard holds in every state of the domain";
}
inline Target mcdc_target(const std::string& adaptable, const fretish::SelectionRequirement& r,
                          const std::string& atom) {
  return new_target(adaptable, Criterion::mcdc, r.id + "/" + atom,
                    "MC/DC of " + atom + " in " + r.id +
                        ": changing it alone changes the guard and the selected alternative");
}
// Why an atom of requirement `req` has no MC/DC pair, the first of these that holds.
enum class NoPair {
  atom_fixed,      // the atom never changes over the domain (`holds`: it is always true)
  atom_tied,       // it never changes alone
  guard_fixed,     // the guard never changes (`holds`: it always holds)
  guard_masked,    // changing the atom alone never changes the guard
  same_selection,  // where it changes the guard, `earlier` requirements, or the same, are selected
};
inline std::string no_pair(NoPair why, const std::string& atom, const std::string& req,
                           bool holds = false, const std::vector<std::string>& earlier = {}) {
  std::string text = "not independently testable: ";
  switch (why) {
    case NoPair::atom_fixed:
      return text + atom + " is " + (holds ? "true" : "false") + " in every state of the domain";
    case NoPair::atom_tied:
      return text + atom + " never changes alone: the domain or the other atoms tie it to them";
    case NoPair::guard_fixed:
      return text + "the guard of " + req + (holds ? " holds in every" : " holds in no") +
             " state of the domain, so no atom can change it";
    case NoPair::guard_masked:
      return text + "changing " + atom + " alone never changes the guard of " + req +
             " (the other atoms mask it)";
    case NoPair::same_selection: break;
  }
  text += "wherever " + atom + " alone changes the guard of " + req + ", ";
  return text + (earlier.empty() ? "the same alternative is selected either way"
                                 : "an earlier requirement (" + join(earlier, ", ") +
                                       ") holds either way and is selected");
}
// Boundary targets: an integer on either side of the boundary between `lo` and `lo + 1`; a
// real below, at or above a breakpoint (`side` -1, 0, 1), between its neighbours `before` and
// `after`; a line of two reals `x + b*y = rhs` and either side of it.
inline Target integer_boundary(const std::string& adaptable, const std::string& name,
                               const std::string& lo, const std::string& hi, bool below) {
  const std::string side = below ? "below" : "above";
  return new_target(adaptable, Criterion::boundary, name + "/" + lo + "|" + hi + "/" + side,
                    name + " = " + (below ? lo : hi) + ", " + side + " the boundary between " + lo +
                        " and " + hi);
}
inline Target real_boundary(const std::string& adaptable, const std::string& name, int side,
                            const std::string& before, const std::string& at,
                            const std::string& after) {
  const std::string id = name + "/" + at + "/";
  if (side == 0)
    return new_target(adaptable, Criterion::boundary, id + "at",
                      name + " = " + at + ", on the boundary");
  return new_target(adaptable, Criterion::boundary, id + (side < 0 ? "below" : "above"),
                    name + " in (" + (side < 0 ? before : at) + ", " + (side < 0 ? at : after) +
                        "), just " + (side < 0 ? "below" : "above") + " the boundary " + at);
}
inline std::string line_text(const std::string& x, const verify::detail::Fraction& b,
                             const std::string& y) {
  if (b.is_zero()) return x;
  const bool unit = b == verify::detail::Fraction(1) || b == verify::detail::Fraction(-1);
  return x + (b.sign() < 0 ? " - " : " + ") +
         (unit ? "" : (b.sign() < 0 ? -b : b).decimal() + "*") + y;
}
inline Target line_boundary(const std::string& adaptable, const std::string& line,
                            const std::string& rhs, int side) {
  const char* names[] = {"below", "at", "above"};
  const char* relations[] = {" < ", " = ", " > "};
  return new_target(adaptable, Criterion::boundary,
                    "line/" + line + " = " + rhs + "/" + names[side + 1],
                    line + relations[side + 1] + rhs +
                        (side == 0 ? ", on the boundary" : ", beside the boundary"));
}
inline constexpr const char* kNoStateThere =
    "no state of the domain lies there (the assumptions rule it out)";

}  // namespace uabt::campaign
