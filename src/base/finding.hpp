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
  // Findings of the same check in the same file that follow this one and are not listed: one
  // mistake repeated 20,000 times is reported 20 times and then counted (sort_findings).
  std::size_t more_like_it = 0;
};

// Names as a message lists them: "a", "a and b", "a, b and c".
std::string listed_with_and(const std::vector<std::string>& names);

// Builds a finding with the check's default severity from the catalogue.
Finding make_finding(const std::string& check, std::string message, SourceLocation location);

bool has_errors(const std::vector<Finding>& findings);

// How many findings of one check one file lists; the rest are counted on the last one listed.
inline constexpr std::size_t kFindingsListedPerCheckAndFile = 20;

// Sorts findings by file, line, column, check and message so output is deterministic, and
// keeps the first kFindingsListedPerCheckAndFile of each check in each file: the last one kept
// counts the others (`more_like_it`, and a note "and N more like it" every format prints).
void sort_findings(std::vector<Finding>& findings);

// The findings a list stands for: its size plus every `more_like_it`.
std::size_t findings_count(const std::vector<Finding>& findings);

}  // namespace uabt
