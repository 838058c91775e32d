#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/domain.hpp"
#include "fretish/requirement.hpp"

namespace uabt::fretish {

// Where a piece of FRETISH text sits in its file, so that errors name the right line/column.
struct TextOrigin {
  std::string file;  // as displayed (relative to the mission directory)
  int line = 1;      // line of the text's first character
  int column = 1;    // column of the text's first character
};

struct ParseResult {
  std::vector<Requirement> requirements;
  std::vector<Finding> findings;  // fretish-syntax errors, fretish-precedence warnings
};

// One sentence (no label). Appends findings; returns nullopt on a syntax error.
std::optional<Requirement> parse_requirement(const std::string& text, const TextOrigin& origin,
                                             std::vector<Finding>& findings);

// A standalone expression (domain assumptions, tests).
ExprPtr parse_expression(const std::string& text, const TextOrigin& origin,
                         std::vector<Finding>& findings);

// requirements.fret: one requirement a line, `#` comments, optional `ID:` label, optional
// trailing `.`; an unlabelled requirement gets the id R<line>.
ParseResult parse_requirements_file(const std::string& content, const std::string& file);

// A FRET export: a bare array of requirements or {requirements, variables}. Variables'
// dataType feeds `domain`; "assumption" reqids become assumptions.
ParseResult parse_fret_json(const std::string& content, const std::string& file, Domain& domain);

// domain.fret: declarations and `assume NAME: expr`.
Domain parse_domain_file(const std::string& content, const std::string& file,
                         std::vector<Finding>& findings);

}  // namespace uabt::fretish
