#pragma once
#include <vector>

#include "fretish/expr.hpp"
#include "smt/types.hpp"

namespace uabt::smt {

// True for the nodes that make up a condition's boolean skeleton: ! & | xor -> <->, and
// = / != between two conditions (which mean <-> and xor).
bool is_boolean_structure(const fretish::Expr& e, const Typing& typing);

// The atom occurrences of a type-checked condition, left to right: the maximal
// sub-expressions below the boolean skeleton (a boolean variable, a relation, a boolean ite),
// truth-value literals excluded. Every condition is a boolean function of its atoms.
std::vector<const fretish::Expr*> atom_occurrences(const fretish::Expr& condition,
                                                   const Typing& typing);

}  // namespace uabt::smt
