#include "report/model.hpp"

#include <algorithm>

#include <cctype>

#include "base/text.hpp"

namespace uabt::report {

ReportInput ReportInput::of(const load::Mission& mission, std::string tool_version,
                            std::vector<std::string> stages) {
  ReportInput input;
  input.tool_version = std::move(tool_version);
  input.mission_name = mission.name;
  input.mission = &mission;
  for (const auto& site : mission.adaptables)
    if (!site.id.empty() && std::find(input.adaptables.begin(), input.adaptables.end(), site.id) ==
                                input.adaptables.end())
      input.adaptables.push_back(site.id);
  input.findings = mission.findings;
  input.stages = std::move(stages);
  return input;
}

std::string ReportInput::verdict_text() const {
  if (!passed()) return "fail";
  int retired = 0, weakened = 0;
  if (uplink)
    for (const ContractChange& c : uplink->contract) {
      if (c.old_holds || c.consent.empty()) continue;
      ++(c.change == "removed" ? retired : weakened);
    }
  const auto count = [](int n, const char* what) {
    return std::to_string(n) + (n == 1 ? " guarantee " : " guarantees ") + what;
  };
  if (retired && weakened)
    return "pass with " + count(retired, "retired") + " and " + std::to_string(weakened) +
           " weakened";
  if (retired) return "pass with " + count(retired, "retired");
  if (weakened) return "pass with " + count(weakened, "weakened");
  return "pass";
}

std::string ReportInput::banner() const {
  std::string out = verdict_text();
  for (std::size_t i = 0; i < out.size() && out[i] != ' '; ++i)
    out[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[i])));
  return out;
}

std::string TestCampaign::headline() const {
  if (!not_built.empty()) return "no test campaign: " + not_built;
  std::string out = directory + ": " + count_text(scenarios, "scenario");
  if (change_scenarios > 0)
    out += " (" + std::to_string(change_scenarios) + " for " +
           (change_scenarios == 1 ? "a behaviour change" : "behaviour changes") + ")";
  return out + (scenarios == 1 ? " covers " : " cover ") + std::to_string(covered) + " of " +
         count_text(reachable, "reachable target") + "; " + count_text(targets, "target") + ", " +
         std::to_string(targets - reachable - undecided.size()) + " unreachable" +
         (undecided.empty() ? "" : ", " + std::to_string(undecided.size()) + " not decided");
}

std::vector<std::string> TestCampaign::details() const {
  std::vector<std::string> out;
  for (const auto& [target, reason] : unreachable)
    out.push_back("unreachable: " + target + ": " + reason);
  for (const auto& [target, reason] : undecided)
    out.push_back("not decided: " + target + ": " + reason);
  for (const auto& [node, reason] : skipped)
    out.push_back("no targets for " + node + ": " + reason);
  out.insert(out.end(), notes.begin(), notes.end());
  for (const auto& problem : problems) out.push_back("not reached: " + problem);
  return out;
}

}  // namespace uabt::report
