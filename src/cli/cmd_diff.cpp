#include <iostream>

#include "base/diagnostics.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "report/impact.hpp"
#include "verify/impact.hpp"

namespace uabt::cli {

// The semantic impact of an uplink: which states change their selected alternative. Exit 0
// when both versions load and the impact was decided; 1 when either has errors or a question
// stayed open.
void register_diff(CLI::App& app, int& exit_code) {
  struct Args {
    std::string before, after, format = "text", output;
    unsigned timeout_ms = 10000;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Which states change their selected alternative between two versions");
  cmd->add_option("OLD", args->before, "mission directory as it runs now")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("NEW", args->after, "mission directory as uplinked")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--format", args->format, "output format")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("-o,--output", args->output, "write to FILE instead of standard output");
  cmd->add_option("--timeout-ms", args->timeout_ms, "solver time limit per query");
  cmd->callback([args, &exit_code] {
    auto before = load_or_complain(args->before, {});
    auto after = load_or_complain(args->after, {});
    if (!before || !after) {
      exit_code = kExitUsage;
      return;
    }
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
    exit_code = has_errors(impact.findings) ? kExitFail : kExitPass;
  });
}

}  // namespace uabt::cli
