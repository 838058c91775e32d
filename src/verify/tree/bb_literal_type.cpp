// bb-literal-type: BT.CPP converts a port's literal with convertFromString<T> of the port's
// type; a literal that does not convert fails in getInput(), on the robot.
#include "bt/port_types.hpp"
#include "verify/tree/blackboard_checks.hpp"

namespace uabt::verify::tree {

using bt::literal_converts;

std::vector<Finding> check_literal_types(const FlowGraph& g) {
  std::vector<Finding> out;
  for (const LiteralPort& p : g.literal_ports) {
    if (literal_converts(p.value, p.type)) continue;
    Finding f = make_finding("bb-literal-type",
                             "port '" + p.port + "' of " + p.node_kind + " is \"" + p.value +
                                 "\", which does not convert to its type " + p.type +
                                 " (nodes.xml): BehaviorTree.CPP's getInput() fails there",
                             p.location);
    f.notes.push_back("write a " + p.type + " literal, or read the value from an entry ({key})");
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace uabt::verify::tree
