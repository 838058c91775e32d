#pragma once
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <z3++.h>

#include "base/finding.hpp"
#include "base/value.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "smt/types.hpp"

namespace uabt::smt {

// Lowers FRETISH conditions over one domain into Z3. Owns the run's z3::context, so every
// formula of a run shares one variable per state variable. Integers and reals map to Z3 Int
// and Real; an enumeration is an Int in [0, n) whose literals are their indices; a name that
// is not in the domain and is used as a condition is a Bool.
class Encoder {
 public:
  // One state variable as the solver sees it.
  struct Slot {
    std::string name;
    Sort sort;
    const fretish::Variable* declaration;  // nullptr for an implicit boolean
    z3::expr constant;
  };

  // One conjunct of the domain constraint D, with what it stands for (to name an unsat core).
  struct DomainPart {
    std::string description;  // "battery in [0, 100]", "assumption one_terrain"
    z3::expr constraint;
    SourceLocation location;
  };

  // `domain` must outlive the encoder and not change while it is used.
  explicit Encoder(const fretish::Domain& domain);
  Encoder(const Encoder&) = delete;
  Encoder& operator=(const Encoder&) = delete;

  z3::context& context() { return context_; }
  const fretish::Domain& domain() const { return domain_; }
  const Typing& typing() const { return typing_; }

  // Type checks and lowers a condition. nullopt when it is ill-typed; `findings` says why.
  std::optional<z3::expr> lower_condition(const fretish::Expr& condition,
                                          const SourceLocation& where,
                                          std::vector<Finding>& findings);

  // Lowers a condition that lower_condition accepted, with the listed boolean sub-conditions
  // replaced by the given formulas (vacuity checks flip atom occurrences).
  z3::expr lower(const fretish::Expr& condition,
                 const std::unordered_map<const fretish::Expr*, z3::expr>& overrides = {});

  // D: variable ranges, enumeration membership and the domain's assumptions. Ill-typed
  // assumptions and unreadable bounds are reported and left out.
  std::vector<DomainPart> domain_parts(std::vector<Finding>& findings);

  // Every variable: the domain's in declaration order, then implicit booleans in first-use order.
  const std::vector<Slot>& variables() const { return slots_; }
  const Slot* find_slot(const std::string& name) const;

  // A Bool constant no FRETISH name can clash with (assumption literals, definitions).
  z3::expr fresh_literal(const char* prefix);

  // A full assignment of variables() from a model (model completion for unconstrained ones).
  State state_of(const z3::model& model) const;

 private:
  z3::context context_;
  const fretish::Domain& domain_;
  Typing typing_;
  std::vector<Slot> slots_;
  std::unordered_map<std::string, std::size_t> slot_index_;

  struct Term {
    z3::expr e;
    Sort sort;
  };
  Term lower_term(const fretish::Expr& e,
                  const std::unordered_map<const fretish::Expr*, z3::expr>& overrides);
  // A long disjunction, its comparisons of an integer variable with numerals as ranges.
  z3::expr lower_disjunction(const fretish::Expr& e,
                             const std::unordered_map<const fretish::Expr*, z3::expr>& overrides);
  z3::expr as_real(const Term& t);
  z3::expr implicit_boolean(const std::string& name);
  std::optional<z3::expr> bound(const Slot& slot, const std::string& text, bool is_lower,
                                std::vector<Finding>& findings);
};

}  // namespace uabt::smt
