#include "base/finding.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "base/catalogue.hpp"

namespace uabt {

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::note: return "note";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
  }
  return "error";
}

Finding make_finding(const std::string& check, std::string message, SourceLocation location) {
  const CheckInfo* info = find_check(check);
  // An undocumented check id is a programming error: every finding must be explainable.
  if (info == nullptr) throw std::logic_error("finding with undocumented check id: " + check);
  Finding f;
  f.check = check;
  const std::string sev = info->severity;
  f.severity = sev == "warning" ? Severity::warning
               : sev == "note"  ? Severity::note
                                : Severity::error;
  f.message = std::move(message);
  f.location = std::move(location);
  return f;
}

bool has_errors(const std::vector<Finding>& findings) {
  return std::any_of(findings.begin(), findings.end(),
                     [](const Finding& f) { return f.severity == Severity::error; });
}

void sort_findings(std::vector<Finding>& findings) {
  std::stable_sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
    return std::tie(a.location.file, a.location.line, a.location.column, a.check, a.adaptable,
                    a.message) < std::tie(b.location.file, b.location.line, b.location.column,
                                          b.check, b.adaptable, b.message);
  });
}

}  // namespace uabt
