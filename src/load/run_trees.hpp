// Which trees a run of the mission instantiates (ARCHITECTURE §12): the main tree, the trees its
// SubTrees call, and at each adaptable node the alternatives a requirement selects, with theirs.
// A tree nothing calls is in the files but has no node in the run, as in BehaviorTree.CPP's
// createTree. One rule for every stage that names the nodes a run has: the gate's property
// check and realize read it; the engine built on the compiled tree has exactly these nodes.
#pragma once
#include <string>
#include <vector>

#include "load/mission.hpp"

namespace uabt::load {

struct RunTree {
  const bt::TreeDef* tree = nullptr;
  const Alternative* alternative = nullptr;  // the alternative the tree came with, or none
};

// Whether the compiler copies `alt` into the tree. Unknown while a requirement of its node does
// not parse: counted as selected, so that one mistake is not reported twice.
bool selected(const Mission& m, const Alternative& alt);

// The trees a run instantiates, each once, main tree first. SubTree IDs resolve as in the
// compiled document: the mission's trees first, then each selected alternative's in order.
// Without a main tree (a load error says why), every tree of the mission and of the selected
// alternatives.
std::vector<RunTree> run_trees(const Mission& m);

}  // namespace uabt::load
