#pragma once
#include <set>
#include <string>
#include <vector>

#include "bt/tree.hpp"

namespace uabt::testing::mutation {

// How a mutant must fare under conformance checking.
enum class Kind {
  deviation,  // leaves the prescribed shape or source (maybe behaviour-preserving): must be caught
  guard,      // changes only condition-checking subtrees: the guard oracle decides
  rewrite,    // an equivalence-preserving rewrite of a guard: must be accepted
};

struct Mutant {
  std::string op;           // operator name, e.g. "negate-guard"
  std::string description;  // where and what
  Kind kind = Kind::deviation;
  bt::Document document;
};

// What the mutator must know about the compiled document's trees.
struct Layout {
  std::vector<std::string> adaptables;      // selection tree IDs
  std::set<std::string> fixed_trees;        // the trees of mission.xml
  std::set<std::string> alternative_trees;  // the alternatives' trees
};

// Every first-order mutant of every operator (see mutator.cpp for the list).
std::vector<Mutant> all_mutants(const bt::Document& compiled, const Layout& layout);

// The operators in the order they are reported.
const std::vector<std::string>& operator_names();

}  // namespace uabt::testing::mutation
