#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "runtime/script/program.hpp"
#include "runtime/script/value.hpp"
#include "verify/fraction.hpp"

namespace uabt::prove {

// Where the atoms that read a numeric environment variable cut its range (DESIGN §10.1).
// Inside one cell (a breakpoint, or an open interval between two) every atom `a·x + b op c`
// has one truth value, so the explicit engine branches over one value per cell instead of
// every value. A variable read in any other way (an effect copies it, an atom relates it to
// another variable) cannot be cut: `uncut` says where.
class Cuts {
 public:
  // `numeric`: the numeric environment variables (integers and reals no action writes).
  explicit Cuts(std::set<std::string, std::less<>> numeric) : numeric_(std::move(numeric)) {}

  // `where` names the expression for a reason ("requirements.fret:4:1", "a script `x > 2`").
  void add(const fretish::Expr& e, const std::string& where);
  // `name_of(slot)`: the root blackboard key a script name resolves to ("" when unknown).
  void add(const runtime::script::Program& program, const std::string& where);
  // A condition leaf or a port that reads the variable as it is.
  void add_truth_read(const std::string& variable, const std::string& where);
  void add_uncut(const std::string& variable, const std::string& why);

  const std::set<verify::detail::Fraction>& breaks(const std::string& variable) const;
  // Why `variable` cannot be cut ("" when it can).
  std::string uncut(const std::string& variable) const;

 private:
  // `atom`: the innermost relation around `e` that could not be cut, for the reason.
  void walk(const fretish::Expr& e, const std::string& where, const fretish::Expr* atom);
  std::set<std::string, std::less<>> numeric_;
  std::map<std::string, std::set<verify::detail::Fraction>, std::less<>> breaks_;
  std::map<std::string, std::string, std::less<>> uncut_;
};

// One value per cell of `variable`'s range cut at `breaks` (the declared bounds are cells of
// their own): the breakpoint itself, or a value inside the open interval, an integer near its
// middle where one lies inside (so that counterexamples read like numbers people write).
// Cells of an integer that hold no integer are left out.
std::vector<runtime::ScriptValue> cell_values(const fretish::Variable& variable,
                                              const std::set<verify::detail::Fraction>& breaks);

}  // namespace uabt::prove
