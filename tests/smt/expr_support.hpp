#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/domain.hpp"
#include "fretish/parse.hpp"

namespace uabt::testing {

// Parses a FRETISH expression as if it stood at requirements.fret:1:1; throws on a syntax error
// so a typo in a test cannot pass as a verdict.
inline fretish::ExprPtr expr(const std::string& text) {
  std::vector<Finding> findings;
  fretish::ExprPtr e = fretish::parse_expression(text, {"requirements.fret", 1, 1}, findings);
  if (!e || has_errors(findings))
    throw std::runtime_error("test expression does not parse: " + text +
                             (findings.empty() ? "" : ": " + findings.front().message));
  return e;
}

// A domain from domain.fret text; throws when the text has errors.
inline fretish::Domain domain(const std::string& text) {
  std::vector<Finding> findings;
  fretish::Domain d = fretish::parse_domain_file(text, "domain.fret", findings);
  if (has_errors(findings))
    throw std::runtime_error("test domain does not parse: " + findings.front().message);
  return d;
}

}  // namespace uabt::testing
