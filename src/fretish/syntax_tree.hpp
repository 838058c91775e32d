#pragma once
// Internal: runs a grammar/ rule with a PEGTL control that builds a light syntax tree
// (only the rules listed in NodeRules), records the furthest failure for "expected …"
// messages, and bounds nesting depth. Backtracking discards the nodes of failed attempts.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <tao/pegtl.hpp>

#include "grammar/domain.hpp"
#include "grammar/fretish.hpp"

namespace uabt::fretish::detail {

// Parenthesis / if-then / call nesting the parser accepts (each level recurses in PEGTL).
inline constexpr int kMaxNesting = 200;

template <typename Rule>
const void* rule_tag() {
  static const char tag = 0;
  return &tag;
}

struct SyntaxNode {
  const void* rule = nullptr;
  std::size_t begin = 0;
  std::size_t end = 0;  // one past the last byte
  std::vector<std::unique_ptr<SyntaxNode>> children;

  template <typename Rule>
  bool is() const {
    return rule == rule_tag<Rule>();
  }
  template <typename Rule>
  const SyntaxNode* child() const {
    for (const auto& c : children)
      if (c->is<Rule>()) return c.get();
    return nullptr;
  }
  std::string_view text(std::string_view source) const { return source.substr(begin, end - begin); }
};

template <typename... Rules>
struct RuleSet {
  template <typename Rule>
  static constexpr bool contains = (std::is_same_v<Rule, Rules> || ...);
};

namespace g = uabt::grammar;

using NodeRules = RuleSet<
    // expressions
    g::equivalence, g::implication, g::exclusive, g::disjunction, g::conjunction, g::negation,
    g::relation, g::additive, g::multiplicative, g::power_chain, g::op_iff, g::op_implies,
    g::op_xor, g::op_or, g::op_and, g::op_not, g::op_relation, g::op_add, g::op_sub, g::op_mul,
    g::op_div, g::op_mod, g::op_negate, g::paren_expression, g::if_then, g::occurrence,
    g::occurrence_direction, g::call, g::function_name, g::number, g::negative_number, g::bool_true,
    g::bool_false, g::plain_identifier, g::quoted_identifier,
    // sentences
    g::nasa, g::freeform, g::scope_body, g::mode_scope_words, g::condition_scope_words,
    g::mode_or_condition_scope_words, g::mode_name, g::first_condition, g::next_condition,
    g::qualifier, g::condition_connective, g::truth_value, g::component, g::component_name,
    g::shall_keyword, g::probability, g::probability_relop, g::probability_value, g::timing_body,
    g::timing_within, g::timing_for, g::timing_after, g::timing_until, g::timing_before,
    g::timing_timepoint, g::timepoint_which, g::timing_word, g::duration_value, g::time_unit,
    g::response, g::label_name,
    // domain declarations
    g::boolean_declaration, g::integer_declaration, g::real_declaration, g::enum_declaration,
    g::assumption_declaration, g::integer_type, g::real_type, g::variable_name, g::lower_bound,
    g::upper_bound, g::enum_literal, g::assumption_name, g::tick_declaration, g::tick_period,
    g::tick_unit>;

// What a rule is called in an "expected …" message; rules without a name are not reported.
template <typename Rule>
inline constexpr const char* expected_name = nullptr;

#define UABT_EXPECTED(rule, name) \
  template <>                     \
  inline constexpr const char* expected_name<g::rule> = name
UABT_EXPECTED(primary, "an expression");
UABT_EXPECTED(op_iff, "an operator");
UABT_EXPECTED(op_implies, "an operator");
UABT_EXPECTED(op_xor, "an operator");
UABT_EXPECTED(op_or, "an operator");
UABT_EXPECTED(op_and, "an operator");
UABT_EXPECTED(op_relation, "an operator");
UABT_EXPECTED(op_add, "an operator");
UABT_EXPECTED(op_sub, "an operator");
UABT_EXPECTED(op_mul, "an operator");
UABT_EXPECTED(op_div, "an operator");
UABT_EXPECTED(op_mod, "an operator");
UABT_EXPECTED(op_pow, "an operator");
UABT_EXPECTED(close_paren, "')'");
UABT_EXPECTED(then_keyword, "'then'");
UABT_EXPECTED(occurrence_direction, "'previous' or 'next'");
UABT_EXPECTED(occurrence_keyword, "'occurrence'");
UABT_EXPECTED(occurrence_separator, "','");
UABT_EXPECTED(argument_separator, "','");
UABT_EXPECTED(closing_quote, "a closing '\"'");
UABT_EXPECTED(end_of_expression, "end of expression");
UABT_EXPECTED(mode_name, "a mode name");
UABT_EXPECTED(truth_value, "'true' or 'false'");
UABT_EXPECTED(component_name, "a component name");
UABT_EXPECTED(shall_keyword, "'shall'");
UABT_EXPECTED(probability_relop, "a comparison operator");
UABT_EXPECTED(probability_value, "a number");
UABT_EXPECTED(duration_value, "a number");
UABT_EXPECTED(time_unit, "a time unit (ticks, seconds, ...)");
UABT_EXPECTED(timepoint_which, "'first', 'same', 'next' or 'last'");
UABT_EXPECTED(timepoint_keyword, "'timepoint'");
UABT_EXPECTED(timing_body, "a timing");
UABT_EXPECTED(satisfy_keyword, "'satisfy'");
UABT_EXPECTED(end_of_requirement, "end of requirement");
UABT_EXPECTED(variable_name, "a variable name");
UABT_EXPECTED(name_separator, "','");
UABT_EXPECTED(range_keyword, "'in'");
UABT_EXPECTED(open_bracket, "'['");
UABT_EXPECTED(lower_bound, "a number");
UABT_EXPECTED(bound_separator, "','");
UABT_EXPECTED(upper_bound, "a number");
UABT_EXPECTED(close_bracket, "']'");
UABT_EXPECTED(open_brace, "'{'");
UABT_EXPECTED(enum_literal, "an enum literal");
UABT_EXPECTED(literal_separator, "','");
UABT_EXPECTED(close_brace, "'}'");
UABT_EXPECTED(assumption_name, "an assumption name");
UABT_EXPECTED(assumption_colon, "':'");
UABT_EXPECTED(declaration, "a declaration");
UABT_EXPECTED(end_of_line, "end of line");
#undef UABT_EXPECTED

template <typename Rule>
inline constexpr bool is_lookahead = false;
template <typename... Rules>
inline constexpr bool is_lookahead<tao::pegtl::at<Rules...>> = true;
template <typename... Rules>
inline constexpr bool is_lookahead<tao::pegtl::not_at<Rules...>> = true;

struct NestingTooDeep {
  std::size_t offset;
};

struct ParseState {
  std::vector<std::unique_ptr<SyntaxNode>> open;  // open[0] is the root
  // Children of open.back() when each active rule started: a rule that fails drops the
  // nodes its successful sub-rules attached (e.g. `mode_name` inside a failed `M mode`).
  std::vector<std::size_t> child_marks;
  std::vector<std::size_t> name_starts;
  bool any_expected = false;
  std::size_t furthest = 0;           // start of the furthest named rule that failed
  std::vector<const char*> expected;  // names that failed there, first failure first
  int depth = 0;
  int lookahead = 0;

  ParseState() { open.push_back(std::make_unique<SyntaxNode>()); }

  void expect(std::size_t pos, const char* name);
};

template <typename Rule>
struct TreeControl : tao::pegtl::normal<Rule> {
  template <typename Input>
  static std::size_t offset(const Input& in) {
    return static_cast<std::size_t>(in.current() - in.begin());
  }

  template <typename Input>
  static void start(const Input& in, ParseState& s) {
    if constexpr (is_lookahead<Rule>) {
      ++s.lookahead;
    } else {
      if (s.lookahead > 0) return;
      const std::size_t pos = offset(in);
      if constexpr (std::is_same_v<Rule, g::expression>) {
        if (++s.depth > kMaxNesting) throw NestingTooDeep{pos};
      }
      s.child_marks.push_back(s.open.back()->children.size());
      if constexpr (NodeRules::contains<Rule>) {
        auto node = std::make_unique<SyntaxNode>();
        node->rule = rule_tag<Rule>();
        node->begin = pos;
        s.open.push_back(std::move(node));
      }
      if constexpr (expected_name<Rule> != nullptr) s.name_starts.push_back(pos);
    }
  }

  template <typename Input>
  static void success(const Input& in, ParseState& s) {
    if constexpr (is_lookahead<Rule>) {
      --s.lookahead;
    } else {
      if (s.lookahead > 0) return;
      if constexpr (std::is_same_v<Rule, g::expression>) --s.depth;
      if constexpr (NodeRules::contains<Rule>) {
        auto node = std::move(s.open.back());
        s.open.pop_back();
        node->end = offset(in);
        s.open.back()->children.push_back(std::move(node));
      }
      s.child_marks.pop_back();
      if constexpr (expected_name<Rule> != nullptr) s.name_starts.pop_back();
    }
  }

  template <typename Input>
  static void failure(const Input&, ParseState& s) {
    if constexpr (is_lookahead<Rule>) {
      --s.lookahead;
    } else {
      if (s.lookahead > 0) return;
      if constexpr (std::is_same_v<Rule, g::expression>) --s.depth;
      if constexpr (NodeRules::contains<Rule>) s.open.pop_back();
      s.open.back()->children.resize(s.child_marks.back());
      s.child_marks.pop_back();
      if constexpr (expected_name<Rule> != nullptr) {
        const std::size_t pos = s.name_starts.back();
        s.name_starts.pop_back();
        s.expect(pos, expected_name<Rule>);
      }
    }
  }
};

// Outcome of one parse: the root's children on success, otherwise where it stopped.
struct ParseOutcome {
  bool ok = false;
  std::unique_ptr<SyntaxNode> root;
  bool too_deep = false;
  std::size_t error_offset = 0;
  std::vector<const char*> expected;
};

template <typename Grammar>
ParseOutcome run_parse(std::string_view text) {
  ParseState state;
  ParseOutcome outcome;
  tao::pegtl::memory_input<tao::pegtl::tracking_mode::lazy> in(text.data(), text.size(), "");
  try {
    outcome.ok = tao::pegtl::parse<Grammar, tao::pegtl::nothing, TreeControl>(in, state);
  } catch (const NestingTooDeep& e) {
    outcome.too_deep = true;
    outcome.error_offset = e.offset;
    return outcome;
  }
  if (outcome.ok) {
    outcome.root = std::move(state.open.front());
    outcome.root->end = text.size();
  } else {
    outcome.error_offset = state.any_expected ? state.furthest : 0;
    outcome.expected = std::move(state.expected);
  }
  return outcome;
}

}  // namespace uabt::fretish::detail
