#pragma once
#include <z3++.h>

#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "runtime/script/program.hpp"

namespace uabt::prove {

// What the symbolic engine cannot model exactly; it declines with this reason rather than
// answer.
class SymbolicUnsupported : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Sorts of the state as the symbolic engine encodes it: booleans, integers, reals, and names
// (enum values, alternatives, `none`) as integer codes of one table.
enum class SymType { boolean, integer, real, symbol };

struct SymValue {
  SymType type;
  z3::expr e;
  std::set<int> codes;  // symbol: the codes it may take
};

// Codes of names, shared by every expression of one encoding.
class SymbolCodes {
 public:
  int code(const std::string& name);
  const std::string& name(int code) const { return names_.at(static_cast<std::size_t>(code)); }
  bool has(const std::string& name) const { return codes_.contains(name); }

 private:
  std::map<std::string, int> codes_;
  std::vector<std::string> names_;
};

// The blackboard entries a script may touch, as the encoder sees them.
struct ScriptScope {
  // The state variable a script name (as written, `@x` too) stands for (index into the value
  // vector), -1 if none.
  std::function<int(const std::string&)> var_of;
  const fretish::Domain* domain = nullptr;  // tells enum values from entries
  const std::vector<SymType>* types = nullptr;
  const std::vector<std::set<int>>* domains = nullptr;  // symbol variables: their codes
  SymbolCodes* codes = nullptr;
};

// Runs a BT.CPP script over `values` under `guard` (each assignment becomes
// values[v] = ite(guard, new, old)). Each expression is read as FRETISH by the one reading of
// the script language (verify/script_reading.hpp) and encoded by fretish_bool's encoder;
// assignments store with runtime/script/eval.cpp's rules on the typed subset they accept.
// Anything else throws SymbolicUnsupported naming `where`. Returns the last statement's value,
// or nothing for an empty script.
std::optional<SymValue> run_script(z3::context& ctx, const runtime::script::Program& program,
                                   const ScriptScope& scope, std::vector<z3::expr>& values,
                                   const z3::expr& guard, const std::string& where);

// The truth a script result has for BT.CPP (ScriptCondition): booleans and numbers.
z3::expr script_truth(const SymValue& v, const std::string& where);

// A FRETISH expression over observables, with fretish/evaluate.cpp's meaning on the typed
// subset it accepts. `resolve` gives an identifier's value (throws when unknown).
z3::expr fretish_bool(z3::context& ctx, const fretish::Expr& e,
                      const std::function<SymValue(const std::string&)>& resolve,
                      const std::string& where);
// The same for an expression of any type.
SymValue fretish_value(z3::context& ctx, const fretish::Expr& e,
                       const std::function<SymValue(const std::string&)>& resolve,
                       const std::string& where);

// A runtime value as a term of `type` (symbols by their code).
z3::expr constant_of(z3::context& ctx, const runtime::ScriptValue& v, SymType type,
                     SymbolCodes& codes);
// A decimal literal ("0.5", "12") as a Z3 real or integer.
z3::expr real_literal(z3::context& ctx, double value);

}  // namespace uabt::prove
