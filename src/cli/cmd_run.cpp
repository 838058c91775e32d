#include <iostream>

#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "runtime/manager.hpp"

namespace uabt::cli {

// The Behavior Tree Manager on a simulated world. Exit 0 when the mission completes with
// SUCCESS, 1 when it fails, times out, or cannot start (the mission does not pass the gate).
void register_run(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, scenario, trace, selection = "sequence";
    std::vector<std::string> uplinks;
    std::int64_t max_ticks = 0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run the mission in a simulated world; uplinks go through the gate");
  cmd->add_option("MISSION", args->mission, "mission directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--scenario", args->scenario, "scenario JSON (DESIGN §8)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option(
      "--uplink", args->uplinks,
      "TICK:DIR — an uplink package, relative to the mission, arriving before tick TICK");
  cmd->add_option("--trace", args->trace, "write the trace as JSON lines to FILE");
  cmd->add_option("--selection", args->selection, "selector style of the compiled tree")
      ->check(CLI::IsMember({"sequence", "reactive"}));
  cmd->add_option("--max-ticks", args->max_ticks,
                  "stop after this many ticks (default: the scenario's)");
  cmd->callback([args, &exit_code] {
    try {
      runtime::Scenario scenario = runtime::load_scenario(args->scenario);
      runtime::ManagerOptions options;
      options.max_ticks = args->max_ticks;
      options.gate.compile.selection = args->selection == "reactive"
                                           ? compile::SelectionStyle::reactive
                                           : compile::SelectionStyle::sequence;
      runtime::BehaviorTreeManager manager(args->mission, std::move(scenario), options);
      for (const auto& spec : args->uplinks) {
        const auto colon = spec.find(':');
        std::int64_t tick = 0;
        try {
          if (colon == std::string::npos) throw std::invalid_argument("no ':'");
          tick = std::stoll(spec.substr(0, colon));
        } catch (const std::exception&) {
          std::cerr << "uabt: --uplink " << spec << ": expected TICK:DIR\n";
          exit_code = kExitUsage;
          return;
        }
        manager.add_uplink(tick, spec.substr(colon + 1));
      }
      runtime::ManagerRun run = manager.run();
      std::cout << runtime::trace_summary(run) << runtime::property_summary(run);
      if (!args->trace.empty())
        write_file_atomically(args->trace, runtime::trace_json_lines(run.trace));
      exit_code =
          run.finished && run.status == runtime::NodeStatus::success && !run.guarantees_failed
              ? kExitPass
              : kExitFail;
    } catch (const std::exception& e) {
      std::cerr << "uabt: " << e.what() << "\n";
      exit_code = kExitFail;
    }
  });
}

}  // namespace uabt::cli
