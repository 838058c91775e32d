#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bt/script/lexer.hpp"
#include "bt/script/value.hpp"

namespace uabt::bt::script {

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

// The blackboard key a script name reads: `@x` is the root blackboard's x.
inline std::string entry_key(std::string_view name) {
  return std::string(name.starts_with('@') ? name.substr(1) : name);
}

// := = += -= *= /= (the last operators of Op).
inline bool is_assignment(Op op) {
  return op >= Op::assign_create;
}

enum class CompareOp : std::uint8_t { eq, ne, lt, gt, le, ge };

inline constexpr std::uint32_t kUnbound = UINT32_MAX;

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
  std::string name;               // a name's blackboard key, as written (`@x` keeps its '@')
  std::string spelling;           // a number literal as written (0x10, 2.50, 1e3)
  std::uint32_t slot = kUnbound;  // what a reader bound the name to (the engine's slot)
};

// A parsed BT.CPP 4.x script: `;`-separated statements over blackboard keys, as a flat tree
// of Expr nodes. The one parser of the language: the engine evaluates it, conform reads a
// condition back into FRETISH, prove encodes it, the checks list the keys it names.
//
// Grammar follows BT.CPP's scripting (src/script_parser.cpp), loosest first: assignment
// (:= = += -= *= /=, right to left: `a := b := 3`) < `?:` (not chainable) < `||` `&&` (one
// level, left to right) < comparison chains (== != < > <= >=) < operands: arithmetic
// (+ - then * / then unary -, with `..` string concatenation) or bitwise (| ^ then & then ~
// and !); mixing the two kinds needs parentheses, and `!`/`~`/`-` apply to one operand
// ("!a == b" is "(!a) == b").
class Script {
 public:
  // Throws ScriptError with the column of the problem.
  static Script parse(std::string_view code);

  const std::string& code() const { return code_; }
  bool empty() const { return statements_.empty(); }
  // The blackboard keys the script names, in first-use order.
  std::vector<std::string> names() const;
  // True when a statement assigns (the script may change the blackboard).
  bool writes() const;
  // The blackboard keys its assignments write, in the order written, once per assignment.
  std::vector<std::string> assigned() const;
  // True when an assignment sits inside a larger expression, so that an entry may change
  // while the expression that read it is still being evaluated.
  bool nested_assignment() const { return nested_assignment_; }

  const std::vector<Expr>& nodes() const { return nodes_; }
  std::vector<Expr>& nodes() { return nodes_; }  // to bind names
  const std::vector<std::uint32_t>& statements() const { return statements_; }
  const std::vector<std::uint32_t>& compare_operands() const { return operands_; }
  const std::vector<CompareOp>& compare_ops() const { return compare_ops_; }

 private:
  friend class Parser;
  std::string code_;
  std::vector<Expr> nodes_;
  std::vector<std::uint32_t> statements_;
  std::vector<std::uint32_t> operands_;  // compare operand lists
  std::vector<CompareOp> compare_ops_;
  bool nested_assignment_ = false;
};

}  // namespace uabt::bt::script
