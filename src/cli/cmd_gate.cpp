#include <iostream>

#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "cli/findings_output.hpp"
#include "gate/gate.hpp"
#include "gate/uplink.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::cli {

void register_gate(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, source_root, out = "uabt-report", nodes, selection, format = "text",
                                      output, uplink;
    bool allow_overlap = false;
    unsigned timeout_ms = 10000;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "gate",
      "The pre-uplink gate: verify, compile, conform, and write every report and OUT/tests/");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("--out", args->out, "report directory (default: uabt-report)");
  add_nodes_option(*cmd, args->nodes);
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  cmd->add_flag("--allow-overlap", args->allow_overlap,
                "report overlapping guards as warnings (priority decides on purpose)");
  add_number_option(*cmd, "--timeout-ms", 1, kMaxTimeoutMs,
                    "solver time limit per query (inconclusive fails)",
                    [args](std::int64_t ms) { args->timeout_ms = static_cast<unsigned>(ms); });
  cmd->add_option("--uplink", args->uplink,
                  "an uplink package to merge and gate before it is sent; the reports add where "
                  "each requirement went and the behaviour change, OUT/merged/ the merged mission, "
                  "OUT/tests/ its test campaign with a scenario per behaviour change")
      ->check(CLI::ExistingDirectory);
  add_findings_output_options(*cmd, args->format, args->output);
  add_source_root_option(*cmd, args->source_root);
  cmd->callback([args, &exit_code] {
    check_output_directory(args->out, "--out");  // before the work, not after it
    load::LoadOptions load_options;
    if (!args->nodes.empty()) load_options.nodes_file = args->nodes;
    auto mission = load_or_complain(args->mission, load_options, exit_code);
    if (!mission) return;
    std::optional<load::Mission> running;
    if (!args->uplink.empty()) {
      running = std::move(mission);
      load_options.uplinks.push_back(args->uplink);
      mission = load_or_complain(args->mission, load_options, exit_code);
      if (!mission) return;
    }
    gate::Options options;
    options.verify.allow_overlap = args->allow_overlap;
    options.verify.timeout_ms = args->timeout_ms;
    options.conform.timeout_ms = args->timeout_ms;
    apply_selection(args->selection, options.compile);
    // How the reports tell to replay a counterexample: the style given on the command line
    // (without one, `uabt run` compiles each node in the style the mission declares).
    options.proof_reporting.counterexample_dir =
        (std::filesystem::path(args->out) / "counterexamples").generic_string();
    options.proof_reporting.mission_path =
        running ? (std::filesystem::path(args->out) / "merged").generic_string() : args->mission;
    if (!args->selection.empty())
      options.proof_reporting.run_options = "--selection " + args->selection;
    // A mission with guarantees passes only when each one is proved (ARCHITECTURE §10).
    gate::Outcome outcome =
        running ? gate::run_uplink_gate(*running, std::move(*mission), options, tool_version())
                : gate::run_gate(std::move(*mission), options, tool_version());
    outcome.report.uri_prefix = sarif_uri_prefix(args->mission, args->source_root);
    // What conform says about the compiled tree points at its file in the report directory.
    if (!outcome.report.compiled_tree_file.empty())
      relocate_findings(
          outcome.report.findings, outcome.report.compiled_tree_file,
          relative_path(std::filesystem::path(args->out) / outcome.report.compiled_tree_file,
                        outcome.mission->dir));
    // The test campaign for the testbed, beside the reports (never a finding).
    gate::add_test_campaign(outcome, options, "tests/");
    report::write_reports(outcome.report, args->out, outcome.compiled_xml);
    gate::write_test_campaign(outcome, std::filesystem::path(args->out) / "tests");
    if (running)
      gate::write_merged_mission(*outcome.mission, std::filesystem::path(args->out) / "merged");
    exit_code = write_findings(outcome.report, args->format, args->output);
  });
}

}  // namespace uabt::cli
