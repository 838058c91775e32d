#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "fretish/integer_ranges.hpp"
#include "runtime/script/program.hpp"
#include "runtime/script/value.hpp"
#include "verify/fraction.hpp"

namespace uabt::prove {

namespace detail {
struct Atom;
}

// An atom that compares a variable x of the cut with the mission's own state (variables the
// mission writes, whose value is known in every state): `x op -(Σ terms·m + b)`, up to the
// direction of `op`. Its breakpoint depends on the state, so it is computed there (ARCHITECTURE
// §10.1): when the environment chooses x, from the values the mission's variables have then.
struct MixedAtom {
  std::vector<std::pair<std::string, verify::detail::Fraction>> terms;
  verify::detail::Fraction b;
  // An assumption's or the initial condition's: it is read with the tick's starting state.
  bool at_tick_start = false;
  std::string where;  // "the atom `battery >= reserve` (requirements.fret:4:1)"
};

// Where the atoms that read a numeric environment variable cut its range (ARCHITECTURE §10.1).
// Inside one cell (a breakpoint, or an open interval between two) every atom `a·x + b op c`
// has one truth value, so the explicit engine branches over one value per cell instead of
// every value. An atom `a·x + Σ b·m op c` whose other variables m are the mission's own state
// cuts x in each state at hand (`mixed`). A variable read in any other way (an effect copies
// it, an atom relates it to another variable of the cut, or is not linear in it) cannot be
// cut: `uncut` says where.
class Cuts {
 public:
  // `numeric`: the numeric environment variables (integers and reals no action writes).
  // `mission`: the numeric variables of the mission's own state (a value in every state).
  // `integers`: those of either declared integer, whose quotient truncates (not affine).
  // `enums`: the enumerated environment variables, each with its declared values.
  using EnumValues = std::map<std::string, std::set<std::string, std::less<>>, std::less<>>;
  explicit Cuts(std::set<std::string, std::less<>> numeric,
                std::set<std::string, std::less<>> mission = {},
                std::set<std::string, std::less<>> integers = {}, EnumValues enums = {})
      : numeric_(std::move(numeric)),
        mission_(std::move(mission)),
        integers_(std::move(integers)),
        enums_(std::move(enums)) {}

  // `where` names the expression for a reason ("requirements.fret:4:1", "a script `x > 2`").
  // `at_tick_start`: an assumption or the initial condition (read with the tick's first state).
  void add(const fretish::Expr& e, const std::string& where, bool at_tick_start = false);
  // A script, by its FRETISH reading (verify/script_reading.hpp) with `domain`'s names: its
  // atoms cut as a requirement's; an entry it assigns, or reads in a way with no reading, is
  // not cut.
  void add(const runtime::script::Program& program, const fretish::Domain& domain,
           const std::string& where);
  // Conditions of which only the disjunction is seen: the ScriptConditions of a Fallback in a
  // selection tree the compiler generates (no property observes those nodes, and a Fallback of
  // conditions ends in the tick it starts). A long run of an integer's comparisons with
  // numerals among them is cut only at the ends of the union of their ranges.
  void add_any_of(const std::vector<const runtime::script::Program*>& programs,
                  const fretish::Domain& domain, const std::string& where);
  // A condition leaf or a port that reads the variable as it is.
  void add_truth_read(const std::string& variable, const std::string& where);
  void add_uncut(const std::string& variable, const std::string& why);

  const std::set<verify::detail::Fraction>& breaks(const std::string& variable) const;
  const std::vector<MixedAtom>& mixed(const std::string& variable) const;
  // The values of an enumerated variable that some atom names (`terrain = rocks`, a script's
  // `terrain == 'rocks'`): every value no atom names has the same truth in every atom, so the
  // values no atom names are one cell.
  const std::set<std::string, std::less<>>& named(const std::string& variable) const;
  // Why `variable` cannot be cut ("" when it can).
  std::string uncut(const std::string& variable) const;

 private:
  // `atom`: the innermost relation around `e` that could not be cut, for the reason.
  void walk(const fretish::Expr& e, const std::string& where, const fretish::Expr* atom,
            bool at_tick_start);
  // Records `atom` (a breakpoint, or a mixed atom); false when there is none.
  bool cut(const std::optional<detail::Atom>& atom, const std::string& where, bool at_tick_start);
  // Records the value an (in)equality of an enumerated variable with one of its values names;
  // false when the operands are not such a pair.
  bool name_value(const std::string& variable, const std::string& value);
  // Breakpoints at the ends of the union of each variable's ranges.
  void cut_at_range_ends(std::map<std::string, std::vector<fretish::IntegerRange>>& ranges);
  std::set<std::string, std::less<>> numeric_, mission_, integers_;
  EnumValues enums_;
  std::map<std::string, std::set<std::string, std::less<>>, std::less<>> named_;
  std::map<std::string, std::set<verify::detail::Fraction>, std::less<>> breaks_;
  std::map<std::string, std::vector<MixedAtom>, std::less<>> mixed_;
  std::map<std::string, std::string, std::less<>> uncut_;
};

// One value per cell of `variable`'s range cut at `breaks` (the declared bounds are cells of
// their own): the breakpoint itself, or a value inside the open interval, an integer near its
// middle where one lies inside (so that counterexamples read like numbers people write).
// Cells of an integer that hold no integer are left out.
std::vector<runtime::ScriptValue> cell_values(const fretish::Variable& variable,
                                              const std::set<verify::detail::Fraction>& breaks);
// One value per cell of an enumerated variable: the values some atom names, and the first value
// (in declaration order) that no atom names, all in declaration order.
std::vector<runtime::ScriptValue> enum_cell_values(const fretish::Variable& variable,
                                                   const std::set<std::string, std::less<>>& named);

}  // namespace uabt::prove
