#pragma once
// Internal: builds Expr trees from the syntax tree of grammar/fretish_expression.hpp, folding
// each operator list with its associativity and warning on fretish-precedence mixes.
#include <string>
#include <string_view>
#include <vector>

#include "base/finding.hpp"
#include "fretish/expr.hpp"
#include "fretish/source_text.hpp"
#include "fretish/syntax_tree.hpp"

namespace uabt::fretish::detail {

// Depth of an Expr tree the builder accepts; deeper trees (e.g. 5000 chained '!') would make
// every recursive consumer of the AST overflow its stack.
inline constexpr int kMaxExprDepth = 1000;

class ExpressionBuilder {
 public:
  ExpressionBuilder(std::string_view text, const TextMap& map, std::vector<Finding>& findings)
      : text_(text), map_(map), findings_(findings) {}

  // Builds the expression of an expression-level node. Returns nullptr after adding a
  // fretish-syntax finding when the tree would be deeper than kMaxExprDepth.
  ExprPtr build(const SyntaxNode& node);

  // Name of an identifier node (plain, quoted, or a rule wrapping one), unquoted.
  std::string name_of(const SyntaxNode& node) const;

 private:
  struct Built {
    ExprPtr expr;
    int depth = 1;
  };
  // An expression uabt cannot represent: nested too deeply, or a number that fits no type.
  struct Refusal {
    std::size_t offset;
    std::string message;
  };

  Built visit(const SyntaxNode& node);
  Built make(ExprKind kind, std::vector<Built> args, std::size_t begin, std::size_t end);
  Built left_fold(const SyntaxNode& node);
  Built right_fold(const SyntaxNode& node);
  Built flat(const SyntaxNode& node, ExprKind kind);
  Built negation(const SyntaxNode& node);
  Built relation(const SyntaxNode& node);
  Built power_chain(const SyntaxNode& node);
  Built parenthesized(const SyntaxNode& node);
  Built call(const SyntaxNode& node);
  Built occurrence(const SyntaxNode& node);
  // fretish-not-fret: accepted here, refused by FRET's own parser.
  void warn_not_fret(std::size_t offset, const std::string& message);
  void check_operator(const SyntaxNode& op);
  // fretish-precedence at `op`, the outer operator of a `xor`/`|` or `<->`/`->` mix.
  void warn_mixed(const SyntaxNode& op, const char* inner);

  std::string_view text_;
  const TextMap& map_;
  std::vector<Finding>& findings_;
};

}  // namespace uabt::fretish::detail
