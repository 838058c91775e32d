#include <unistd.h>

#include <iostream>

#include "base/diagnostics.hpp"
#include "bt/schema.hpp"
#include "bt/xml_io.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"

namespace uabt::cli {

void register_schema(CLI::App& app, int& exit_code) {
  struct Args {
    std::string nodes, output;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "schema",
      "Write an XML Schema (XSD 1.0) of the trees the robot can load: BehaviorTree.CPP 4.10's "
      "built-in nodes plus those of NODES.xml, one element per node ID with an attribute per "
      "port (required when it has no default; typed when its type maps to XSD), for editors and "
      "`xmllint --schema nodes.xsd alternative.xml`");
  cmd->add_option("NODES.xml", args->nodes,
                  "the robot's <TreeNodesModel> (nodes.xml, or any BehaviorTree.CPP file with one)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "schema file to write (default: stdout)");
  cmd->callback([args, &exit_code] {
    std::vector<Finding> findings;
    bt::ReadOptions read_options;
    read_options.confine_to = std::filesystem::path(args->nodes).parent_path();
    if (read_options.confine_to.empty()) read_options.confine_to = ".";
    read_options.display_base = std::filesystem::current_path();
    auto document = bt::read_document(args->nodes, read_options, findings);
    TextOptions text;
    text.show_source = ::isatty(STDERR_FILENO) != 0;
    std::cerr << format_text(findings, text);
    if (!document || has_errors(findings)) {
      std::cerr << "uabt: " << args->nodes << ": no schema written\n";
      exit_code = kExitFail;
      return;
    }
    emit(args->output, bt::write_schema(document->node_models));
    exit_code = kExitPass;
  });
}

}  // namespace uabt::cli
