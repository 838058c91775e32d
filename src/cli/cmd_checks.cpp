#include <iostream>

#include "base/catalogue.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"

namespace uabt::cli {

// The catalogue of checks (generated from checks/*.md): one line each, or a Markdown table.
void register_checks(CLI::App& app, int& exit_code) {
  auto format = std::make_shared<std::string>("text");
  CLI::App* cmd = app.add_subcommand("checks", "List every check: id, severity, stage, summary");
  cmd->add_option("--format", *format, "text or markdown (a table for documentation)")
      ->check(CLI::IsMember({"text", "markdown"}));
  cmd->callback([format, &exit_code] {
    if (*format == "markdown") {
      std::cout << "| check | severity | stage | what it catches |\n| --- | --- | --- | --- |\n";
      for (const auto& info : check_catalogue())
        std::cout << "| `" << info.id << "` | " << info.severity << " | " << info.stage << " | "
                  << info.summary << " |\n";
    } else {
      for (const auto& info : check_catalogue())
        std::cout << info.id << " (" << info.severity << ", " << info.stage << "): " << info.summary
                  << "\n";
    }
    exit_code = kExitPass;
  });
}

}  // namespace uabt::cli
