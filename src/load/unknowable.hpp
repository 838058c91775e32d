#pragma once
#include "load/mission.hpp"

namespace uabt::load {

// One mistake, one finding: what a broken input makes unknowable is not reported as if it were
// known. Marks in m.not_verified the adaptable nodes whose guard checks would be meaningless: a
// requirement that does not parse (the nodes its line names, else every node), and a
// declaration that is invalid (every node: the domain is unknown until it is fixed).
void mark_unknowable(Mission& m);

}  // namespace uabt::load
