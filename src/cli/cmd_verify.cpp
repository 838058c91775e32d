#include <iostream>

#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "cli/findings_output.hpp"
#include "verify/verify.hpp"

namespace uabt::cli {

void register_verify(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, source_root, nodes, format = "text", output;
    bool allow_overlap = false;
    unsigned timeout_ms = 10000;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "Prove the selection guards unambiguous, complete and reachable");
  add_mission_argument(*cmd, args->mission);
  add_nodes_option(*cmd, args->nodes);
  add_findings_output_options(*cmd, args->format, args->output);
  add_source_root_option(*cmd, args->source_root);
  cmd->add_flag("--allow-overlap", args->allow_overlap,
                "report overlapping guards as warnings (priority decides on purpose)");
  add_number_option(*cmd, "--timeout-ms", 1, kMaxTimeoutMs,
                    "solver time limit per query; past it the verdict is inconclusive and fails",
                    [args](std::int64_t ms) { args->timeout_ms = static_cast<unsigned>(ms); });
  cmd->callback([args, &exit_code] {
    load::LoadOptions load_options;
    if (!args->nodes.empty()) load_options.nodes_file = args->nodes;
    auto mission = load_or_complain(args->mission, load_options, exit_code);
    if (!mission) return;
    verify::Options options;
    options.allow_overlap = args->allow_overlap;
    options.timeout_ms = args->timeout_ms;
    verify::Result result = verify::verify_mission(*mission, options);
    report::ReportInput input =
        report::ReportInput::of(*mission, tool_version(), {"load", "verify"});
    input.findings.insert(input.findings.end(), result.findings.begin(), result.findings.end());
    sort_findings(input.findings);
    input.coverage = std::move(result.coverage);
    input.uri_prefix = sarif_uri_prefix(args->mission, args->source_root);
    exit_code = write_findings(input, args->format, args->output);
  });
}

}  // namespace uabt::cli
