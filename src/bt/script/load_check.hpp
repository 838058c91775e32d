#pragma once
// What BehaviorTree.CPP refuses about a node's scripts when it builds the tree: the one rule set
// the engine applies at build time and the static checks apply before (so that compile and
// verify refuse exactly what the engine refuses).
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bt/script/ast.hpp"

namespace uabt::bt {
struct Node;
}

namespace uabt::bt::script {

// BT.CPP 4.x's pre- and post-condition attributes; each holds a script.
bool is_condition_attribute(std::string_view name);

// Why BT.CPP refuses the script `code` of `what` ("Script", "Sequence _skipIf"), or nullopt
// when it parses; `empty_refused` for a ScriptCondition, whose script must give a result.
std::optional<std::string> script_refusal(const std::string& what, const std::string& code,
                                          bool empty_refused);

// One script of a node as BT.CPP's builder sees it: the attribute that holds it ("" for a
// Script or ScriptCondition without its `code`), and either the parsed script or why BT.CPP
// refuses it.
struct NodeScript {
  std::string attribute;
  std::optional<Script> script;
  std::string refusal;  // "" when it parses
};

// Every script of `node`, each parsed once, in attribute order: what the engine builds from
// and what the static checks report.
std::vector<NodeScript> parse_node_scripts(const Node& node);

// Every refusal for the scripts of `node`: (attribute it concerns, message), in attribute order.
std::vector<std::pair<std::string, std::string>> node_script_refusals(const Node& node);

}  // namespace uabt::bt::script
