#pragma once
#include <memory>
#include <string>
#include <vector>

#include "base/location.hpp"

namespace uabt::fretish {

// Operators with FRET's formalized meaning (LTL.g4): see grammar/README.md.
enum class ExprKind {
  bool_literal,  // true / false                          (bool_value)
  number,        // 12, 0.5, 1e3                           (text keeps the literal)
  identifier,    // OnDust, "quoted id"                   (text)
  call,          // absReal(x), ite(c, a, b)              (text = function, args)
  // boolean
  logical_not,
  logical_and,
  logical_or,
  logical_xor,
  implies,
  iff,
  // relations, args = {lhs, rhs}
  eq,
  ne,
  lt,
  le,
  gt,
  ge,
  // arithmetic
  add,
  sub,
  mul,
  div,
  mod,
  pow,
  negate,
};

struct Expr;
using ExprPtr = std::shared_ptr<const Expr>;

struct Expr {
  ExprKind kind = ExprKind::bool_literal;
  std::string text;
  bool bool_value = false;
  std::vector<ExprPtr> args;   // operands, left to right; and/or may have more than two
  SourceRange range;           // where it stands in its file
  bool parenthesized = false;  // written inside ( ) in the source
};

ExprPtr make_expr(ExprKind kind, std::vector<ExprPtr> args, SourceRange range = {});
ExprPtr make_identifier(std::string name, SourceRange range = {});
ExprPtr make_number(std::string literal, SourceRange range = {});
ExprPtr make_bool(bool value, SourceRange range = {});

bool is_boolean_connective(ExprKind kind);  // not and or xor implies iff
bool is_relation(ExprKind kind);            // eq ne lt le gt ge
bool is_arithmetic(ExprKind kind);          // add sub mul div mod pow negate

// FRETISH text of an expression, fully determined by the tree: operators that bind looser
// than their parent are parenthesized. Identifiers that need it are quoted.
std::string to_fretish(const Expr& e);

// Structural equality (ignores source ranges and parenthesization).
bool same_expr(const Expr& a, const Expr& b);

// Written as an integer, digits with an optional '-': FRETISH types `12` as integer and `12.0`
// or `1e3` as real.
bool is_integer_literal(const std::string& text);
// A numeral written as a whole number without a sign, such as the exponent of `x ^ 2`.
bool is_natural_numeral(const Expr& e);

// Every identifier used, in first-occurrence order (function names excluded).
std::vector<std::string> identifiers_of(const Expr& e);

}  // namespace uabt::fretish
