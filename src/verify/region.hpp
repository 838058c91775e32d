#pragma once
#include <string>
#include <utility>
#include <vector>

#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "smt/types.hpp"

namespace uabt::verify::detail {

// One literal of a cube: an atom of the guards, or its negation.
struct CubeLiteral {
  const fretish::Expr* atom;
  bool positive;
};

// Renders a cube for people: literals over one variable merge into an interval
// (`battery in [0, 19]`) or a set of enum literals (`terrain in {sand, mud}`); boolean
// variables read `OnDust` / `!OnDust`; anything else is the atom's FRETISH text.
std::string render_cube(const std::vector<CubeLiteral>& cube, const fretish::Domain& domain,
                        const smt::Typing& typing);

}  // namespace uabt::verify::detail
