#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <regex>
#include <set>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "manager/manager.hpp"

namespace uabt::cli {

namespace {

// TICK:DIR → (tick, DIR as a path from the mission directory, which is how the manager
// resolves a package). DIR is given from the current directory, as every path on the command
// line. Prints why and returns nullopt when the argument is malformed or DIR is no directory.
std::optional<std::pair<std::int64_t, std::string>> parse_uplink_argument(
    const std::string& spec, const std::string& mission) {
  namespace fs = std::filesystem;
  const auto colon = spec.find(':');
  if (colon == std::string::npos) {
    std::cerr << "uabt: --uplink " << spec
              << ": expected TICK:DIR (a tick number, then the package directory)\n";
    return std::nullopt;
  }
  std::int64_t tick = 0;
  try {
    tick = whole_number("its TICK", spec.substr(0, colon), 0, kMaxTicks);
  } catch (const UsageError& e) {
    std::cerr << "uabt: --uplink " << spec << ": " << e.what()
              << " (TICK:DIR: a tick number, then the package directory)\n";
    return std::nullopt;
  }
  const fs::path dir = spec.substr(colon + 1);
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) {
    std::cerr << "uabt: --uplink " << spec << ": " << dir.generic_string()
              << ": no such directory (paths are relative to the current directory)\n";
    return std::nullopt;
  }
  return std::make_pair(tick, fs::proximate(dir, mission, ec).generic_string());
}

}  // namespace

// The Behavior Tree Manager on a simulated world. Exit 0 when the mission completes with
// SUCCESS; 1 when it fails, times out (max_ticks), stops on a tick error (verdict `error`:
// what BehaviorTree.CPP would throw, e.g. a script reading a key nobody set), or cannot
// start (the mission does not pass the gate, the scenario does not fit the mission).
void register_run(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, scenario, trace, monitor_trace, selection, trace_level = "events";
    std::vector<std::string> uplinks;
    std::int64_t max_ticks = 0;
    bool smart_selection = false, stats = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run the mission in a simulated world; uplinks go through the gate");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("--scenario", args->scenario,
                  "scenario JSON (missions/README.md, section \"scenarios/*.json\")")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option(
      "--uplink", args->uplinks,
      "TICK:DIR — an uplink package (a path from the current directory) arriving before tick "
      "TICK");
  cmd->add_option("--trace", args->trace,
                  "write the run's events (selections, uplinks, violations, …) as JSON lines to "
                  "FILE");
  cmd->add_option("--monitor-trace", args->monitor_trace,
                  "write what the mission properties read, one {\"tick\": t, \"state\": {…}} "
                  "line per tick, to FILE: the trace `uabt monitor` checks");
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  add_number_option(*cmd, "--max-ticks", 1, kMaxTicks,
                    "stop after this many ticks, verdict timeout (default: the scenario's)",
                    [args](std::int64_t ticks) { args->max_ticks = ticks; });
  cmd->add_flag("--smart-selection", args->smart_selection,
                "reactive selections re-run their guards only when a variable the guards read "
                "changed (not BT.CPP's tick; same selections, fewer condition ticks)");
  cmd->add_flag("--stats", args->stats, "print condition ticks per mission tick");
  cmd->add_option("--trace-level", args->trace_level,
                  "events, or nodes: also every node status change and condition read")
      ->check(CLI::IsMember({"events", "nodes"}));
  cmd->callback([args, &exit_code] {
    // Every --uplink is checked before the run starts: a typo must not let a run go on
    // without the uplink it was meant to test.
    std::vector<std::pair<std::int64_t, std::string>> uplinks;
    for (const auto& spec : args->uplinks) {
      auto uplink = parse_uplink_argument(spec, args->mission);
      if (!uplink) {
        exit_code = kExitUsage;
        return;
      }
      uplinks.push_back(std::move(*uplink));
    }
    try {
      runtime::Scenario scenario = runtime::load_scenario(args->scenario);
      const std::string counterexample_of = scenario.counterexample_of;
      manager::ManagerOptions options;
      options.max_ticks = args->max_ticks;
      options.trace_nodes = args->trace_level == "nodes";
      options.smart_selection = args->smart_selection;
      options.monitor_trace = !args->monitor_trace.empty();
      apply_selection(args->selection, options.gate.compile);
      manager::BehaviorTreeManager bt_manager(args->mission, std::move(scenario), options);
      for (const auto& [tick, package] : uplinks) bt_manager.add_uplink(tick, package);
      manager::ManagerRun run = bt_manager.run();
      if (!run.unverified.empty()) {
        std::set<std::string> checks;
        for (const Finding& f : run.unverified) checks.insert(f.check);
        std::string names;
        for (const std::string& c : checks) names += (names.empty() ? "" : ", ") + c;
        std::cerr << "uabt: warning: the mission does not pass the gate's checks ("
                  << run.unverified.size()
                  << (run.unverified.size() == 1 ? " error: " : " errors: ") << names
                  << "); it runs unverified, only to replay the counterexample of '"
                  << counterexample_of << "' in " << args->scenario << "\n";
      }
      std::cout << manager::trace_summary(run, path_prefix_for(args->mission))
                << manager::property_summary(run);
      if (args->stats) {
        char per_tick[32];
        std::snprintf(
            per_tick, sizeof per_tick, "%.2f",
            run.ticks ? static_cast<double>(run.condition_ticks) / static_cast<double>(run.ticks)
                      : 0.0);
        std::cout << "condition ticks: " << run.condition_ticks << " in " << run.ticks << " ticks ("
                  << per_tick << " per tick)\n";
      }
      if (!args->trace.empty())
        write_file_atomically(args->trace, runtime::trace_json_lines(run.trace));
      if (!args->monitor_trace.empty())
        write_file_atomically(args->monitor_trace, run.monitor_trace);
      if (run.error) {
        // GCC style: "file:line:col: error: …", then where in the running tree it happened.
        static const std::regex located(R"(^([^:]+:\d+:\d+): (.*)$)");
        std::smatch m;
        const std::string text = with_user_path(run.error->message, path_prefix_for(args->mission));
        if (std::regex_match(text, m, located))
          std::cerr << m[1] << ": error: " << m[2] << "\n";
        else
          std::cerr << "uabt: error: " << text << "\n";
        std::cerr << "  note: tick " << run.error->tick << ", node " << run.error->path << "\n";
        if (!run.error->script.empty())
          std::cerr << "  note: script `" << run.error->script << "`\n";
      }
      exit_code = run.verdict == "success" && !run.guarantees_failed ? kExitPass : kExitFail;
    } catch (const manager::NotAdmitted& e) {
      TextOptions text_options;
      text_options.path_prefix = path_prefix_for(args->mission);
      std::cerr << "uabt: " << e.what() << ":\n" << format_text(e.findings, text_options);
      exit_code = kExitFail;
    } catch (const runtime::ScenarioError& e) {
      std::cerr << e.what() << "\n";  // file:line:col: error: … lines
      exit_code = kExitFail;
    } catch (const OutputError&) {
      throw;  // an output path uabt cannot write: exit 2
    } catch (const std::exception& e) {
      std::cerr << "uabt: " << e.what() << "\n";
      exit_code = kExitFail;
    }
  });
}

}  // namespace uabt::cli
