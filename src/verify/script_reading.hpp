#pragma once
#include <string>
#include <vector>

#include "bt/script/ast.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"

namespace uabt::verify {

// A script read as a FRETISH expression: the one reading of the script language for every
// stage that reasons about a tree (conform, verify's whole-tree checks, the symbolic prover).
// The engine (runtime/script/eval.cpp) runs the script; ScriptMeaning.* checks that the two
// agree.
struct ScriptReading {
  fretish::ExprPtr expr;  // nullptr when `error` says why the code is not a condition
  std::string error;
  // Blackboard entries the code reads without the `@` root prefix: they resolve through the
  // SubTree blackboards between the script and the tree that owns the state.
  std::vector<std::string> local_reads;
};

// Parses BehaviorTree.CPP 4.x script syntax as a side-effect-free condition: numbers,
// true/false, identifiers (blackboard entries; `@x` is the root blackboard's x), 'quoted'
// strings (enum literals: `'rocks'` is the literal rocks), parentheses, unary - and !,
// * /, + -, comparison chains (`a < b < c` is `a < b && b < c`), and && || (one precedence
// level, left-associative, as in BT.CPP's grammar), and `c ? a : b` as `ite(c, a, b)`.
// Assignments, `;`, `..` and bitwise operators are refused. The reading keeps BT.CPP's meaning
// where FRETISH's differs: `/` divides as doubles (`x / 2` of an integer x reads `x / 2.0`), and
// `==`/`!=` with a real operand hold within float epsilon of equal (`a - b <= eps & b - a <= eps`).
// `domain` tells enum literals from variables: a quoted string must be a literal of one of its
// enums, an unquoted name must not be only a literal.
ScriptReading parse_script_condition(const std::string& code, const fretish::Domain& domain);

// One expression of a parsed script (a statement, or an assignment's value) read the same way:
// the whole-tree checks ask the domain about preconditions and assigned values with it.
// `names_as_written` keeps a root name's `@` in the identifier (`@x` and `x` may be two entries
// for a reader that resolves them in the script's own scope, as the symbolic engine does).
ScriptReading read_script_expression(const bt::script::Script& script, std::uint32_t index,
                                     const fretish::Domain& domain, bool names_as_written = false);

}  // namespace uabt::verify
