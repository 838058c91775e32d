#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "smt/solver.hpp"

int main(int argc, char** argv) {
  uabt::smt::keep_freed_memory();
  CLI::App app{"uabt: compile, verify and run adaptable behavior trees"};
  app.require_subcommand(1);
  app.set_version_flag("--version", uabt::cli::tool_version());
  int exit_code = uabt::cli::kExitPass;
  uabt::cli::register_compile(app, exit_code);
  uabt::cli::register_verify(app, exit_code);
  uabt::cli::register_conform(app, exit_code);
  uabt::cli::register_gate(app, exit_code);
  uabt::cli::register_report(app, exit_code);
  uabt::cli::register_diff(app, exit_code);
  uabt::cli::register_run(app, exit_code);
  uabt::cli::register_prove(app, exit_code);
  uabt::cli::register_realizable(app, exit_code);
  uabt::cli::register_monitor(app, exit_code);
  uabt::cli::register_schema(app, exit_code);
  uabt::cli::register_tests(app, exit_code);
  uabt::cli::register_coverage(app, exit_code);
  uabt::cli::register_explain(app, exit_code);
  uabt::cli::register_checks(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : uabt::cli::kExitUsage;
  } catch (const uabt::cli::UsageError& e) {
    std::cerr << "uabt: " << e.what() << "\n";
    return uabt::cli::kExitUsage;
  } catch (const uabt::OutputError& e) {
    // An output path uabt cannot write: a command-line error.
    std::cerr << "uabt: " << e.what() << "\n";
    return uabt::cli::kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "uabt: " << e.what() << "\n";
    return uabt::cli::kExitFail;
  }
  return exit_code;
}
