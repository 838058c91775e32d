#include "base/finding.hpp"

#include <algorithm>
#include <map>
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

std::string listed_with_and(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k)
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return out;
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

namespace {

std::string more_like_it_note(std::size_t count) {
  std::string digits = std::to_string(count), grouped;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    if (k > 0 && (digits.size() - k) % 3 == 0) grouped += ',';
    grouped += digits[k];
  }
  return "and " + grouped + " more like it in this file, not listed: uabt lists the first " +
         std::to_string(kFindingsListedPerCheckAndFile) + " findings of a check in a file";
}

// Keeps the first kFindingsListedPerCheckAndFile findings of each check in each file; the last
// one kept counts the rest. Running it again on its own output changes nothing.
void summarise_repeats(std::vector<Finding>& findings) {
  std::map<std::pair<std::string, std::string>, std::vector<std::size_t>> groups;
  for (std::size_t k = 0; k < findings.size(); ++k)
    groups[{findings[k].location.file, findings[k].check}].push_back(k);
  std::vector<bool> dropped(findings.size(), false);
  bool any = false;
  for (const auto& [key, members] : groups) {
    if (members.size() <= kFindingsListedPerCheckAndFile) continue;
    any = true;
    Finding& last = findings[members[kFindingsListedPerCheckAndFile - 1]];
    if (last.more_like_it > 0) last.notes.pop_back();  // its earlier count, recounted below
    for (std::size_t k = kFindingsListedPerCheckAndFile; k < members.size(); ++k) {
      last.more_like_it += 1 + findings[members[k]].more_like_it;
      dropped[members[k]] = true;
    }
    last.notes.push_back(more_like_it_note(last.more_like_it));
  }
  if (!any) return;
  std::vector<Finding> kept;
  kept.reserve(findings.size());
  for (std::size_t k = 0; k < findings.size(); ++k)
    if (!dropped[k]) kept.push_back(std::move(findings[k]));
  findings = std::move(kept);
}

}  // namespace

void sort_findings(std::vector<Finding>& findings) {
  std::stable_sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
    return std::tie(a.location.file, a.location.line, a.location.column, a.check, a.adaptable,
                    a.message) < std::tie(b.location.file, b.location.line, b.location.column,
                                          b.check, b.adaptable, b.message);
  });
  summarise_repeats(findings);
}

std::size_t findings_count(const std::vector<Finding>& findings) {
  std::size_t count = findings.size();
  for (const auto& f : findings) count += f.more_like_it;
  return count;
}

}  // namespace uabt
