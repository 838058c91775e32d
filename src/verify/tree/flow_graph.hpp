#pragma once
// The whole tree as BehaviorTree.CPP 4.10 ticks it, once, from a fresh blackboard: the mission's
// main tree with every SubTree expanded and every <Adaptable> expanded into each of its
// alternatives (the compiled tree runs them as SubTrees with _autoremap). The whole-tree checks
// (bb-*, script-*) read it.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/location.hpp"
#include "bt/script/ast.hpp"
#include "bt/tree.hpp"
#include "load/mission.hpp"

namespace uabt::verify::tree {

// A vertex is a node being ticked (enter), running its own part once its pre-conditions let it
// (run: only for a node that has some), or returning (success, failure, skipped).
enum class Step : std::uint8_t { enter, run, success, failure, skipped };

struct TickNode {
  const bt::Node* xml = nullptr;
  SourceLocation location;
  std::string label;  // "MoveTo 'approach'", "SubTree 'Dock'"
  std::uint32_t scope = 0;
};

// A blackboard entry one vertex reads.
struct Read {
  std::uint32_t entry = 0;
  std::string what;  // "input port 'goal' ({goal})", "the script `x > 1` of _skipIf"
};

struct Vertex {
  std::uint32_t node = 0;
  Step step = Step::enter;
  std::vector<std::uint32_t> preds;   // vertices before it; every pred has a smaller index
  std::vector<Read> reads;            // entries read when it is reached
  std::vector<std::uint32_t> writes;  // entries written when it is left
};

// An entry used with a type: a port whose nodes.xml declares type=, or a script assignment.
struct TypedUse {
  std::uint32_t entry = 0;
  std::string type;  // as nodes.xml writes it ("double", "std::string"), or "script string"/…
  bool from_script = false;
  std::string literal;  // a script's assigned string (it may convert to the port's type)
  SourceLocation location;
  std::string what;  // "port 'speed' of MoveTo"
};

// A script of the tree: ScriptCondition/Script code or a pre/post-condition attribute.
struct ScriptSite {
  std::string attribute;  // code, _skipIf, _onSuccess, …
  std::string node_kind;  // ScriptCondition, Script, or the node that carries the attribute
  std::shared_ptr<const bt::script::Script> script;
  SourceLocation location;
  std::uint32_t scope = 0;
  bool condition = false;  // its value decides (ScriptCondition, _skipIf, _while, …)
};

// A port set to a literal, with the type nodes.xml declares for it.
struct LiteralPort {
  std::string port, type, value, node_kind;
  SourceLocation location;
};

struct FlowGraph {
  std::vector<TickNode> nodes;
  std::vector<Vertex> vertices;  // topological: every edge goes to a larger index; 0 = root enter
  std::vector<std::string> entry_keys;  // an entry's key in the scope that owns it
  std::vector<std::uint32_t> entry_scopes;
  std::vector<std::string> scope_trees;  // the tree each scope instance runs
  std::vector<char> robot;               // the robot provides the entry (the domain declares it)
  std::vector<TypedUse> typed_uses;      // tree order
  std::vector<ScriptSite> scripts;       // tree order, each source place once
  std::vector<LiteralPort> literal_ports;

  std::string entry_name(std::uint32_t entry) const;
};

// Builds the graph of the mission's main tree (an empty graph when it has none).
FlowGraph build_flow_graph(const load::Mission& mission);

}  // namespace uabt::verify::tree
