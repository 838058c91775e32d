#include <iostream>

#include "base/diagnostics.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "report/impact.hpp"
#include "verify/impact.hpp"

namespace uabt::cli {

// The semantic impact of an uplink: which states change their selected alternative, between
// two mission directories or between a mission and the mission with an uplink package merged
// (the same merge as `gate --uplink` and `run`). Exit 0 when both versions load and the
// impact was decided; 1 when either has errors or a question stayed open, and with
// --exit-code also when any state changes its alternative (like `git diff --exit-code`).
void register_diff(CLI::App& app, int& exit_code) {
  struct Args {
    std::string before, after, uplink, format = "text", output;
    bool exit_on_change = false;
    unsigned timeout_ms = 10000;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Which states change their selected alternative between two versions");
  cmd->add_option("OLD", args->before, "mission directory as it runs now")
      ->required()
      ->check(CLI::ExistingDirectory);
  auto* after = cmd->add_option("NEW", args->after, "mission directory as uplinked")
                    ->check(CLI::ExistingDirectory);
  auto* uplink = cmd->add_option("--uplink", args->uplink,
                                 "an uplink package: NEW is OLD with the package merged")
                     ->check(CLI::ExistingDirectory);
  after->excludes(uplink);
  cmd->add_flag("--exit-code", args->exit_on_change,
                "exit 1 when any state changes its alternative");
  cmd->add_option("--format", args->format, "output format")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("-o,--output", args->output, "write to FILE instead of standard output");
  add_number_option(*cmd, "--timeout-ms", 1, kMaxTimeoutMs, "solver time limit per query",
                    [args](std::int64_t ms) { args->timeout_ms = static_cast<unsigned>(ms); });
  cmd->callback([args, &exit_code] {
    if (args->after.empty() && args->uplink.empty()) {
      std::cerr << "uabt diff: give NEW or --uplink DIR\n";
      exit_code = kExitUsage;
      return;
    }
    load::LoadOptions merged;
    if (!args->uplink.empty()) merged.uplinks.push_back(args->uplink);
    auto before = load_or_complain(args->before, {}, exit_code);
    auto after =
        load_or_complain(args->uplink.empty() ? args->after : args->before, merged, exit_code);
    if (!before || !after) return;
    if (has_errors(before->findings) || has_errors(after->findings)) {
      std::cerr << format_text(before->findings) << format_text(after->findings)
                << "uabt: diff needs two missions that load without errors\n";
      exit_code = kExitFail;
      return;
    }
    verify::Options options;
    options.timeout_ms = args->timeout_ms;
    verify::Impact impact = verify::selection_impact(*before, *after, options);
    emit(args->output,
         args->format == "json" ? report::impact_json(impact) : report::impact_text(impact));
    bool changed = false;
    for (const auto& node : impact.nodes) changed |= node.status != "unchanged";
    exit_code =
        has_errors(impact.findings) || (args->exit_on_change && changed) ? kExitFail : kExitPass;
  });
}

}  // namespace uabt::cli
