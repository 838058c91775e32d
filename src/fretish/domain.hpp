#pragma once
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "base/location.hpp"
#include "fretish/expr.hpp"

namespace uabt::fretish {

enum class VarType { boolean, integer, real, enumeration };

const char* var_type_name(VarType t);

// Most literals an enum may declare. The explicit-state prover branches over every value of
// an environment enum, and the solvers give each literal a constructor: beyond this, memory
// and time grow past what a gate can spend, so a larger enum is refused at its declaration.
inline constexpr std::size_t kMaxEnumValues = 4096;

// A state variable the guards range over (FRET glossary types).
struct Variable {
  std::string name;
  VarType type = VarType::boolean;
  // Bounds as literal text (exact for the solver); empty = unbounded.
  std::string lower, upper;
  std::vector<std::string> enum_values;  // enumeration literals, declaration order
  SourceLocation location;
  bool declared = true;  // false: inferred (an undeclared identifier used as a condition)
  // Why the declaration cannot be used as written (an empty range…), reported as
  // domain-invalid; "" when it is fine. Guard checks over such a variable are not made.
  std::string invalid;
};

// Whether a number written for a variable (in a scenario, a trace, world.json) is an integer:
// the type declared for the variable decides, not how JSON writes the number. A real
// variable's number is a real (`12` as well as `12.5`); an integer variable's is an integer
// when it is whole and within 64 bits (`12`, `12.0`). Without a number type declared
// (nullopt, a boolean, an enum) the number is what JSON writes, `written_integer` (`12`, a
// whole number within 64 bits, is an integer; `12.0` a real), and so is a number that fits no
// integer (12.5 for an integer variable), for the reader's type check to refuse.
bool number_is_integer(std::optional<VarType> declared, double number, bool written_integer);

// The declaration as domain.fret writes it: "integer wind in [0, 15]", "enum terrain in {…}".
std::string declaration_text(const Variable& v);
// Same name aside, the same type, bounds (by value) and set of enum literals.
bool same_declaration(const Variable& a, const Variable& b);

// An expression that always holds (domain.fret `assume`, or a FRET "assumption" requirement).
struct Assumption {
  std::string name;
  ExprPtr expr;
  SourceLocation location;
};

// Seconds per time unit as a duration or the tick period writes it: FRETISH's words
// (millisecond, secs, minutes, hour, …) and uabt's abbreviations (ms, us, s, min, h), in any
// case; nullopt for ticks.
std::optional<double> seconds_per_unit(std::string_view unit);

namespace detail {

// Where each name and enum literal of a domain's variables is, so that a lookup costs the same
// for 20,000 variables as for 20: a guard that names every one of them is checked in linear
// time. Built on demand over the variables added since the last lookup (variables are only
// ever appended), under a lock, since verify's threads look names up concurrently. A copy
// starts empty: it indexes its own vector.
class NameIndex {
 public:
  static constexpr std::size_t kNone = SIZE_MAX, kAmbiguous = SIZE_MAX - 1;
  NameIndex() = default;
  NameIndex(const NameIndex&) {}
  NameIndex& operator=(const NameIndex&) {
    std::lock_guard lock(mutex_);
    clear();
    return *this;
  }
  // The position of the variable `name` in `variables` (the first, as a scan finds it), or
  // kNone.
  std::size_t variable(const std::vector<Variable>& variables, const std::string& name) const;
  // The position of the only enum variable with the literal, kAmbiguous or kNone.
  std::size_t enum_owner(const std::vector<Variable>& variables, const std::string& literal) const;

 private:
  void update(const std::vector<Variable>& variables) const;
  void clear() const {
    names_.clear();
    literals_.clear();
    indexed_ = 0;
  }
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::string, std::size_t> names_, literals_;
  mutable std::size_t indexed_ = 0;
};

}  // namespace detail

struct Domain {
  std::vector<Variable> variables;  // only appended to: index_ relies on it
  std::vector<Assumption> assumptions;
  // `tick 100 ms`: seconds per tick, so that durations in time units become ticks.
  std::optional<double> tick_seconds;
  SourceLocation tick_location;

  const Variable* find(const std::string& name) const;
  Variable* find(const std::string& name);
  // Name of the enum variable that has `literal` among its values, if exactly one has.
  const Variable* enum_owning(const std::string& literal) const;

 private:
  detail::NameIndex index_;
};

// number_is_integer for a number written for the variable `declared` (nullptr: a name the
// domain does not declare).
inline bool number_is_integer(const Variable* declared, double number, bool written_integer) {
  return number_is_integer(declared != nullptr ? std::optional(declared->type) : std::nullopt,
                           number, written_integer);
}

}  // namespace uabt::fretish
