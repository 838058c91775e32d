// domain.fret: variable declarations and assumptions, one a line.
#include <cmath>
#include <cstdlib>
#include <exception>
#include <map>
#include <set>

#include "base/number_fit.hpp"
#include "fretish/build_expression.hpp"
#include "fretish/lines.hpp"
#include "fretish/parse.hpp"
#include "fretish/source_text.hpp"
#include "fretish/syntax_tree.hpp"

namespace uabt::fretish {

namespace {

using detail::SyntaxNode;
using detail::TextMap;
namespace g = uabt::grammar;

std::string bound_text(std::string_view written) {
  if (!written.empty() && written.front() == '+') written.remove_prefix(1);
  return std::string(written);
}

long double numeric_value(const std::string& text) {
  return std::strtold(text.c_str(), nullptr);
}

class DomainBuilder {
 public:
  DomainBuilder(Domain& domain, std::vector<Finding>& findings)
      : domain_(domain), findings_(findings) {}

  void line(const detail::Line& line, const std::string& file) {
    const std::string text(line.text);
    const TextMap map(text, TextOrigin{file, line.number, 1});
    const detail::ParseOutcome outcome = detail::run_parse<g::domain_line>(text);
    if (!outcome.ok) {
      findings_.push_back(detail::syntax_finding(outcome, text, map, "end of line"));
      return;
    }
    detail::ExpressionBuilder names(text, map, findings_);
    for (const auto& declaration : outcome.root->children) build(*declaration, text, map, names);
  }

  // Checks that need every declaration: literals against variables and other enums.
  void finish() {
    std::map<std::string, const Variable*> literal_owner;
    for (const Variable& v : domain_.variables) {
      if (v.type != VarType::enumeration) continue;
      for (std::size_t i = 0; i < v.enum_values.size(); ++i) {
        const std::string& literal = v.enum_values[i];
        const SourceLocation& where = literal_locations_[&v - domain_.variables.data()][i];
        if (domain_.find(literal) != nullptr) {
          invalid(
              "enum literal '" + literal + "' of '" + v.name + "' is also the name of a variable",
              where);
        }
        const auto [it, inserted] = literal_owner.emplace(literal, &v);
        if (!inserted && it->second != &v) {
          invalid("enum literal '" + literal + "' of '" + v.name + "' is also a literal of '" +
                      it->second->name + "'",
                  where);
        }
      }
    }
  }

 private:
  void invalid(std::string message, SourceLocation where) {
    findings_.push_back(make_finding("domain-invalid", std::move(message), std::move(where)));
  }

  void build(const SyntaxNode& d, std::string_view text, const TextMap& map,
             detail::ExpressionBuilder& names) {
    if (d.is<g::assumption_declaration>()) {
      assumption(d, text, map, names);
      return;
    }
    if (d.is<g::tick_declaration>()) {
      tick(d, text, map);
      return;
    }
    Variable prototype;
    std::string lower_written, upper_written;
    SourceLocation lower_at, upper_at;
    bool is_unsigned = false;
    std::vector<const SyntaxNode*> declared;
    std::vector<std::string> literals;
    std::vector<SourceLocation> literal_at;
    if (d.is<g::boolean_declaration>()) prototype.type = VarType::boolean;
    if (d.is<g::integer_declaration>()) prototype.type = VarType::integer;
    if (d.is<g::real_declaration>()) prototype.type = VarType::real;
    if (d.is<g::enum_declaration>()) prototype.type = VarType::enumeration;
    for (const auto& child : d.children) {
      const SyntaxNode& c = *child;
      if (c.is<g::integer_type>()) {
        is_unsigned = c.text(text).size() > std::string_view("integer").size();
      } else if (c.is<g::variable_name>()) {
        declared.push_back(&c);
      } else if (c.is<g::lower_bound>()) {
        lower_written = bound_text(c.text(text));
        lower_at = map.location(c.begin);
      } else if (c.is<g::upper_bound>()) {
        upper_written = bound_text(c.text(text));
        upper_at = map.location(c.begin);
      } else if (c.is<g::enum_literal>()) {
        literals.push_back(names.name_of(c));
        literal_at.push_back(map.location(c.begin));
      }
    }
    if (declared.empty()) return;
    const std::string first_name = names.name_of(*declared.front());
    if (!bounds_valid(prototype.type, is_unsigned, first_name, lower_written, upper_written,
                      lower_at, upper_at)) {
      lower_written.clear();  // reported; leave the variable unbounded, its checks unmade
      upper_written.clear();
      prototype.invalid = findings_.back().message;
    }
    prototype.lower = lower_written;
    prototype.upper = upper_written;
    if (is_unsigned && prototype.lower.empty()) prototype.lower = "0";
    if (prototype.type == VarType::enumeration) {
      if (literals.empty()) {
        invalid("enum '" + first_name + "' has no literals", map.location(declared.front()->begin));
        prototype.invalid = findings_.back().message;
      }
      if (literals.size() > kMaxEnumValues) {
        invalid("enum '" + first_name + "' has " + std::to_string(literals.size()) +
                    " literals; uabt handles at most " + std::to_string(kMaxEnumValues) +
                    " (split it, or use an integer range)",
                map.location(declared.front()->begin));
        prototype.invalid = findings_.back().message;
        literals.clear();  // reported; the variable keeps no values, its checks unmade
      }
      std::set<std::string_view> seen;  // a set: an enum may have very many literals
      for (std::size_t i = 0; i < literals.size(); ++i) {
        if (!seen.insert(literals[i]).second) {
          invalid("enum literal '" + literals[i] + "' appears twice in '" + first_name + "'",
                  literal_at[i]);
          continue;
        }
        prototype.enum_values.push_back(literals[i]);
        prototype_literal_at_.push_back(literal_at[i]);
      }
    }
    for (const SyntaxNode* name_node : declared) {
      Variable v = prototype;
      v.name = names.name_of(*name_node);
      v.location = map.location(name_node->begin);
      if (const Variable* earlier = domain_.find(v.name)) {
        invalid(
            "variable '" + v.name + "' is already declared" +
                (earlier->location.line > 0 ? " at line " + std::to_string(earlier->location.line)
                                            : std::string()),
            v.location);
        continue;
      }
      domain_.variables.push_back(std::move(v));
      literal_locations_.push_back(prototype_literal_at_);
    }
    prototype_literal_at_.clear();
  }

  bool bounds_valid(VarType type, bool is_unsigned, const std::string& name,
                    const std::string& lower, const std::string& upper,
                    const SourceLocation& lower_at, const SourceLocation& upper_at) {
    if (lower.empty()) return true;
    for (const auto& [bound, where] : {std::pair{lower, lower_at}, std::pair{upper, upper_at}}) {
      if (type == VarType::integer && !is_integer_literal(bound)) {
        invalid("bound " + bound + " of integer '" + name + "' is not a whole number", where);
        return false;
      }
      if (std::string why = number_misfit(bound); !why.empty()) {
        invalid("bound of '" + name + "': " + why, where);
        return false;
      }
    }
    if (is_unsigned && numeric_value(lower) < 0) {
      invalid("unsigned integer '" + name + "' cannot have the negative lower bound " + lower,
              lower_at);
      return false;
    }
    if (numeric_value(lower) > numeric_value(upper)) {
      invalid("range of '" + name + "' is empty: lower bound " + lower + " exceeds upper bound " +
                  upper,
              lower_at);
      return false;
    }
    return true;
  }

  void tick(const SyntaxNode& d, std::string_view text, const TextMap& map) {
    double value = 0;
    std::optional<double> per_unit;
    for (const auto& child : d.children) {
      if (child->is<g::tick_period>()) {
        const std::string period(child->text(text));
        if (std::string why = number_misfit(period); !why.empty()) {
          invalid("tick period: " + why, map.location(child->begin));
          return;
        }
        value = std::strtod(period.c_str(), nullptr);
      }
      if (child->is<g::tick_unit>()) per_unit = seconds_per_unit(child->text(text));
    }
    const SourceLocation where = map.location(d.begin);
    if (!per_unit) {
      invalid("the tick period needs a unit of time (e.g. 'tick 100 ms')", where);
      return;
    }
    if (domain_.tick_seconds) {
      invalid("the tick period is already declared" +
                  (domain_.tick_location.line > 0
                       ? " at line " + std::to_string(domain_.tick_location.line)
                       : std::string()),
              where);
      return;
    }
    if (!(value > 0) || !std::isfinite(value)) {
      invalid("the tick period must be greater than zero", where);
      return;
    }
    domain_.tick_seconds = value * *per_unit;
    domain_.tick_location = where;
  }

  void assumption(const SyntaxNode& d, std::string_view text, const TextMap& map,
                  detail::ExpressionBuilder& expressions) {
    Assumption a;
    for (const auto& child : d.children) {
      if (child->is<g::assumption_name>()) {
        a.name = std::string(child->text(text));
        a.location = map.location(child->begin);
      } else if (child->is<g::equivalence>()) {
        a.expr = expressions.build(*child);
      }
    }
    if (!a.expr) return;  // too deep: reported by the builder
    for (const Assumption& earlier : domain_.assumptions) {
      if (earlier.name == a.name) {
        invalid("assumption '" + a.name + "' is already declared" +
                    (earlier.location.line > 0 ? " at line " + std::to_string(earlier.location.line)
                                               : std::string()),
                a.location);
        return;
      }
    }
    domain_.assumptions.push_back(std::move(a));
  }

  Domain& domain_;
  std::vector<Finding>& findings_;
  // Where each enum literal was written, parallel to domain_.variables / enum_values.
  std::vector<std::vector<SourceLocation>> literal_locations_;
  std::vector<SourceLocation> prototype_literal_at_;
};

}  // namespace

Domain parse_domain_file(const std::string& content, const std::string& file,
                         std::vector<Finding>& findings) {
  Domain domain;
  try {
    DomainBuilder builder(domain, findings);
    for (const detail::Line& line : detail::content_lines(content))
      if (!detail::is_blank(line.text)) builder.line(line, file);
    builder.finish();
  } catch (const std::exception& e) {
    findings.push_back(make_finding(
        "fretish-syntax", std::string("could not parse the domain: ") + e.what(), {file, 1, 1}));
  }
  return domain;
}

}  // namespace uabt::fretish
