#pragma once
#include "gate/gate.hpp"

namespace uabt::gate {

// The gate's realizability step (ARCHITECTURE §15), after its proofs: whether any tree could meet
// the mission's guarantees in every world its assumptions and world.json's results allow. When
// no tree could and the proofs did not show the mission's tree meeting them, each minimal
// conflict is a `requirements-unrealizable` error (an uplink's requirements named first): fix
// the requirements, not the tree. When the mission's tree was proved to meet them, they are
// realizable in world.json's world and a conflict is a note (they rely on what the world does
// beyond the stated assumptions); a component not decided is a note too, because the proofs
// decide the admission of the tree. Nothing when the mission states no guarantee.
void add_realizability(Outcome& outcome);

}  // namespace uabt::gate
