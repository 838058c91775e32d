#pragma once
// domain.fret: one declaration a line (ARCHITECTURE §3). Rules only; EBNF in grammar/README.md.
//   boolean A, B          integer n in [0, 100]     unsigned integer k
//   real slope in [-45, 45]                          enum terrain in {dust, rocks}
//   assume NAME: EXPR                                tick 100 ms
#include "grammar/fretish.hpp"

namespace uabt::grammar {

struct kw_boolean : keyword<TAO_PEGTL_ISTRING("boolean")> {};
struct kw_integer : keyword<TAO_PEGTL_ISTRING("integer")> {};
struct kw_unsigned : keyword<TAO_PEGTL_ISTRING("unsigned")> {};
struct kw_real : keyword<TAO_PEGTL_ISTRING("real")> {};
struct kw_single : keyword<TAO_PEGTL_ISTRING("single")> {};
struct kw_double : keyword<TAO_PEGTL_ISTRING("double")> {};
struct kw_enum : keyword<TAO_PEGTL_ISTRING("enum")> {};
struct kw_assume : keyword<TAO_PEGTL_ISTRING("assume")> {};

struct variable_name : identifier {};
struct name_separator : one<','> {};
struct variable_names : seq<variable_name, star<ws, name_separator, ws, variable_name>> {};

// Bounds are signed decimals: [-45, 45], [0.5, 1e3].
struct signed_number : seq<opt<one<'-', '+'>>, number> {};
struct lower_bound : signed_number {};
struct upper_bound : signed_number {};
struct open_bracket : one<'['> {};
struct bound_separator : one<','> {};
struct close_bracket : one<']'> {};
struct bound_range
    : seq<open_bracket, ws, lower_bound, ws, bound_separator, ws, upper_bound, ws, close_bracket> {
};
struct range_keyword : kw_in {};
struct optional_range : opt<ws, range_keyword, ws, bound_range> {};

struct boolean_type : kw_boolean {};
struct integer_type : seq<opt<kw_unsigned, ws>, kw_integer> {};
struct real_type : sor<kw_real, kw_single, kw_double> {};
struct boolean_declaration : seq<boolean_type, ws, variable_names> {};
struct integer_declaration : seq<integer_type, ws, variable_names, optional_range> {};
struct real_declaration : seq<real_type, ws, variable_names, optional_range> {};

struct enum_literal : identifier {};
struct open_brace : one<'{'> {};
struct literal_separator : one<','> {};
struct close_brace : one<'}'> {};
struct enum_literals : seq<enum_literal, star<ws, literal_separator, ws, enum_literal>> {};
// An empty {} parses; the loader reports it as domain-invalid with a clearer message.
struct enum_declaration : seq<kw_enum, ws, variable_name, ws, range_keyword, ws, open_brace, ws,
                              opt<enum_literals, ws>, close_brace> {};

struct assumption_name : label_name {};
struct assumption_colon : one<':'> {};
struct assumption_declaration
    : seq<kw_assume, ws, assumption_name, ws, assumption_colon, ws, expression> {};

// The period of one tick, for durations written in time units (ARCHITECTURE §10).
struct kw_tick : keyword<TAO_PEGTL_ISTRING("tick")> {};
struct tick_period : number {};
struct tick_unit : sor<kw_unit, unit_abbreviation> {};
struct tick_declaration : seq<kw_tick, ws, tick_period, ws, tick_unit> {};

struct declaration : sor<boolean_declaration, integer_declaration, real_declaration,
                         enum_declaration, assumption_declaration, tick_declaration> {};
struct end_of_line : eof {};
// One line with its `#` comment already removed.
struct domain_line : seq<ws, opt<declaration>, ws, end_of_line> {};

}  // namespace uabt::grammar
