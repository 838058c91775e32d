#pragma once
// FRETISH expressions with the precedence FRET formalizes (LTL.g4), tightest first:
// ^ (right), unary -, * / mod, + -, relations, ! ~, &, |, xor, -> => (right), <-> <=>.
// Boolean and numeric operators share one precedence ladder so that every parenthesis is
// parsed exactly once (no backtracking between a boolean and a numeric reading).
#include "grammar/fretish_tokens.hpp"

namespace uabt::grammar {

struct expression;

// Operators. Multi-character spellings are tried first; a shorter operator never matches
// the prefix of a longer one ("<" is not the start of "<->", "-" not the start of "->").
struct op_iff : sor<TAO_PEGTL_STRING("<->"), TAO_PEGTL_STRING("<=>")> {};
struct op_implies : sor<TAO_PEGTL_STRING("->"), TAO_PEGTL_STRING("=>")> {};
struct op_xor : kw_xor {};
struct op_or : one<'|'> {};
struct op_and : one<'&'> {};
struct op_not : seq<one<'!', '~'>, not_at<one<'='>>> {};
struct op_relation
    : sor<seq<TAO_PEGTL_STRING("<="), not_at<one<'>'>>>, TAO_PEGTL_STRING(">="),
          TAO_PEGTL_STRING("!="), TAO_PEGTL_STRING("=="), seq<one<'='>, not_at<one<'>'>>>,
          seq<one<'<'>, not_at<sor<TAO_PEGTL_STRING("->"), TAO_PEGTL_STRING("=>")>>>, one<'>'>> {};
struct op_add : one<'+'> {};
struct op_sub : seq<one<'-'>, not_at<one<'>'>>> {};
struct op_mul : one<'*'> {};
struct op_div : one<'/'> {};
struct op_mod : kw_mod {};
struct op_pow : one<'^'> {};
// A '-' written against a digit is the sign of a number (FRET's NUMBER token), not a negation.
struct op_negate : seq<one<'-'>, not_at<one<'>'>>, not_at<digit>> {};

// Primary expressions.
struct close_paren : one<')'> {};
struct paren_expression : seq<one<'('>, ws, expression, ws, close_paren> {};
struct then_keyword : kw_then {};
// if A then B  ==  A -> B; B extends as far to the right as it can.
struct if_then : seq<kw_if, ws, expression, ws, then_keyword, ws, expression> {};
struct occurrence_direction : sor<kw_previous, kw_next> {};
struct occurrence_keyword : kw_occurrence {};
struct occurrence_separator : one<','> {};
// at the previous|next occurrence of P, Q
struct occurrence : seq<kw_at, ws, kw_the, ws, occurrence_direction, ws, occurrence_keyword, ws,
                        kw_of, ws, expression, ws, occurrence_separator, ws, expression> {};
struct function_name : identifier {};
struct argument_separator : one<','> {};
struct call_arguments : seq<expression, star<ws, argument_separator, ws, expression>> {};
struct call : seq<function_name, ws, one<'('>, ws, opt<call_arguments, ws>, close_paren> {};
// -1 ^ 2 is (-1) ^ 2 = 1, as in FRET; - 1 ^ 2 (a space after '-') is -(1 ^ 2).
struct negative_number : seq<one<'-'>, number> {};
struct bool_true : kw_true {};
struct bool_false : kw_false {};
struct primary : sor<paren_expression, if_then, occurrence, number, negative_number, bool_true,
                     bool_false, call, identifier> {};

// Binary levels; each is a flat list folded by the AST builder (left or right).
// -x ^ 2 is -(x ^ 2), -2 ^ 2 is (-2) ^ 2; x ^ -y is allowed; ^ is right-associative.
struct power_chain
    : seq<star<op_negate, ws>, primary, star<ws, op_pow, ws, star<op_negate, ws>, primary>> {};
struct multiplicative : seq<power_chain, star<ws, sor<op_mul, op_div, op_mod>, ws, power_chain>> {};
struct additive : seq<multiplicative, star<ws, sor<op_add, op_sub>, ws, multiplicative>> {};
// Relations do not chain: "a < b < c" is an error.
struct relation : seq<additive, opt<ws, op_relation, ws, additive>> {};
// ! binds looser than a relation: !x > 3 is !(x > 3).
struct negation : seq<star<op_not, ws>, relation> {};
struct conjunction : seq<negation, star<ws, op_and, ws, negation>> {};
struct disjunction : seq<conjunction, star<ws, op_or, ws, conjunction>> {};
struct exclusive : seq<disjunction, star<ws, op_xor, ws, disjunction>> {};
struct implication : seq<exclusive, star<ws, op_implies, ws, exclusive>> {};
struct equivalence : seq<implication, star<ws, op_iff, ws, implication>> {};
// Every nested expression passes through this rule (the parser bounds its nesting depth).
struct expression : seq<equivalence> {};

// What may continue an expression after an operand (a lookahead only).
struct expression_continuation : sor<one<'&', '|', '<', '>', '=', '+', '-', '*', '/', '^', '('>,
                                     TAO_PEGTL_STRING("!="), kw_xor, kw_mod> {};

// A standalone expression (domain assumptions, tests).
struct end_of_expression : eof {};
struct expression_text : seq<ws, expression, ws, end_of_expression> {};
// An expression after `if … then …` is rewritten as FRET does (`A => B`), re-read alone.
struct expression_span : seq<ws, expression, ws, eof> {};

}  // namespace uabt::grammar
