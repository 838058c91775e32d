#pragma once
#include "conform/context.hpp"

namespace uabt::conform {

// compiled-adaptable-left: an <Adaptable> anywhere in the compiled document.
void check_adaptables_left(Context& ctx);

// compiled-dangling-subtree: a SubTree whose ID names no tree of the compiled document.
void check_dangling_subtrees(Context& ctx);

// compiled-fixed-part-changed: every tree of mission.xml (and its main tree choice) must be in
// the compiled document unchanged, except that each <Adaptable ID="A"/> became a SubTree call.
void check_fixed_part(Context& ctx);

// bt-structure over every tree of the compiled document, <Adaptable> not allowed.
void check_compiled_structure(Context& ctx);

}  // namespace uabt::conform
