#include <iostream>

#include "base/files.hpp"
#include "bt/xml_io.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "cli/findings_output.hpp"
#include "conform/conform.hpp"

namespace uabt::cli {

void register_conform(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, source_root, compiled, nodes, format = "text", output;
    unsigned timeout_ms = 10000;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "conform", "Prove that a compiled BT implements the mission's requirements");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("COMPILED", args->compiled,
                  "compiled BT XML (uabt's, the paper generator's, or hand-edited)")
      ->required()
      ->check(CLI::ExistingFile);
  add_nodes_option(*cmd, args->nodes);
  add_number_option(*cmd, "--timeout-ms", 1, kMaxTimeoutMs,
                    "solver time limit per query (inconclusive fails)",
                    [args](std::int64_t ms) { args->timeout_ms = static_cast<unsigned>(ms); });
  add_findings_output_options(*cmd, args->format, args->output);
  add_source_root_option(*cmd, args->source_root);
  cmd->callback([args, &exit_code] {
    load::LoadOptions load_options;
    if (!args->nodes.empty()) load_options.nodes_file = args->nodes;
    auto mission = load_or_complain(args->mission, load_options, exit_code);
    if (!mission) return;
    report::ReportInput input =
        report::ReportInput::of(*mission, tool_version(), {"load", "conform"});
    const std::filesystem::path compiled_path(args->compiled);
    bt::ReadOptions read_options;
    read_options.confine_to =
        compiled_path.parent_path().empty() ? "." : compiled_path.parent_path();
    read_options.display_base = std::filesystem::current_path();
    std::vector<Finding> compiled_findings;
    auto compiled = bt::read_document(compiled_path, read_options, compiled_findings);
    if (compiled && !has_errors(mission->findings)) {
      conform::Options options;
      options.timeout_ms = args->timeout_ms;
      auto result = conform::conform_tree(*mission, *compiled, options);
      compiled_findings.insert(compiled_findings.end(), result.findings.begin(),
                               result.findings.end());
    }
    // Every finding's file is relative to the mission directory, this one's too.
    relocate_findings(compiled_findings, display_path(compiled_path, read_options.display_base),
                      relative_path(compiled_path, mission->dir));
    input.findings.insert(input.findings.end(), compiled_findings.begin(), compiled_findings.end());
    sort_findings(input.findings);
    input.uri_prefix = sarif_uri_prefix(args->mission, args->source_root);
    exit_code = write_findings(input, args->format, args->output, {"conforms", "does not conform"});
  });
}

}  // namespace uabt::cli
