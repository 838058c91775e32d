#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/requirement.hpp"

namespace uabt::fretish {

// A requirement that chooses an alternative of an adaptable node (ARCHITECTURE §3):
// "In <adaptable> [if <guard>] Mission shall [immediately] satisfy selected_alt = <alt>".
struct SelectionRequirement {
  std::string id;
  std::string adaptable;
  std::string alternative;
  ExprPtr guard;                        // nullptr: the node's default
  SourceLocation location;              // the requirement's start
  SourceLocation guard_location;        // first condition, or the requirement's start
  SourceLocation alternative_location;  // the alternative's name in the response
  int source_index = 0;                 // position in the requirement set (priority order)
};

struct Classification {
  std::vector<SelectionRequirement> selections;  // file order
  std::vector<Requirement> properties;  // mission properties (ARCHITECTURE §10), file order
};

// Classifies parsed requirements. A requirement that reads `selected_alt` but is outside the
// selection subset gets a `fretish-unsupported` error naming each field (scope, component,
// timing, response); so do what has no meaning at all (a freeform sentence, `with
// probability`). Every other requirement is a mission property.
Classification classify_requirements(const std::vector<Requirement>& requirements,
                                     std::vector<Finding>& findings);

// The selection requirements of classify_requirements.
std::vector<SelectionRequirement> classify_selection(const std::vector<Requirement>& requirements,
                                                     std::vector<Finding>& findings);

}  // namespace uabt::fretish
