#include <iostream>

#include "base/catalogue.hpp"
#include "base/suggest.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"

namespace uabt::cli {

void register_explain(CLI::App& app, int& exit_code) {
  auto id = std::make_shared<std::string>();
  CLI::App* cmd =
      app.add_subcommand("explain", "Explain a check: why it matters, an example, the fix");
  cmd->add_option("CHECK-ID", *id, "check id, e.g. guard-overlap (omit to list every check)");
  cmd->callback([id, &exit_code] {
    if (id->empty()) {
      for (const auto& info : check_catalogue())
        std::cout << info.id << " (" << info.severity << ", " << info.stage << "): " << info.summary
                  << "\n";
      exit_code = kExitPass;
      return;
    }
    const CheckInfo* info = find_check(*id);
    if (info == nullptr) {
      std::vector<std::string> ids;
      for (const auto& known : check_catalogue()) ids.push_back(known.id);
      const std::string hint = did_you_mean(*id, ids);
      std::cerr << "uabt: unknown check '" << *id << "'" << (hint.empty() ? "" : " (" + hint + ")")
                << "; `uabt checks` lists them\n";
      exit_code = kExitUsage;
      return;
    }
    std::cout << "# " << info->id << " (" << info->severity << ")\n\n"
              << info->summary << "\n"
              << info->doc;
    exit_code = kExitPass;
  });
}

}  // namespace uabt::cli
