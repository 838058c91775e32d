#include <filesystem>
#include <iostream>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "campaign/campaign.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "runtime/scenario.hpp"

namespace uabt::cli {

namespace {

std::set<campaign::Criterion> criteria_of(const std::string& name) {
  using campaign::Criterion;
  if (name == "decision") return {Criterion::decision};
  if (name == "mcdc") return {Criterion::mcdc};
  if (name == "boundary") return {Criterion::boundary};
  return {Criterion::decision, Criterion::mcdc, Criterion::boundary};
}

// The mission as loaded, or nullopt after printing why (the exit code is set).
std::optional<load::Mission> loaded_mission(const std::string& dir,
                                            const std::vector<std::string>& uplinks,
                                            int& exit_code) {
  load::LoadOptions options;
  for (const auto& u : uplinks) options.uplinks.push_back(u);
  auto mission = load_or_complain(dir, options);
  if (!mission) {
    exit_code = kExitUsage;
    return std::nullopt;
  }
  std::vector<Finding> errors;
  for (const auto& f : mission->findings)
    if (f.severity == Severity::error) errors.push_back(f);
  if (!errors.empty()) {
    TextOptions text;
    text.path_prefix = path_prefix_for(mission->dir);
    std::cerr << format_text(errors, text) << "uabt: " << dir
              << ": the mission does not load; fix the errors above first\n";
    exit_code = kExitFail;
    return std::nullopt;
  }
  return mission;
}

}  // namespace

// The test campaign: scenarios that select every alternative, decide every guard both ways,
// show each atom's independent effect (MC/DC) and sit on both sides of every boundary, each
// replayed on the runtime; OUT/junit.xml reports the replays.
void register_tests(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, out, criterion = "all", selection;
    std::vector<std::string> uplinks;
    std::int64_t max_ticks = 100;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "tests", "Write a test campaign (uabt run scenarios) and replay it; OUT/junit.xml");
  cmd->add_option("MISSION", args->mission, "mission directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--uplink", args->uplinks,
                  "an uplink package: the campaign of the mission with it merged")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", args->out, "directory for the scenarios, campaign.json, junit.xml")
      ->required();
  cmd->add_option("--criterion", args->criterion, "decision | mcdc | boundary | all (default)")
      ->check(CLI::IsMember({"decision", "mcdc", "boundary", "all"}));
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  cmd->add_option("--max-ticks", args->max_ticks, "max_ticks of each scenario (default 100)")
      ->check(CLI::PositiveNumber);
  cmd->callback([args, &exit_code] {
    auto mission = loaded_mission(args->mission, args->uplinks, exit_code);
    if (!mission) return;
    campaign::Options options;
    options.criteria = criteria_of(args->criterion);
    options.max_ticks = args->max_ticks;
    apply_selection(args->selection, options.compile);
    try {
      const campaign::Campaign c = campaign::build_campaign(*mission, options);
      const std::filesystem::path out(args->out);
      for (const auto& [name, content] : campaign::campaign_files(c))
        write_file_atomically(out / name, content);
      std::cout << campaign::campaign_text(c);
      exit_code = c.passed() ? kExitPass : kExitFail;
    } catch (const std::exception& e) {
      std::cerr << "uabt: tests: " << e.what() << "\n";
      exit_code = kExitFail;
    }
  });
}

// What scenarios (replayed) or monitor traces covered of the campaign's targets, and a
// scenario's initial state for each target they missed.
void register_coverage(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, format = "text", selection;
    std::vector<std::string> runs;
    std::int64_t max_ticks = 0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "coverage", "What scenarios or monitor traces covered of the campaign's targets");
  cmd->add_option("MISSION", args->mission, "mission directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("SCENARIO", args->runs,
                  "scenario JSON files (replayed) or monitor traces (JSON lines)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--format", args->format, "text | json")->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  cmd->callback([args, &exit_code] {
    auto mission = loaded_mission(args->mission, {}, exit_code);
    if (!mission) return;
    try {
      campaign::Model model(*mission, criteria_of("all"));
      compile::Options compile_options;
      apply_selection(args->selection, compile_options);
      const campaign::Replayer replayer(*mission, compile_options);
      campaign::CoverageReport report;
      report.mission = mission->name;
      report.targets = model.targets();
      report.skipped = model.skipped();
      std::vector<std::string> errors;
      for (const auto& file : args->runs) {
        std::string error;
        const auto content = read_text_file(file, error);
        if (!content) {
          errors.push_back(file + ": error: " + error);
          continue;
        }
        // A scenario is one JSON object; a monitor trace is one object a line.
        const bool trace = content->find("\"tick\"") != std::string::npos &&
                           content->find("\"state\"") != std::string::npos &&
                           content->find("\"initial\"") == std::string::npos;
        if (trace) {
          std::vector<Finding> findings;
          campaign::RunRecord run = campaign::observe_trace(*mission, *content, file, findings);
          if (!findings.empty()) {
            errors.push_back(format_text(findings));
            continue;
          }
          report.runs.push_back(std::move(run));
          continue;
        }
        try {
          report.runs.push_back(replayer.run(*content, file));
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
      std::cout << (args->format == "json" ? campaign::coverage_json(report)
                                           : campaign::coverage_text(report));
      bool all = true;
      for (std::size_t k = 0; k < report.targets.size(); ++k)
        all = all && (!report.targets[k].reachable || report.covered[k]);
      exit_code = all ? kExitPass : kExitFail;
    } catch (const std::exception& e) {
      std::cerr << "uabt: coverage: " << e.what() << "\n";
      exit_code = kExitFail;
    }
  });
}

}  // namespace uabt::cli
