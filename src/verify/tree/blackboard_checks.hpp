#pragma once
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "verify/tree/flow_graph.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::tree {

// bb-read-before-write: an entry read where some path of ticks from the root has not written
// it (BT.CPP fails there); the shortest such path is the witness (relatedLocations).
std::vector<Finding> check_read_before_write(const FlowGraph& graph);

// bb-type-conflict: one entry used with two types BT.CPP refuses to mix (nodes.xml port types,
// the values scripts assign), reported at both places.
std::vector<Finding> check_type_conflicts(const FlowGraph& graph);

// bb-literal-type: a port's literal that does not convert to the port's nodes.xml type.
std::vector<Finding> check_literal_types(const FlowGraph& graph);

class DomainQuestions;

// script-decided: a condition script (ScriptCondition, _skipIf, _failureIf, _successIf,
// _while) over the domain that the domain makes always or never true.
std::vector<Finding> check_script_decided(const FlowGraph& graph, const load::Mission& mission,
                                          DomainQuestions& questions);

// script-out-of-range: an assignment to a domain variable whose value is outside the
// variable's declared range in every state of the domain.
std::vector<Finding> check_script_range(const FlowGraph& graph, const load::Mission& mission,
                                        DomainQuestions& questions);

// guard-division-by-zero, arith-division-by-zero: a script's division over the domain whose
// divisor is zero, or can be where it is evaluated, checked as a guard's division is.
std::vector<Finding> check_script_divisions(const FlowGraph& graph, const load::Mission& mission,
                                            DomainQuestions& questions, const Options& options);

// The blackboard and script checks above on the mission, its alternatives and merged uplinks.
std::vector<Finding> check_blackboard_and_scripts(const load::Mission& mission,
                                                  const Options& options);

}  // namespace uabt::verify::tree
