#pragma once
#include "load/mission.hpp"

namespace uabt::load {

// One mistake, one finding: what a broken input makes unknowable is not reported as if it were
// known. Marks in m.not_verified the adaptable nodes whose guard checks would be meaningless: a
// requirement that does not parse (the nodes its line names, else every node), and a
// variable whose declaration is invalid (the nodes whose guards read it, directly or through
// assumptions that tie it to what they read).
void mark_unknowable(Mission& m);

}  // namespace uabt::load
