#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/blackboard.hpp"
#include "runtime/script/lexer.hpp"
#include "runtime/script/value.hpp"

namespace uabt::runtime::script {

// Deepest expression nesting a script may have (parentheses, prefix operators and operator
// chains all count), so that parsing and evaluation recursion stay bounded.
inline constexpr int kMaxScriptDepth = 128;

enum class Op : std::uint8_t {
  literal,
  name,
  negate,       // -x
  logical_not,  // !x
  complement,   // ~x
  add,
  sub,
  mul,
  div,
  concat,  // x .. y
  bit_and,
  bit_or,
  bit_xor,
  logic_and,
  logic_or,
  compare,  // a < b == c: a chain, as BT.CPP's comparison list
  conditional,
  assign_create,  // :=
  assign,         // =
  add_assign,
  sub_assign,
  mul_assign,
  div_assign,
};

enum class CompareOp : std::uint8_t { eq, ne, lt, gt, le, ge };

struct Expr {
  Op op = Op::literal;
  std::uint32_t a = 0, b = 0, c = 0;  // operands (conditional: a ? b : c)
  // compare: operands_[list_begin, list_begin + list_size) joined by
  // compare_ops_[ops_begin, ops_begin + list_size - 1)
  std::uint32_t list_begin = 0;
  std::uint32_t list_size = 0;
  std::uint32_t ops_begin = 0;
  std::size_t column = 0;
  ScriptValue literal;
  std::string name;
  SlotId slot = kNoSlot;
};

// A compiled BT.CPP 4.x script: `;`-separated statements over blackboard keys.
// parse() once, bind() its names to slots once, run() on every tick. run() allocates nothing
// once every register has seen its largest string.
//
// Grammar and meaning follow BT.CPP's scripting (scripting/operators.hpp), loosest first:
// assignment (:= = += -= *= /=, right to left: `a := b := 3`) < `?:` (not chainable) < `||` `&&`
// (one level, left to right, both sides evaluated) < comparison chains (== != < > <= >=) <
// operands: arithmetic (+ - then * / then unary -, with `..` string concatenation) or
// bitwise (| ^ then & then ~ and !); mixing the two kinds needs parentheses, and `!`/`~`/`-`
// apply to one operand ("!a == b" is "(!a) == b").
class Program {
 public:
  // Throws ScriptError with the column of the problem.
  static Program parse(std::string_view code);

  const std::string& code() const { return code_; }
  bool empty() const { return statements_.empty(); }
  // The blackboard keys the script names, in first-use order.
  std::vector<std::string> names() const;
  // True when a statement assigns (the script may change the blackboard).
  bool writes() const;

  // Resolves every name in `scope` (creating empty entries, which read as undefined).
  void bind(Blackboard& blackboard, ScopeId scope);

  // Runs every statement; returns the last one's value (empty for an empty script).
  // Throws ScriptError on undefined keys and type errors, as BT.CPP throws at tick.
  const ScriptValue& run(Blackboard& blackboard);

  // The compiled form, read-only: for a model checker that interprets scripts symbolically.
  const std::vector<Expr>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& statements() const { return statements_; }
  const std::vector<std::uint32_t>& compare_operands() const { return operands_; }
  const std::vector<CompareOp>& compare_ops() const { return compare_ops_; }

 private:
  friend class Parser;
  const ScriptValue& eval(std::uint32_t index, Blackboard& blackboard);
  const ScriptValue& eval_compare(const Expr& e, Blackboard& blackboard);
  const ScriptValue& eval_assign(std::uint32_t index, Blackboard& blackboard);

  std::string code_;
  std::vector<Expr> nodes_;
  std::vector<std::uint32_t> statements_;
  std::vector<std::uint32_t> operands_;  // compare operand lists
  std::vector<CompareOp> compare_ops_;
  std::vector<ScriptValue> registers_;  // one result per node, reused every run
  bool copy_reads_ = false;             // a nested assignment may change an entry mid-expression
  ScriptValue empty_;
};

}  // namespace uabt::runtime::script
