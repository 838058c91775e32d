#include <set>
#include <system_error>

#include "base/files.hpp"
#include "gate/gate.hpp"

namespace uabt::gate {

void add_test_campaign(Outcome& outcome, const Options& options, const std::string& directory) {
  report::TestCampaign& summary = outcome.report.campaign.emplace();
  summary.directory = directory;
  if (!outcome.passed()) {
    summary.not_built = "the gate failed (a mission that fails the gate is not tested)";
    return;
  }
  campaign::Options campaign_options;
  campaign_options.compile = options.compile;
  if (outcome.compiled_tree) {
    campaign_options.compiled_tree = &*outcome.compiled_tree;
    campaign_options.trace = &outcome.compiled.trace;
  }
  try {
    outcome.campaign = outcome.report.uplink
                           ? campaign::build_uplink_campaign(
                                 *outcome.mission, outcome.report.uplink->impact, campaign_options)
                           : campaign::build_campaign(*outcome.mission, campaign_options);
  } catch (const std::exception& e) {
    summary.not_built = e.what();
    return;
  }
  const campaign::Campaign& c = *outcome.campaign;
  summary.scenarios = c.scenarios.size();
  summary.change_scenarios = c.change_scenarios();
  summary.targets = c.targets.size();
  for (std::size_t t = 0; t < c.targets.size(); ++t) {
    const campaign::Target& target = c.targets[t];
    if (!target.reachable) {
      (target.undecided ? summary.undecided : summary.unreachable)
          .emplace_back(target.text, target.reason);
      continue;
    }
    ++summary.reachable;
    if (c.covered[t]) ++summary.covered;
  }
  summary.skipped = c.skipped;
  summary.notes = c.notes;
  for (const auto& s : c.scenarios)
    for (const auto& problem : s.problems) summary.problems.push_back(s.name + ".json: " + problem);
}

void write_test_campaign(const Outcome& outcome, const std::filesystem::path& dir) {
  std::set<std::string> written;
  if (outcome.campaign)
    for (const auto& [name, content] : campaign::campaign_files(*outcome.campaign)) {
      write_file_atomically(dir / name, content);
      written.insert(name);
    }
  std::error_code error;
  if (!std::filesystem::is_directory(dir, error)) return;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    const auto name = entry.path().filename().string();
    const auto extension = entry.path().extension();
    if ((extension == ".json" || name == campaign::kJunitFile) && !written.count(name))
      remove_output_file(entry.path());
  }
  // Only when empty, and never a link to a directory of the user's.
  if (written.empty() && !std::filesystem::is_symlink(dir, error))
    std::filesystem::remove(dir, error);
}

}  // namespace uabt::gate
