#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "campaign/campaign.hpp"
#include "campaign/guarantee.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "runtime/scenario.hpp"
#include "verify/verify.hpp"

namespace uabt::cli {

namespace {

// The runs a command line names: a file as given; a folder (a campaign `uabt tests` wrote, a
// testbed's traces) as its .json and .jsonl files in name order, without the campaign's own
// summary.
std::vector<std::string> expand_runs(const std::vector<std::string>& arguments,
                                     std::vector<std::string>& errors) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const auto& argument : arguments) {
    if (!fs::is_directory(argument)) {
      files.push_back(argument);
      continue;
    }
    std::vector<std::string> inside;
    for (const auto& entry : fs::directory_iterator(argument)) {
      const fs::path& path = entry.path();
      if (!entry.is_regular_file() || path.filename() == campaign::kSummaryFile) continue;
      if (path.extension() == ".json" || path.extension() == ".jsonl")
        inside.push_back(path.generic_string());
    }
    std::sort(inside.begin(), inside.end());
    if (inside.empty())
      errors.push_back(argument +
                       ": error: no scenario (.json) or monitor trace (.jsonl) in this "
                       "folder");
    files.insert(files.end(), inside.begin(), inside.end());
  }
  return files;
}

// A monitor trace is one JSON object a line, each a tick (or a selection header); a scenario
// is one object over the whole file, so its first line alone is not a complete object.
bool is_monitor_trace(const std::string& content) {
  const std::size_t begin = content.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return false;
  const std::size_t end = content.find('\n', begin);
  const auto line = nlohmann::json::parse(
      content.substr(begin, end == std::string::npos ? std::string::npos : end - begin), nullptr,
      false);
  return line.is_object() && (line.contains("tick") || line.contains("selection"));
}

}  // namespace

// What scenarios (replayed) or monitor traces covered of the campaign's targets, and a
// scenario's initial state for each target they missed.
void register_coverage(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, format = "text", selection, output;
    std::vector<std::string> runs, uplinks;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "coverage", "What scenarios or monitor traces covered of the campaign's targets");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("--uplink", args->uplinks,
                  "an uplink package: the targets of the mission with it merged, as uabt tests "
                  "--uplink plans them")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("SCENARIO", args->runs,
                  "scenario JSON files (replayed), monitor traces (JSON lines), or folders of "
                  "them (a campaign from uabt tests)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--format", args->format,
                  "text | json | html (a page with the visited cells drawn over each node's "
                  "coverage map)")
      ->check(CLI::IsMember({"text", "json", "html"}));
  cmd->add_option("-o,--output", args->output, "write the output to FILE");
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  cmd->callback([args, &exit_code] {
    auto mission = load_without_errors(args->mission, args->uplinks, exit_code);
    if (!mission) return;
    try {
      campaign::Options options;
      options.criteria = campaign_criteria("all");
      campaign::Model model(*mission, options.criteria);
      apply_selection(args->selection, options.compile);
      const auto replayer = campaign::Replayer::compiling(*mission, options.compile);
      // The guarantee targets, solved in world.json's world as `uabt tests` solves them.
      std::optional<prove::WorldModel> world;
      options.world = campaign::load_world(*mission, world);
      const campaign::GuaranteePlan guarantees =
          campaign::plan_guarantee_targets(*mission, replayer, options);
      campaign::CoverageReport report;
      report.mission = mission->name;
      report.targets = model.targets();
      report.skipped = model.skipped();
      report.notes = guarantees.notes;
      const std::size_t first = report.targets.size();
      report.targets.insert(report.targets.end(), guarantees.targets.begin(),
                            guarantees.targets.end());
      // A missed guarantee target gets the campaign's scenario that reaches it.
      for (const auto& s : guarantees.scenarios)
        for (std::size_t t : s.purpose)
          if (s.problems.empty()) report.targets[first + t].scenario = s.json;
      std::set<std::size_t> reached;                  // guarantee targets, by the runs
      std::map<std::size_t, std::string> not_judged;  // guarantee targets a trace cannot judge
      std::set<std::size_t> judged;
      std::vector<std::string> errors;
      for (const auto& file : expand_runs(args->runs, errors)) {
        if (std::filesystem::path(file).filename() == campaign::kSummaryFile) {
          errors.push_back(file +
                           ": error: this is the summary `uabt tests` writes beside its "
                           "scenarios, not a scenario: name the scenarios or their folder");
          continue;
        }
        std::string error;
        const auto content = read_text_file(file, error);
        if (!content) {
          errors.push_back(file + ": error: " + error);
          continue;
        }
        if (is_monitor_trace(*content)) {
          std::vector<Finding> findings;
          campaign::RunRecord run = campaign::observe_trace(*mission, *content, file, findings);
          if (!findings.empty()) {
            errors.push_back(format_text(findings));
            continue;
          }
          report.runs.push_back(std::move(run));
          std::map<std::size_t, std::string> lacks;
          for (std::size_t t : campaign::guarantees_reached(guarantees, *content, file, lacks))
            reached.insert(t);
          for (std::size_t t = 0; t < guarantees.targets.size(); ++t) {
            const auto it = lacks.find(t);
            if (it == lacks.end())
              judged.insert(t);
            else
              not_judged.emplace(t, file + ": " + it->second);
          }
          continue;
        }
        try {
          report.runs.push_back(replayer.run(*content, file));
          for (std::size_t t : campaign::guarantees_reached(guarantees, replayer, *content, file))
            reached.insert(t);
          for (std::size_t t = 0; t < guarantees.targets.size(); ++t) judged.insert(t);
        } catch (const runtime::ScenarioError& e) {
          errors.push_back(e.what());
        }
      }
      if (!errors.empty()) {
        for (const auto& e : errors) std::cerr << e << (e.ends_with("\n") ? "" : "\n");
        exit_code = kExitFail;
        return;
      }
      report.covered = model.covered(report.runs);
      for (std::size_t t = 0; t < guarantees.targets.size(); ++t) {
        report.covered.push_back(reached.count(t) > 0);
        // Not judged by any run: not counted as missed.
        const auto why = not_judged.find(t);
        if (!judged.count(t) && why != not_judged.end() && guarantees.targets[t].reachable)
          report.not_judged.emplace(first + t, why->second);
      }
      report.visits = model.visits(report.runs);
      if (args->format == "html") {
        // The coverage maps, as `uabt report` draws them.
        const verify::Result verified = verify::verify_mission(*mission, {});
        emit(args->output,
             campaign::coverage_html(report, *mission, verified.coverage, tool_version()));
      } else {
        emit(args->output, args->format == "json" ? campaign::coverage_json(report)
                                                  : campaign::coverage_text(report));
      }
      bool all = true;
      for (std::size_t k = 0; k < report.targets.size(); ++k)
        all = all &&
              (!report.targets[k].reachable || report.covered[k] || report.not_judged.count(k));
      exit_code = all ? kExitPass : kExitFail;
    } catch (const OutputError&) {
      throw;  // an output path uabt cannot write: exit 2
    } catch (const std::exception& e) {
      std::cerr << "uabt: coverage: " << e.what() << "\n";
      exit_code = kExitFail;
    }
  });
}

}  // namespace uabt::cli
