#pragma once
// FRETISH lexical rules: whitespace, reserved words, identifiers, numbers, strings.
// Rules only (no actions); see grammar/README.md for the EBNF these implement.
#include <tao/pegtl.hpp>

namespace uabt::grammar {

using namespace tao::pegtl;

// FRET's lexer drops ' ', '\t', '\r', '\n' between tokens.
struct ws : star<space> {};
struct comma : one<','> {};

// Characters that may continue an identifier; a keyword must not be followed by one.
struct id_char : sor<alnum, one<'_', '.', '%'>> {};

template <typename Word>
struct keyword : seq<Word, not_at<id_char>> {};

// Case-insensitive reserved words (FRET's Requirement.g4 lexer).
struct kw_after : keyword<TAO_PEGTL_ISTRING("after")> {};
struct kw_always : keyword<TAO_PEGTL_ISTRING("always")> {};
struct kw_and : keyword<TAO_PEGTL_ISTRING("and")> {};
struct kw_at : keyword<TAO_PEGTL_ISTRING("at")> {};
struct kw_before : keyword<TAO_PEGTL_ISTRING("before")> {};
struct kw_during : keyword<TAO_PEGTL_ISTRING("during")> {};
struct kw_eventually : keyword<TAO_PEGTL_ISTRING("eventually")> {};
struct kw_except : keyword<TAO_PEGTL_ISTRING("except")> {};
struct kw_false : keyword<TAO_PEGTL_ISTRING("false")> {};
struct kw_finally : keyword<TAO_PEGTL_ISTRING("finally")> {};
struct kw_first : keyword<TAO_PEGTL_ISTRING("first")> {};
struct kw_for : keyword<TAO_PEGTL_ISTRING("for")> {};
struct kw_if : keyword<TAO_PEGTL_ISTRING("if")> {};
struct kw_immediately : keyword<TAO_PEGTL_ISTRING("immediately")> {};
struct kw_in : keyword<TAO_PEGTL_ISTRING("in")> {};
struct kw_initially : keyword<TAO_PEGTL_ISTRING("initially")> {};
struct kw_is : keyword<TAO_PEGTL_ISTRING("is")> {};
struct kw_last : keyword<TAO_PEGTL_ISTRING("last")> {};
struct kw_mod : keyword<TAO_PEGTL_ISTRING("mod")> {};
struct kw_mode : keyword<TAO_PEGTL_ISTRING("mode")> {};
struct kw_never : keyword<TAO_PEGTL_ISTRING("never")> {};
struct kw_next : keyword<TAO_PEGTL_ISTRING("next")> {};
struct kw_not : keyword<TAO_PEGTL_ISTRING("not")> {};
struct kw_occurrence : keyword<TAO_PEGTL_ISTRING("occurrence")> {};
struct kw_of : keyword<TAO_PEGTL_ISTRING("of")> {};
struct kw_only : keyword<TAO_PEGTL_ISTRING("only")> {};
struct kw_or : keyword<TAO_PEGTL_ISTRING("or")> {};
struct kw_previous : keyword<TAO_PEGTL_ISTRING("previous")> {};
struct kw_probability : keyword<TAO_PEGTL_ISTRING("probability")> {};
struct kw_same : keyword<TAO_PEGTL_ISTRING("same")> {};
struct kw_satisfy : keyword<TAO_PEGTL_ISTRING("satisfy")> {};
struct kw_shall : keyword<TAO_PEGTL_ISTRING("shall")> {};
struct kw_the : keyword<TAO_PEGTL_ISTRING("the")> {};
struct kw_then : keyword<TAO_PEGTL_ISTRING("then")> {};
struct kw_timepoint : keyword<TAO_PEGTL_ISTRING("timepoint")> {};
struct kw_true : keyword<TAO_PEGTL_ISTRING("true")> {};
struct kw_unless : keyword<TAO_PEGTL_ISTRING("unless")> {};
struct kw_until : keyword<TAO_PEGTL_ISTRING("until")> {};
struct kw_upon : keyword<TAO_PEGTL_ISTRING("upon")> {};
struct kw_what : keyword<TAO_PEGTL_ISTRING("what")> {};
struct kw_when : keyword<TAO_PEGTL_ISTRING("when")> {};
struct kw_whenever : keyword<TAO_PEGTL_ISTRING("whenever")> {};
struct kw_where : keyword<TAO_PEGTL_ISTRING("where")> {};
struct kw_while : keyword<TAO_PEGTL_ISTRING("while")> {};
struct kw_with : keyword<TAO_PEGTL_ISTRING("with")> {};
struct kw_within : keyword<TAO_PEGTL_ISTRING("within")> {};
struct kw_xor : keyword<TAO_PEGTL_ISTRING("xor")> {};

// Time units: TICK : tick s?, MICROSECOND : microsec (ond)? s?, ... (FRET ignores the unit).
struct optional_s : opt<TAO_PEGTL_ISTRING("s")> {};
struct optional_ond_s : seq<opt<TAO_PEGTL_ISTRING("ond")>, optional_s> {};
struct unit_word : sor<seq<TAO_PEGTL_ISTRING("tick"), optional_s>,
                       seq<TAO_PEGTL_ISTRING("microsec"), optional_ond_s>,
                       seq<TAO_PEGTL_ISTRING("millisec"), optional_ond_s>,
                       seq<TAO_PEGTL_ISTRING("sec"), optional_ond_s>,
                       seq<TAO_PEGTL_ISTRING("minute"), optional_s>,
                       seq<TAO_PEGTL_ISTRING("hour"), optional_s>> {};
struct kw_unit : seq<unit_word, not_at<id_char>> {};
// uabt's abbreviations, as `tick 100 ms` in domain.fret writes them (not FRET's, and not reserved:
// `s` and `h` stay names everywhere but after a duration).
struct unit_abbreviation : sor<keyword<TAO_PEGTL_ISTRING("ms")>, keyword<TAO_PEGTL_ISTRING("us")>,
                               keyword<TAO_PEGTL_ISTRING("s")>, keyword<TAO_PEGTL_ISTRING("min")>,
                               keyword<TAO_PEGTL_ISTRING("h")>> {};

struct reserved_word
    : sor<kw_after, kw_always, kw_and, kw_at, kw_before, kw_during, kw_eventually, kw_except,
          kw_false, kw_finally, kw_first, kw_for, kw_if, kw_immediately, kw_in, kw_initially, kw_is,
          kw_last, kw_mod, kw_mode, kw_never, kw_next, kw_not, kw_occurrence, kw_of, kw_only, kw_or,
          kw_previous, kw_probability, kw_same, kw_satisfy, kw_shall, kw_the, kw_then, kw_timepoint,
          kw_true, kw_unless, kw_until, kw_upon, kw_what, kw_when, kw_whenever, kw_where, kw_while,
          kw_with, kw_within, kw_xor, kw_unit> {};

// STRING : '"' (ESC | .)*? '"' with ESC : '\"' | '\\'.
struct string_escape : sor<TAO_PEGTL_STRING("\\\""), TAO_PEGTL_STRING("\\\\")> {};
struct string_char : sor<string_escape, not_one<'"'>> {};
struct closing_quote : one<'"'> {};
struct quoted_string : seq<one<'"'>, star<string_char>, closing_quote> {};

// ID : [a-zA-Z][a-zA-Z0-9_.%]* | STRING, never a reserved word.
struct plain_identifier : seq<not_at<reserved_word>, alpha, star<id_char>> {};
struct quoted_identifier : seq<one<'"'>, plus<string_char>, closing_quote> {};
struct identifier : sor<quoted_identifier, plain_identifier> {};

// NUMBER without FRET's leading '-': "x-1" is a subtraction, "-1" a negation.
struct exponent : seq<one<'e', 'E'>, opt<one<'+', '-'>>, plus<digit>> {};
struct number : seq<plus<digit>, opt<one<'.'>, plus<digit>>, opt<exponent>> {};

}  // namespace uabt::grammar
