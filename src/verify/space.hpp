#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/value.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "smt/types.hpp"
#include "verify/bits.hpp"
#include "verify/fraction.hpp"
#include "verify/linear.hpp"
#include "verify/real_cells.hpp"

namespace uabt::verify::detail {

// One digit of the enumerated space: a discrete variable (its values) or a real component
// (its cells).
struct Dimension {
  std::string name;  // the variable; a component: its variables joined by ", "
  const fretish::Variable* declaration = nullptr;  // nullptr: implicit boolean or component
  smt::Sort sort = smt::Sort::boolean;             // real: a component
  std::int64_t lowest = 0;                         // integers: the value of digit 0
  std::uint64_t radix = 2;
  int component = -1;  // index into Space::components() for real dimensions

  // The value as CompiledCondition reads it: 0/1, the literal index, or the integer.
  std::int64_t number(std::uint64_t digit) const {
    return sort == smt::Sort::integer ? lowest + static_cast<std::int64_t>(digit)
                                      : static_cast<std::int64_t>(digit);
  }
};

// The state space of one adaptable node, enumerated exactly: discrete variables by value, real
// variables by the cells their atoms' boundaries cut them into (ARCHITECTURE §5). Discrete
// dimensions come first (fastest digits), so the states of one combination of real cells are
// one run of indices and a measure is a weighted sum of run counts.
class Space {
 public:
  Space(const fretish::Domain& domain, const smt::Typing& typing)
      : domain_(domain), typing_(typing) {}

  // Sets up the space over `names`, cutting real ranges at the boundaries of `atoms`. Returns
  // why it cannot be enumerated ("" when it can). Atoms that cannot be measured exactly are
  // remembered with the reason (unmeasured()).
  std::string plan(const std::set<std::string>& names,
                   const std::vector<const fretish::Expr*>& atoms);

  const fretish::Domain& domain() const { return domain_; }
  std::uint64_t size() const { return size_; }
  const std::vector<Dimension>& dimensions() const { return dims_; }
  const std::vector<RealComponent>& components() const { return components_; }
  bool has_reals() const { return !components_.empty(); }
  // The first real variable the space cuts into cells ("" when none).
  const std::string& first_real() const {
    static const std::string none;
    return components_.empty() ? none : components_.front().axes.front().variable;
  }
  // Why some atom is not measured exactly (first reason), "" when every atom is.
  const std::string& unmeasured() const { return unmeasured_; }

  // Where a condition holds (three-valued, see Truth).
  Truth truth(const fretish::Expr& e);
  // The measure of a set: its size when every variable is discrete, else the sum over the
  // discrete points of the length, area or volume of its real part.
  Fraction measure(const Bits& set) const;
  // The measure of one state.
  const Fraction& weight(std::uint64_t state) const { return weights_[state / discrete_size_]; }
  // The digit of dimension `d` in `state`.
  std::uint64_t digit(std::uint64_t state, std::size_t d) const {
    return (state / strides_[d]) % dims_[d].radix;
  }
  std::uint64_t stride(std::size_t d) const { return strides_[d]; }
  // The state (cell) a full assignment lies in; nullopt when a value is missing or outside.
  // A real lies at a breakpoint as side_of says, so a run's state lands in the cell whose
  // atoms have the values the run computed.
  std::optional<std::uint64_t> state_of(const State& state) const;

 private:
  struct AtomPlan {
    enum class Kind { discrete, linear, unmeasured } kind = Kind::discrete;
    std::optional<LinearAtom> linear;
  };

  const fretish::Domain& domain_;
  const smt::Typing& typing_;
  std::vector<Dimension> dims_;
  std::vector<RealComponent> components_;
  std::vector<std::uint64_t> strides_;
  std::uint64_t size_ = 0;
  std::uint64_t discrete_size_ = 1;
  std::vector<Fraction> weights_;          // per combination of real cells
  std::map<std::string, AtomPlan> plans_;  // by FRETISH text
  std::map<std::string, Truth> atoms_;     // by FRETISH text: repeated atoms evaluated once
  std::string unmeasured_;

  Truth atom(const fretish::Expr& e);
  void note_unmeasured(const std::string& reason) {
    if (unmeasured_.empty()) unmeasured_ = reason;
  }
};

// The variables a condition reads (domain variables and implicit booleans).
void variables_of(const fretish::Expr& e, const smt::Typing& typing, std::set<std::string>& out);

// A number's exact value: an integer, or a real's text ("1/3", "-0.25", "7").
std::optional<Fraction> exact_value(const Value& v);

// Where a number lies against a breakpoint: -1 below, 0 at, 1 above; nullopt for a value that
// is no number (or NaN). A run's real is a double, and the one evaluator compares doubles, so a
// real lies at a breakpoint when it is the breakpoint's nearest double: the value a scenario writes
// for it (1/3 as 0.3333333333333333), where the run's guard holds as at 1/3. An integer compares
// exactly. Every reading of a run's state against the cells (enumerated and solved campaign
// nodes, coverage) asks this.
std::optional<int> side_of(const Value& v, const Fraction& breakpoint);

}  // namespace uabt::verify::detail
