#pragma once
#include <vector>

#include "compile/selection_space.hpp"

namespace uabt::compile {

// One condition the decision structure ticks: "the dimension's piece is one of these".
struct DecisionTest {
  std::size_t dimension = 0;
  std::vector<bool> holds;  // per piece of the dimension
};

// A binary decision over the cells of a SelectionSpace. Every leaf carries one label (the
// first enabled requirement, -1 none) that is the label of every cell reaching it.
struct Decision {
  struct Node {
    int test = -1;          // -1: a leaf
    int yes = -1, no = -1;  // children (node indices)
    int label = -1;         // leaves
  };
  std::vector<DecisionTest> tests;
  std::vector<Node> nodes;
  int root = -1;
};

// Condition nodes ticked per selection: mean over the domain's states (weighted by their
// measure; by cell when the measure is zero) and the most in any state.
struct SelectionCost {
  double average = 0;
  int worst = 0;
};

// Greedy: at each node the test with the largest information gain about the label (by the
// states' measure, then by cell count), which makes a balanced search of ordered and enum
// variables and skips what the assumptions rule out.
Decision build_decision(const SelectionSpace& space);

SelectionCost decision_cost(const SelectionSpace& space, const Decision& decision);

// Algorithm 1's layout (Fig. 4): guards in priority order, each short-circuited, until one holds.
SelectionCost algorithm1_cost(const SelectionSpace& space);

}  // namespace uabt::compile
