#include <filesystem>
#include <iostream>
#include <optional>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "campaign/campaign.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "verify/impact.hpp"

namespace uabt::cli {

// The test campaign: scenarios that select every alternative, decide every guard both ways,
// show each atom's independent effect (MC/DC), sit on both sides of every boundary and fire
// every guarantee's trigger with each of its atoms deciding (prove over world.json), each
// replayed on the runtime; OUT/junit.xml reports the replays.
void register_tests(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, out, criterion = "all", selection;
    std::vector<std::string> uplinks;
    std::int64_t max_ticks = 100;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "tests",
      "Write a test campaign (uabt run scenarios) and replay it; OUT/junit.xml; with --uplink, "
      "one more scenario per behaviour change of the last package");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("--uplink", args->uplinks,
                  "an uplink package: the campaign of the mission with it merged")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", args->out, "directory for the scenarios, campaign.json, junit.xml")
      ->required();
  cmd->add_option("--criterion", args->criterion,
                  "decision | mcdc | boundary | guarantee | all (default)")
      ->check(CLI::IsMember({"decision", "mcdc", "boundary", "guarantee", "all"}));
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  add_number_option(*cmd, "--max-ticks", 1, kMaxTicks, "max_ticks of each scenario (default 100)",
                    [args](std::int64_t ticks) { args->max_ticks = ticks; });
  cmd->callback([args, &exit_code] {
    check_output_directory(args->out, "--out");  // before the work, not after it
    auto mission = load_without_errors(args->mission, args->uplinks, exit_code);
    if (!mission) return;
    // The last package is the one tested, as `gate --uplink` gates it: its behaviour changes
    // are those from the mission with the packages before it.
    std::optional<load::Mission> running;
    if (!args->uplinks.empty()) {
      running = load_without_errors(args->mission, {args->uplinks.begin(), args->uplinks.end() - 1},
                                    exit_code);
      if (!running) return;
    }
    campaign::Options options;
    options.criteria = campaign_criteria(args->criterion);
    options.max_ticks = args->max_ticks;
    apply_selection(args->selection, options.compile);
    try {
      const campaign::Campaign c =
          running ? campaign::build_uplink_campaign(
                        *mission, verify::selection_impact(*running, *mission, {}), options)
                  : campaign::build_campaign(*mission, options);
      const std::filesystem::path out(args->out);
      for (const auto& [name, content] : campaign::campaign_files(c))
        write_file_atomically(out / name, content);
      std::cout << campaign::campaign_text(c);
      exit_code = c.passed() ? kExitPass : kExitFail;
    } catch (const OutputError&) {
      throw;  // an output path uabt cannot write: exit 2
    } catch (const std::exception& e) {
      std::cerr << "uabt: tests: " << e.what() << "\n";
      exit_code = kExitFail;
    }
  });
}

}  // namespace uabt::cli
