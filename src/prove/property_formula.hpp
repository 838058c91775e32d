#pragma once
#include <array>
#include <string>
#include <vector>

#include "fretish/expr.hpp"
#include "monitor/expression.hpp"
#include "monitor/formula.hpp"
#include "monitor/templates.hpp"

namespace uabt::prove {

// A property's monitor as one past-time formula over atoms: boolean expressions of a single
// tick's state, which the engines evaluate (the explicit one on the blackboard, the symbolic one
// as terms). A part without FRET's temporal functions is one atom; in a part with them,
// persisted(n, p), occurred(n, p), prevOcc(p, q) and FTP become past-time subformulas over the
// atoms of their arguments, with the same meaning as monitor::CompiledExpression (FRET's
// expansions, counted from the scope's left end point): bounded ages and since-bits, constant
// state like the `within` and `for` timings.
struct PropertyFormula {
  monitor::Formula formula;
  int root = -1;
  int mode = -1, condition = -1;        // the nodes of the parts that trigger, -1 when absent
  std::vector<fretish::ExprPtr> atoms;  // input k is atoms[k] at this tick
  std::string unsupported;              // why prove cannot read a part ("" when it can)
};

// `parts` are the mode, condition, response, stop condition and a trap's condition
// (fretish::Requirement::judged), null where absent; `resolve` tells FRET's FTP from a variable
// of that name.
PropertyFormula build_property_formula(const monitor::Shape& shape,
                                       const std::array<fretish::ExprPtr, 5>& parts,
                                       const monitor::Resolver& resolve);

}  // namespace uabt::prove
