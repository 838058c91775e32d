#pragma once
#include <CLI/CLI.hpp>

namespace uabt::cli {

// Each subcommand registers its options and the action to run; the action returns the exit
// code. Registration keeps main() free of per-command details.
void register_compile(CLI::App& app, int& exit_code);
void register_explain(CLI::App& app, int& exit_code);
void register_checks(CLI::App& app, int& exit_code);
void register_verify(CLI::App& app, int& exit_code);
void register_gate(CLI::App& app, int& exit_code);
void register_conform(CLI::App& app, int& exit_code);
void register_report(CLI::App& app, int& exit_code);
void register_diff(CLI::App& app, int& exit_code);
void register_run(CLI::App& app, int& exit_code);
void register_prove(CLI::App& app, int& exit_code);
void register_monitor(CLI::App& app, int& exit_code);
void register_schema(CLI::App& app, int& exit_code);
void register_tests(CLI::App& app, int& exit_code);
void register_coverage(CLI::App& app, int& exit_code);
void register_realizable(CLI::App& app, int& exit_code);

}  // namespace uabt::cli
