#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/requirement.hpp"

namespace uabt::fretish {

// A requirement that chooses an alternative of an adaptable node (DESIGN §3):
// "In <adaptable> [if <guard>] Mission shall [immediately] satisfy selected_alt = <alt>".
struct SelectionRequirement {
  std::string id;
  std::string adaptable;
  std::string alternative;
  ExprPtr guard;               // nullptr: the node's default
  SourceLocation location;     // the requirement's start
  SourceLocation guard_location;        // first condition, or the requirement's start
  SourceLocation alternative_location;  // the alternative's name in the response
  int source_index = 0;        // position in the requirement set (priority order)
};

// Classifies parsed requirements. Those outside the subset get a `fretish-unsupported`
// error that names the field (scope, timing, response, component, probability).
std::vector<SelectionRequirement> classify_selection(const std::vector<Requirement>& requirements,
                                                     std::vector<Finding>& findings);

}  // namespace uabt::fretish
