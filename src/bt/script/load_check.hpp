#pragma once
// What BehaviorTree.CPP refuses about a node's scripts when it builds the tree: the one rule set
// the engine applies at build time and the static checks apply before (so that compile and
// verify refuse exactly what the engine refuses).
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

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

// Every refusal for the scripts of `node`: (attribute it concerns, message), in attribute order.
std::vector<std::pair<std::string, std::string>> node_script_refusals(const Node& node);

}  // namespace uabt::bt::script
