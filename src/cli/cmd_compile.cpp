#include <unistd.h>

#include <iostream>

#include "base/diagnostics.hpp"
#include "bt/xml_io.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "compile/compile.hpp"

namespace uabt::cli {

void register_compile(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, output, selection, nodes;
    int bt_format = 4;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd =
      app.add_subcommand("compile", "Compile an adaptable mission into one BT (Algorithm 1)");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("-o,--output", args->output, "output XML file (default: stdout)");
  add_number_option(*cmd, "--bt-format", 3, 4, "BehaviorTree.CPP XML format",
                    [args](std::int64_t format) { args->bt_format = static_cast<int>(format); });
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  add_nodes_option(*cmd, args->nodes);
  cmd->callback([args, &exit_code] {
    load::LoadOptions load_options;
    if (!args->nodes.empty()) load_options.nodes_file = args->nodes;
    auto mission = load_or_complain(args->mission, load_options, exit_code);
    if (!mission) return;
    compile::Options options;
    options.bt_format = args->bt_format;
    apply_selection(args->selection, options);
    compile::Result result = compile::compile_mission(*mission, options);
    std::vector<Finding> shown = mission->findings;
    shown.insert(shown.end(), result.findings.begin(), result.findings.end());
    TextOptions text;
    text.path_prefix = path_prefix_for(mission->dir);
    text.source_dir = mission->dir;
    text.show_source = ::isatty(STDERR_FILENO) != 0;
    std::cerr << format_text(shown, text);
    if (has_errors(mission->findings) || !result.ok) {
      std::cerr << "uabt: " << mission->name << ": not compiled\n";
      exit_code = kExitFail;
      return;
    }
    bt::WriteOptions write_options;
    write_options.format = args->bt_format;
    emit(args->output, bt::write_document(result.document, write_options));
    // compile emits whatever loads; deciding what may fly is the gate's job.
    std::cerr << "uabt: " << mission->name
              << ": compiled, not verified: `uabt gate` proves the guards and the tree\n";
    exit_code = kExitPass;
  });
}

}  // namespace uabt::cli
