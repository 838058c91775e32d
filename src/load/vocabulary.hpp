#pragma once
#include <string>
#include <vector>

#include "fretish/expr.hpp"
#include "load/mission.hpp"

namespace uabt::load {

// One expression whose names must be known: a guard, an assumption (later: a mission
// property). The check is the same for every kind; only the wording and what a broken one
// stops differ.
struct VocabularyUse {
  const fretish::Expr* expr = nullptr;
  SourceLocation owner;     // where the expression's requirement or assumption starts
  std::string requirement;  // its requirement id ("" for an assumption)
  std::string assumption;   // its assumption name ("" for a requirement)
  std::string adaptable;    // the adaptable node whose guard it is ("" otherwise)
};

// The guards of the selection requirements and the domain's assumptions, in file order.
std::vector<VocabularyUse> vocabulary_uses(const Mission& m);

// The vocabulary rule (missions/README.md). With a declared vocabulary (domain.fret or nodes.xml):
// every identifier of `uses` must be declared (`ref-undeclared`, with "did you mean"); the node
// whose guard reads an undeclared name, or every node for an assumption, is not verified; a
// declared variable nothing reads is `domain-unused-variable`. Without one: a name within two edits
// of another is `ref-similar-name`. Fills m.undeclared and m.not_verified.
void check_vocabulary(Mission& m, const std::vector<VocabularyUse>& uses);

}  // namespace uabt::load
