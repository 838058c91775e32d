#pragma once
#include <string>
#include <unordered_map>
#include <vector>

#include "base/finding.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"

namespace uabt::smt {

// The sort of a FRETISH sub-expression. Enumerations are told apart by their declaring
// variable (two enums with the same literal list are compatible).
enum class Sort { boolean, integer, real, enumeration, invalid };

const char* sort_name(Sort s);

struct TypeInfo {
  Sort sort = Sort::invalid;
  const fretish::Variable* enum_type = nullptr;  // enumeration: the variable declaring it
  // Identifiers only: what the name resolved to.
  const fretish::Variable* variable = nullptr;  // a domain variable
  int enum_index = -1;                          // an enumeration literal (index into enum_type)
  bool implicit_boolean = false;                // not in the domain, used as a condition
};

// Types of every node of the expressions checked so far, keyed by node address (the
// mission's expression trees outlive every analysis of them).
class Typing {
 public:
  const TypeInfo* find(const fretish::Expr& e) const;
  const TypeInfo& at(const fretish::Expr& e) const;  // throws std::out_of_range
  void set(const fretish::Expr& e, TypeInfo info) { types_[&e] = info; }

 private:
  std::unordered_map<const fretish::Expr*, TypeInfo> types_;
};

// Type checks a condition (a guard or an assumption) against the domain and records the type
// of each node in `typing`. Mismatches become `ref-type-mismatch` errors, a division by a
// literal zero an `arith-division-by-zero` error, each at the offending sub-expression of
// `file`. Returns true when the condition is well typed (warnings allowed).
bool check_condition(const fretish::Expr& condition, const fretish::Domain& domain,
                     const SourceLocation& where, Typing& typing, std::vector<Finding>& findings);

// Lookups that do not depend on the loader having filled the domain in a particular way.
const fretish::Variable* find_variable(const fretish::Domain& domain, const std::string& name);
int enum_literal_index(const fretish::Variable& enum_variable, const std::string& literal);

// A number written as zero (`0`, `0.0`, `-0`): a divisor every state makes zero.
bool is_literal_zero(const fretish::Expr& e);

// FRET's arithmetic functions (absInt … ite) and their arity.
bool is_known_function(const std::string& name, std::size_t& arity);

}  // namespace uabt::smt
