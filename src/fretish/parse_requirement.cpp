// parse_requirement / parse_expression: one FRETISH sentence or expression into the AST.
#include <cctype>
#include <exception>
#include <sstream>

#include "base/number_fit.hpp"
#include "base/text.hpp"
#include "fretish/build_expression.hpp"
#include "fretish/parse.hpp"
#include "fretish/source_text.hpp"
#include "fretish/syntax_tree.hpp"

namespace uabt::fretish {

namespace {

using detail::ExpressionBuilder;
using detail::SyntaxNode;
using detail::TextMap;
namespace g = uabt::grammar;

// Keyword text as the header documents it: lower case, single spaces.
std::string normalized_words(std::string_view text) {
  std::istringstream words{std::string(text)};
  std::string word, out;
  while (words >> word) {
    if (!out.empty()) out += ' ';
    out += lower_case(word);
  }
  return out;
}

std::string trimmed(std::string_view text) {
  std::size_t b = 0, e = text.size();
  while (b < e && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(text[e - 1]))) --e;
  return std::string(text.substr(b, e - b));
}

bool is_expression_node(const SyntaxNode& n) {
  return n.is<g::equivalence>();
}

class RequirementBuilder {
 public:
  RequirementBuilder(std::string_view text, const TextMap& map, std::vector<Finding>& findings)
      : text_(text), map_(map), findings_(findings), expressions_(text, map, findings) {}

  // False when an expression was too deep (a finding has been added).
  bool build(const SyntaxNode& nasa, Requirement& r) {
    bool seen_shall = false;
    for (const auto& child : nasa.children) {
      const SyntaxNode& n = *child;
      if (n.is<g::scope_body>()) {
        if (!scope(n, r)) return false;
      } else if (n.is<g::first_condition>() || n.is<g::next_condition>()) {
        if (!condition(n, r)) return false;
      } else if (n.is<g::shall_keyword>()) {
        seen_shall = true;
      } else if (n.is<g::component>()) {
        const SyntaxNode* name = n.child<g::component_name>();
        r.component = expressions_.name_of(name ? *name : n);
        r.component_range = range(name ? *name : n);
        r.component_before_shall = !seen_shall;
      } else if (n.is<g::probability>()) {
        probability(n, r);
      } else if (n.is<g::timing_body>()) {
        if (!timing(n, r)) return false;
      } else if (n.is<g::response>()) {
        r.response_range = range(n);
        const SyntaxNode* e = expression_child(n);
        if (e == nullptr || !(r.response = expressions_.build(*e))) return false;
      }
    }
    return true;
  }

 private:
  SourceRange range(const SyntaxNode& n) const { return map_.range(n.begin, n.end); }
  std::string words(const SyntaxNode& n) const { return normalized_words(n.text(text_)); }

  static const SyntaxNode* expression_child(const SyntaxNode& n) {
    for (const auto& c : n.children)
      if (is_expression_node(*c)) return c.get();
    return nullptr;
  }

  bool scope(const SyntaxNode& n, Requirement& r) {
    Scope s;
    s.range = range(n);
    for (const auto& child : n.children) {
      const SyntaxNode& c = *child;
      if (c.is<g::mode_scope_words>() || c.is<g::condition_scope_words>() ||
          c.is<g::mode_or_condition_scope_words>()) {
        s.keyword = words(c);
      } else if (c.is<g::mode_name>()) {
        s.mode = expressions_.name_of(c);
      } else if (is_expression_node(c)) {
        if (!(s.condition = expressions_.build(c))) return false;
      }
    }
    // An odd number of negations (not, unless, except) makes the scope "not in".
    int negations = 0;
    std::istringstream ws{s.keyword};
    for (std::string w; ws >> w;)
      if (w == "not" || w == "unless" || w == "except") ++negations;
    s.negated = negations % 2 == 1;
    if (s.keyword == "not in")
      findings_.push_back(make_finding(
          "fretish-not-fret", "FRET spells this scope 'when not in' or 'if not in', not 'not in'",
          map_.location(n.begin)));
    r.scope = std::move(s);
    return true;
  }

  bool condition(const SyntaxNode& n, Requirement& r) {
    Condition c;
    c.range = range(n);
    for (const auto& child : n.children) {
      const SyntaxNode& part = *child;
      if (part.is<g::condition_connective>()) {
        c.connective = words(part);
      } else if (part.is<g::qualifier>()) {
        c.qualifier = words(part);
      } else if (part.is<g::truth_value>()) {
        const bool is_true = words(part) == "true";
        // FRET's lexer takes a lower-case `true`/`false` for the expression literal, so its
        // `IS (TRUE | FALSE)` fails on it; any other case is its keyword.
        const std::string_view spelled = part.text(text_);
        if (spelled == "true" || spelled == "false")
          findings_.push_back(make_finding("fretish-not-fret",
                                           std::string("FRET cannot parse a lower-case 'is ") +
                                               std::string(spelled) + "': write 'is " +
                                               (is_true ? "TRUE" : "FALSE") + "'",
                                           map_.location(part.begin)));
        c.is_true_suffix = is_true;
        c.is_false_suffix = !is_true;
      } else if (is_expression_node(part)) {
        if (!(c.expr = expressions_.build(part))) return false;
      }
    }
    r.conditions.push_back(std::move(c));
    return true;
  }

  void probability(const SyntaxNode& n, Requirement& r) {
    Probability p;
    p.range = range(n);
    if (const SyntaxNode* op = n.child<g::probability_relop>()) {
      p.relop = std::string(op->text(text_));
      if (p.relop == "==") p.relop = "=";
    }
    if (const SyntaxNode* v = n.child<g::probability_value>())
      p.number = std::string(v->text(text_));
    r.probability = std::move(p);
  }

  bool timing(const SyntaxNode& n, Requirement& r) {
    Timing& t = r.timing;
    t.range = range(n);
    if (n.children.empty()) return true;
    const SyntaxNode& form = *n.children.front();
    if (form.is<g::timing_word>()) {
      t.keyword = words(form);
    } else if (form.is<g::timing_timepoint>()) {
      const SyntaxNode* which = form.child<g::timepoint_which>();
      t.keyword = "at the " + (which ? words(*which) : std::string("next")) + " timepoint";
    } else if (form.is<g::timing_within>() || form.is<g::timing_for>() ||
               form.is<g::timing_after>()) {
      t.keyword = form.is<g::timing_within>() ? "within"
                  : form.is<g::timing_for>()  ? "for"
                                              : "after";
      if (const SyntaxNode* d = form.child<g::duration_value>()) {
        t.duration = std::string(d->text(text_));
        t.duration_range = range(*d);
        if (std::string why = number_misfit(t.duration); !why.empty()) {
          findings_.push_back(
              make_finding("fretish-syntax", "duration: " + why, map_.location(d->begin)));
          return false;
        }
      }
      if (const SyntaxNode* u = form.child<g::time_unit>()) t.unit = words(*u);
    } else if (form.is<g::timing_until>() || form.is<g::timing_before>()) {
      t.keyword = form.is<g::timing_until>() ? "until" : "before";
      const SyntaxNode* e = expression_child(form);
      if (e == nullptr || !(t.stop_condition = expressions_.build(*e))) return false;
    }
    return true;
  }

  std::string_view text_;
  const TextMap& map_;
  std::vector<Finding>& findings_;
  ExpressionBuilder expressions_;
};

std::optional<Requirement> parse_sentence(const std::string& text, const TextOrigin& origin,
                                          std::vector<Finding>& findings) {
  const TextMap map(text, origin);
  const std::string_view body(text.data(), detail::without_final_period(text));
  std::size_t first = 0;
  while (first < body.size() && std::isspace(static_cast<unsigned char>(body[first]))) ++first;
  if (first == body.size()) {
    findings.push_back(make_finding(
        "fretish-syntax", "empty requirement: expected a FRETISH sentence", map.location(0)));
    return std::nullopt;
  }
  const detail::ParseOutcome outcome = detail::run_parse<g::requirement>(body);
  if (!outcome.ok) {
    findings.push_back(detail::syntax_finding(outcome, body, map, "end of requirement"));
    return std::nullopt;
  }
  Requirement r;
  r.text = trimmed(text);
  r.location = map.location(first);
  for (const auto& child : outcome.root->children) {
    if (child->is<g::freeform>()) {
      r.freeform = true;
      return r;
    }
    if (child->is<g::nasa>()) {
      RequirementBuilder builder(body, map, findings);
      if (!builder.build(*child, r)) return std::nullopt;
    }
  }
  return r;
}

Finding internal_error(const TextOrigin& origin, const char* what) {
  return make_finding("fretish-syntax", std::string("could not parse: ") + what,
                      {origin.file, origin.line, origin.column});
}

}  // namespace

std::optional<Requirement> parse_requirement(const std::string& text, const TextOrigin& origin,
                                             std::vector<Finding>& findings) {
  try {
    return parse_sentence(text, origin, findings);
  } catch (const std::exception& e) {
    findings.push_back(internal_error(origin, e.what()));
  } catch (...) {
    findings.push_back(internal_error(origin, "unknown error"));
  }
  return std::nullopt;
}

ExprPtr parse_expression(const std::string& text, const TextOrigin& origin,
                         std::vector<Finding>& findings) {
  try {
    const TextMap map(text, origin);
    const detail::ParseOutcome outcome = detail::run_parse<g::expression_text>(text);
    if (!outcome.ok) {
      findings.push_back(detail::syntax_finding(outcome, text, map, "end of expression"));
      return nullptr;
    }
    for (const auto& child : outcome.root->children)
      if (is_expression_node(*child)) return ExpressionBuilder(text, map, findings).build(*child);
  } catch (const std::exception& e) {
    findings.push_back(internal_error(origin, e.what()));
  } catch (...) {
    findings.push_back(internal_error(origin, "unknown error"));
  }
  return nullptr;
}

}  // namespace uabt::fretish
