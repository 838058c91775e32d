#pragma once
#include <string>
#include <vector>

#include "base/location.hpp"
#include "base/value.hpp"

namespace uabt {

enum class Severity { note, warning, error };

const char* severity_name(Severity s);

// One result of any stage: a syntax error, a guard overlap, a conformance deviation.
// `check` is a stable id documented in checks/<id>.md (`uabt explain <id>`).
struct Finding {
  std::string check;
  Severity severity = Severity::error;
  std::string message;
  SourceLocation location;
  std::string adaptable;                  // adaptable node it concerns, if any
  std::vector<std::string> requirements;  // requirement ids involved, priority order
  std::vector<std::string> alternatives;  // alternatives involved
  State witness;                          // a full state that makes the finding true
  std::string node_path;                  // compiled-*: path of the node in the tree
  std::vector<std::string> notes;         // printed as "note:" lines under the finding
  // Other places the finding concerns, each with what it is (an overlap: the other
  // requirement); SARIF relatedLocations.
  struct Related {
    SourceLocation location;
    std::string message;
  };
  std::vector<Related> related;
};

// Builds a finding with the check's default severity from the catalogue.
Finding make_finding(const std::string& check, std::string message, SourceLocation location);

bool has_errors(const std::vector<Finding>& findings);

// Sorts findings by file, line, column, check and message so output is deterministic.
void sort_findings(std::vector<Finding>& findings);

}  // namespace uabt
