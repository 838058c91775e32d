#include "fretish/relation.hpp"

namespace uabt::fretish {

ExprKind mirrored_relation(ExprKind kind) {
  switch (kind) {
    case ExprKind::lt: return ExprKind::gt;
    case ExprKind::le: return ExprKind::ge;
    case ExprKind::gt: return ExprKind::lt;
    case ExprKind::ge: return ExprKind::le;
    default: return kind;
  }
}

}  // namespace uabt::fretish
