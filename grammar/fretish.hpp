#pragma once
// FRETISH requirement sentences: FRET's Requirement.g4 (reqt_body), complete, plus
// `with probability`. Rules only; the AST is built in src/fretish. EBNF: grammar/README.md.
#include "grammar/fretish_expression.hpp"

namespace uabt::grammar {

// ---- scope -----------------------------------------------------------------------------
// scope_mode : MODE mode_name | mode_name MODE | mode_name
struct mode_name : identifier {};
struct scope_mode : sor<seq<kw_mode, ws, mode_name>, seq<mode_name, ws, kw_mode>, mode_name> {};
struct scope_condition : seq<expression> {};

struct when_or_if : sor<kw_when, kw_if> {};
struct in_words : seq<opt<when_or_if, ws>, kw_in> {};
// Scopes that take a mode.
struct mode_scope_words
    : sor<seq<kw_only, ws, sor<kw_during, in_words>>, seq<kw_except, ws, sor<kw_during, in_words>>,
          seq<when_or_if, ws, kw_not, ws, kw_in>, in_words, kw_during, seq<kw_unless, ws, kw_in>,
          seq<kw_not, ws, kw_in>> {};
// Scopes that take a condition.
struct condition_scope_words
    : sor<seq<kw_only, ws, kw_while>, seq<kw_except, ws, kw_while>, kw_while> {};
// after/before take a mode or a condition; a lone name (or `mode M`) is a mode, as ANTLR
// resolves the ambiguity in favour of scope_mode.
struct mode_or_condition_scope_words
    : sor<seq<kw_only, ws, sor<kw_after, kw_before>>, kw_after, kw_before> {};
struct lone_scope_mode : seq<scope_mode, not_at<ws, expression_continuation>> {};
struct scope_body
    : sor<seq<mode_or_condition_scope_words, ws, sor<lone_scope_mode, scope_condition>>,
          seq<condition_scope_words, ws, scope_condition>, seq<mode_scope_words, ws, scope_mode>> {
};
struct scope : seq<scope_body, opt<ws, comma>> {};

// ---- conditions ------------------------------------------------------------------------
struct qualifier : sor<kw_upon, kw_whenever, kw_when, kw_unless, kw_where, kw_if> {};
struct condition_connective : sor<kw_and, kw_or> {};
struct truth_value : sor<kw_true, kw_false> {};
struct condition_suffix : seq<kw_is, ws, truth_value> {};
// qualified_condition1 : qualifier_word pre_condition (IS (TRUE | FALSE))?
struct first_condition : seq<qualifier, ws, expression, opt<ws, condition_suffix>> {};
// qualified_condition2 : (AND | OR)? qualifier_word pre_condition (IS (TRUE | FALSE))?
struct next_condition
    : seq<opt<condition_connective, ws>, qualifier, ws, expression, opt<ws, condition_suffix>> {};
struct regular_condition
    : seq<first_condition, star<opt<ws, comma>, ws, next_condition>, opt<ws, comma>> {};
struct reqt_condition : seq<opt<kw_and, ws>, regular_condition> {};

// ---- component, probability ------------------------------------------------------------
struct component_name : identifier {};
struct component : seq<opt<kw_the, ws>, component_name> {};
struct shall_keyword : kw_shall {};
struct component_shall : sor<seq<component, ws, shall_keyword>, seq<shall_keyword, ws, component>> {
};

struct probability_relop : op_relation {};
struct probability_value : number {};
struct probability
    : seq<kw_with, ws, kw_probability, ws, probability_relop, ws, probability_value> {};

// ---- timing ----------------------------------------------------------------------------
struct duration_value : number {};
struct time_unit : sor<kw_unit, unit_abbreviation> {};
struct duration : seq<duration_value, ws, time_unit> {};
struct timing_within : seq<kw_within, ws, duration> {};
struct timing_for : seq<kw_for, ws, duration> {};
struct timing_after : seq<kw_after, ws, duration> {};
struct timing_until : seq<kw_until, ws, expression> {};
struct timing_before : seq<kw_before, ws, expression> {};
struct timepoint_which : sor<kw_first, kw_same, kw_next, kw_last> {};
struct timepoint_keyword : kw_timepoint {};
struct timing_timepoint : seq<kw_at, ws, kw_the, ws, timepoint_which, ws, timepoint_keyword> {};
struct timing_word
    : sor<kw_immediately, kw_initially, kw_finally, kw_eventually, kw_always, kw_never> {};
struct timing_body : sor<timing_within, timing_for, timing_after, timing_until, timing_before,
                         timing_timepoint, timing_word> {};
struct timing : seq<opt<comma, ws>, timing_body, opt<ws, comma>> {};

// ---- response, sentence ----------------------------------------------------------------
struct satisfy_keyword : kw_satisfy {};
struct response : seq<satisfy_keyword, ws, expression> {};

// nasa : scope? reqt_condition? (component SHALL | SHALL component) probability? timing?
//        response
struct nasa : seq<opt<scope, ws>, opt<reqt_condition, ws>, component_shall, opt<ws, probability>,
                  opt<ws, timing>, ws, response> {};
struct freeform : quoted_string {};
struct end_of_requirement : eof {};
// reqt_body : (nasa | freeform) '.'?   (the caller strips a final '.' first, as FRET does,
// because an identifier may end in '.')
struct requirement : seq<ws, sor<nasa, freeform>, ws, opt<one<'.'>, ws>, end_of_requirement> {};

// ---- requirements.fret lines -----------------------------------------------------------
// An optional label `ID:` before the sentence; label ids follow FRET's REQT_ID.
struct label_name : seq<alnum, star<sor<alnum, one<'_', '-', '.'>>>> {};
struct label : seq<ws, label_name, ws, one<':'>> {};

}  // namespace uabt::grammar
