#pragma once
#include <string>
#include <vector>

#include "fretish/expr.hpp"
#include "load/mission.hpp"

namespace uabt::load {

// Identifiers a guard or assumption uses as a truth value (operands of ! & | xor -> <->, or
// the whole expression): these are condition leaves of the robot.
std::vector<const fretish::Expr*> boolean_atoms(const fretish::Expr& e);

// ARCHITECTURE §3: an undeclared identifier used as a condition is a boolean. Adds such identifiers
// to the domain (declared = false) so that every later stage sees one set of variables.
void infer_condition_variables(Mission& m);

// ref-* checks: requirements, adaptable nodes, alternatives and tree IDs refer to each other.
void check_references(Mission& m);

}  // namespace uabt::load
