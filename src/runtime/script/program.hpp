#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bt/script/ast.hpp"
#include "runtime/blackboard.hpp"

namespace uabt::runtime::script {

// The script language lives in bt/script (one parser for every stage); the engine's names
// for it:
using bt::script::CompareOp;
using bt::script::describe;
using bt::script::Expr;
using bt::script::kMaxScriptDepth;
using bt::script::Op;
using bt::script::Script;
using bt::script::ScriptError;

// A compiled BT.CPP 4.x script for the engine: parse() once, bind() its names to slots once,
// run() on every tick. run() allocates nothing once every register has seen its largest
// string. Evaluation follows BT.CPP 4.10's types (see eval.cpp).
class Program {
 public:
  // Throws ScriptError with the column of the problem.
  static Program parse(std::string_view code);
  // The engine's program of a script already parsed.
  static Program of(Script script);

  const std::string& code() const { return script_.code(); }
  bool empty() const { return script_.empty(); }
  // The blackboard keys the script names, in first-use order.
  std::vector<std::string> names() const { return script_.names(); }
  // True when a statement assigns (the script may change the blackboard).
  bool writes() const { return script_.writes(); }

  // Resolves every name in `scope` (creating empty entries, which read as undefined).
  void bind(Blackboard& blackboard, ScopeId scope);

  // Runs every statement; returns the last one's value (empty for an empty script).
  // Throws ScriptError on undefined keys and type errors, as BT.CPP throws at tick.
  const ScriptValue& run(Blackboard& blackboard);

  // The parsed form, read-only: for a model checker that interprets scripts symbolically.
  const Script& script() const { return script_; }
  const std::vector<Expr>& nodes() const { return script_.nodes(); }
  const std::vector<std::uint32_t>& statements() const { return script_.statements(); }

 private:
  const ScriptValue& eval(std::uint32_t index, Blackboard& blackboard);
  const ScriptValue& eval_compare(const Expr& e, Blackboard& blackboard);
  const ScriptValue& eval_assign(std::uint32_t index, Blackboard& blackboard);

  Script script_;
  std::vector<ScriptValue> registers_;  // one result per node, reused every run
  ScriptValue empty_;
};

}  // namespace uabt::runtime::script
