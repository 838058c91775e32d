#pragma once
#include "fretish/expr.hpp"

namespace uabt::fretish {

// The relation with its sides swapped: a < b is b > a (= and != stay).
ExprKind mirrored_relation(ExprKind kind);

}  // namespace uabt::fretish
