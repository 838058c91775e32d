#pragma once
// Helpers of the hardening suite: the real gate on a temporary mission, and the real CLI.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/diagnostics.hpp"
#include "gate/gate.hpp"
#include "load/mission.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {

// A mission that passes the gate: one adaptable node `navigation`, two guarded alternatives
// and a default. Tests replace one file at a time.
inline std::map<std::string, std::string> good_mission_files() {
  return {
      {"mission.xml", mission_with("    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n"
                                   "      <Stop/>\n    </Sequence>")},
      {"requirements.fret",
       "Req1: In navigation if OnDust Mission shall satisfy selected_alt = on_dust\n"
       "Req2: In navigation if OnRocks Mission shall satisfy selected_alt = on_rocks\n"
       "Safe: In navigation Mission shall satisfy selected_alt = hold_position\n"},
      {"domain.fret", "boolean OnDust, OnRocks\nassume one_terrain: !(OnDust & OnRocks)\n"},
      {"alternatives/navigation/on_dust.xml", alternative_tree("on_dust", "<MoveForward/>")},
      {"alternatives/navigation/on_rocks.xml", alternative_tree("on_rocks", "<MoveBackward/>")},
      {"alternatives/navigation/hold_position.xml", alternative_tree("hold_position")},
  };
}

struct GateRun {
  std::optional<gate::Outcome> outcome;  // nullopt when the directory is not a mission
  std::string load_error;

  const std::vector<Finding>& findings() const { return outcome->report.findings; }
  bool passed() const { return outcome && outcome->passed(); }
  std::string text() const {
    return outcome ? format_text(outcome->report.findings) : "not loaded: " + load_error;
  }
  // The first error finding of `check` (any check when empty) located in `file`.
  const Finding* error_in(const std::string& file, const std::string& check = "") const {
    if (!outcome) return nullptr;
    for (const Finding& f : findings()) {
      if (f.severity == Severity::error && f.location.file == file &&
          (check.empty() || f.check == check))
        return &f;
    }
    return nullptr;
  }
  const Finding* first(const std::string& check) const {
    if (!outcome) return nullptr;
    for (const Finding& f : findings())
      if (f.check == check) return &f;
    return nullptr;
  }
};

inline GateRun run_real_gate(const std::filesystem::path& dir, unsigned timeout_ms = 10000) {
  GateRun run;
  std::optional<load::Mission> mission = load::load_mission(dir, {}, run.load_error);
  if (mission) {
    gate::Options options;
    options.verify.timeout_ms = timeout_ms;
    options.conform.timeout_ms = timeout_ms;
    run.outcome = gate::run_gate(std::move(*mission), options, "test");
  }
  return run;
}

// The gate on the good mission with `path` replaced by `content`.
inline GateRun gate_with(const std::string& path, const std::string& content) {
  auto files = good_mission_files();
  files[path] = content;
  TempMission m(files);
  return run_real_gate(m.dir());
}

// The uabt binary, run through the shell with stdout and stderr captured together.
struct CliRun {
  int exit_code = -1;
  std::string output;
};

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

inline CliRun run_cli(const std::vector<std::string>& args) {
  std::string command = shell_quote(UABT_BINARY);
  for (const auto& a : args) command += " " + shell_quote(a);
  command += " 2>&1";
  CliRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
    run.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return run;
}

}  // namespace uabt::testing
