#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "fretish/evaluate.hpp"
#include "fretish/expr.hpp"

namespace uabt::monitor {

// The value of one variable at one tick, and of an expression: fretish::Val, whose operators
// are the one meaning every evaluator shares (ARCHITECTURE §14). Enum literals and other names
// are interned symbols. A number is an integer when its variable is declared integer, its
// literal or JSON value is written without a fraction or exponent, or it is computed from
// integers.
using Val = fretish::Val;

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

// How an evaluation reads a variable whose value may not be chosen yet (a model checker's
// environment, chosen when first read): with a reader, an expression reaches each variable just
// before it reads it from the frame, and reads no argument its value does not depend on.
class Reader {
 public:
  virtual ~Reader() = default;
  // `slot` is about to be read: its value is in the frame afterwards (the reader may write it
  // there, into the very frame the evaluation reads).
  virtual void reach(int slot) = 0;
  // Whether `slot`'s value, reached now, is sure not to be a known value of another kind than
  // boolean (without reaching it).
  virtual bool boolean(int slot) const = 0;
};

// absReal, ite, preBool, persisted, …: FRET's functions the monitor evaluates.
bool is_monitored_function(const std::string& name);

// persisted, occurred, prevOcc: FRET's past-time temporal functions (they read earlier ticks).
bool is_temporal_function(const std::string& name);

// Why FRET's temporal function `name` with `args` arguments is not monitored, in FRET's terms
// (nextOcc, persists, occurs look ahead; the three-argument forms need a window), or "".
std::string unmonitored_temporal(const std::string& name, std::size_t args);

// Where an expression stands in its requirement, for FRET's temporal functions: in the scope's
// mode FRET expands them without the scope (xform.js, pastTemporalConditionsNoBounds); in the
// condition, response and stop condition they count from the scope's left end point ($Left$),
// which the caller gives each tick (set_scope_start), and which is FRET's FTP until then.
enum class Field { mode, other };

// A FRETISH expression compiled for evaluation once per tick: FRET's operators, arithmetic,
// absReal/absInt, minReal/maxReal/minInt/maxInt, ite, preBool/preInt/preReal (the value at
// the previous tick, or the first argument at the first tick), and FRET's predefined FTP (true
// at the first tick only) when no variable has that name.
class CompiledExpression {
 public:
  // Fails (returns nullopt, with `error` set) for an unknown identifier or function.
  static std::optional<CompiledExpression> compile(const fretish::Expr& e, const Resolver& resolve,
                                                   std::string& error, Field field = Field::other);

  // Whether this tick is the first point of the requirement's scope (FRET's $Left$), for
  // persisted/occurred/prevOcc; call before evaluate(). Without a call, the first tick is.
  void set_scope_start(bool left) { left_ = left; }
  bool has_temporal_functions() const { return !temporal_nodes_.empty(); }

  // Evaluates the expression at this tick; `error` is set on a type error (then the value is
  // missing). Call exactly once per tick: pre* keep the previous tick's value. With `reader`,
  // every variable is reached before it is read, and `&`, `|`, `=>` and ite read their
  // arguments left to right and stop once the value is decided (fretish::apply's value on all
  // of them); the temporal functions and pre* still read all of theirs.
  Val evaluate(const std::vector<Val>& frame, std::string& error, Reader* reader = nullptr);
  bool evaluate_bool(const std::vector<Val>& frame, std::string& error, Reader* reader = nullptr);

  const std::vector<int>& variables() const { return variables_; }  // slots read

 private:
  enum class K : std::uint8_t {
    constant,
    variable,
    apply,  // a connective, relation, arithmetic or function: fretish::apply
    previous,
    first_tick,
    persisted,  // FRET: (H[<=n] p) & (H[<n] !$Left$)
    occurred,   // FRET: ((!$Left$) S p) & (O[<=n] p)
    prev_occ    // FRET: $Left$ | Y(((!$Left$ & !p) S p) => ((!$Left$ & !p) S (p & q)))
  };
  struct N {
    K kind = K::constant;
    fretish::Op op = fretish::Op::unknown;
    std::vector<int> args;
    Val constant;
    int slot = -1;
    std::string name;         // variable: for messages
    int state = -1;           // previous: index into previous_; temporal: into temporal_
    std::uint64_t bound = 0;  // persisted, occurred: n
  };
  int build(const fretish::Expr& e, const Resolver& resolve, std::string& error);
  Val eval(int node, const std::vector<Val>& frame);
  // An `&`, `|`, `=>` or ite node with reader_: its arguments until its value is decided.
  Val eval_lazily(const N& n, const std::vector<Val>& frame);
  // Whether node's value cannot be a known value of another kind than boolean.
  bool never_other_than_boolean(int node) const;
  Reader* reader_ = nullptr;  // this evaluation's
  std::string unset_;         // this tick: the first variable read that has no value
  std::string message(const Val& v) const;

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
  // Constant state of a temporal function: two ages that stop at bound + 1 and two bits.
  struct Temporal {
    std::uint64_t age_a = ~std::uint64_t{0};     // persisted: ticks since !p; occurred: since p
    std::uint64_t age_left = ~std::uint64_t{0};  // ticks since $Left$
    bool since_a = false;  // occurred: (!$Left$) S p; prevOcc: (!$Left$ & !p) S p
    bool since_b = false;  // prevOcc: (!$Left$ & !p) S (p & q)
    bool value = false;    // this tick's value
  };
  std::vector<Temporal> temporal_;
  std::vector<int> temporal_nodes_;  // inner ones first
  Field field_ = Field::other;
  std::optional<bool> left_;  // $Left$ at this tick, when given
  bool update_temporal(const std::vector<Val>& frame, std::string& error);
};

}  // namespace uabt::monitor
