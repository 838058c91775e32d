#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "fretish/expr.hpp"

namespace uabt::monitor {

// The value of one variable at one tick. Enum literals and other names are interned symbols.
// A number is an integer when its variable is declared integer, its literal or JSON value is
// written without a fraction or exponent, or it is computed from integers: then `/` and `mod`
// truncate toward zero, as FRET's targets (C, Lustre, SMV) compute them.
struct Val {
  enum class Kind : std::uint8_t { missing, boolean, number, symbol };
  Kind kind = Kind::missing;
  double number = 0;  // booleans as 0/1
  int symbol = -1;
  bool integer = false;  // a number of integer type

  static Val of_bool(bool b) { return {Kind::boolean, b ? 1.0 : 0.0, -1, false}; }
  static Val of_number(double x) { return {Kind::number, x, -1, false}; }
  static Val of_integer(double x) { return {Kind::number, x, -1, true}; }
  static Val of_symbol(int s) { return {Kind::symbol, 0, s, false}; }
};

// Names numbered in order of first use: the variables of a trace (one slot a name, shared by
// every monitor of a run) and the symbols that are values (enum literals, alternatives).
class NameTable {
 public:
  int id(const std::string& name);  // adds the name when new
  std::optional<int> find(const std::string& name) const;
  const std::string& name(int id) const { return names_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return names_.size(); }

 private:
  std::unordered_map<std::string, int> ids_;
  std::vector<std::string> names_;
};
using Symbols = NameTable;
using Variables = NameTable;

// How an identifier of a requirement is read: a variable slot or a literal symbol.
struct Resolved {
  enum class Kind { variable, literal, unknown } kind = Kind::unknown;
  int id = -1;
};
using Resolver = std::function<Resolved(const std::string&)>;

// absReal, ite, preBool, …: FRET's functions the monitor evaluates.
bool is_monitored_function(const std::string& name);

// A FRETISH expression compiled for evaluation once per tick: FRET's operators, arithmetic,
// absReal/absInt, minReal/maxReal/minInt/maxInt, ite, preBool/preInt/preReal (the value at
// the previous tick, or the first argument at the first tick), and FRET's predefined FTP (true
// at the first tick only) when no variable has that name.
class CompiledExpression {
 public:
  // Fails (returns nullopt, with `error` set) for an unknown identifier or function.
  static std::optional<CompiledExpression> compile(const fretish::Expr& e, const Resolver& resolve,
                                                   std::string& error);

  // Evaluates the expression at this tick; `error` is set on a type error (then the value is
  // missing). Call exactly once per tick: pre* keep the previous tick's value.
  Val evaluate(const std::vector<Val>& frame, std::string& error);
  bool evaluate_bool(const std::vector<Val>& frame, std::string& error);

  const std::vector<int>& variables() const { return variables_; }  // slots read

 private:
  enum class K : std::uint8_t {
    constant,
    variable,
    logical_not,
    logical_and,
    logical_or,
    logical_xor,
    implies,
    iff,
    eq,
    ne,
    lt,
    le,
    gt,
    ge,
    add,
    sub,
    mul,
    div,
    mod,
    pow,
    negate,
    abs,
    min,
    max,
    ite,
    previous,
    first_tick
  };
  struct N {
    K kind = K::constant;
    std::vector<int> args;
    Val constant;
    int slot = -1;
    std::string name;  // variable: for messages
    int state = -1;    // previous: index into previous_
  };
  int build(const fretish::Expr& e, const Resolver& resolve, std::string& error);
  Val eval(int node, const std::vector<Val>& frame, std::string& error);

  std::vector<N> nodes_;
  int root_ = -1;
  std::vector<int> variables_;
  struct Previous {
    bool seen = false;
    Val value;
  };
  std::vector<Previous> previous_;
  std::vector<int> previous_nodes_;  // pre* nodes, outermost last
  bool first_tick_ = true;           // FTP: no tick evaluated yet
};

}  // namespace uabt::monitor
