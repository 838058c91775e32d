#pragma once
#include <z3++.h>

namespace uabt::smt {

// Assigns `value` to `to`, releasing the term `to` held. The z3++ header of Z3 4.8.12 (the one
// Debian bookworm ships) move-assigns an expression without releasing the term it replaces, so
// `acc = acc && next` leaks `acc`'s old term and everything under it until the context is
// deleted, and deleting a context that holds such terms is slow: on msl_curiosity the
// symbolic engine left about 4,900 references a run and spent 0.45 s deleting its context.
// Assign a temporary to an existing expression through this; it copies instead.
inline void assign(z3::expr& to, const z3::expr& value) {
  to = value;
}

}  // namespace uabt::smt
