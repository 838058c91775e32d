#pragma once
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace uabt::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;  // what the command wrote to the pipe
};

// Runs a shell command and collects its standard output and exit code.
inline CliRun run_shell(const std::string& command) {
  CliRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) run.out += buffer.data();
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// Runs the real binary in `dir` with `args` (shell syntax), standard error included.
inline CliRun run_uabt_in(const std::string& dir, const std::string& args) {
  return run_shell("cd '" + dir + "' && '" + UABT_BINARY + "' " + args + " 2>&1");
}

}  // namespace uabt::testing
