#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "base/finding.hpp"

namespace uabt {

// How findings are printed for a person at a terminal or in a log.
struct TextOptions {
  // The mission directory as the user can open it from the directory uabt runs in
  // ("missions/msl_curiosity/", "drone_bad/"; "" for the current directory), put in front of
  // the mission-relative file of each finding so that editors and CI problem matchers open it
  // (see path_prefix_for).
  std::string path_prefix;
  // Shows the source line with a caret under the column (GCC style) after each finding that
  // has a line, read from `source_dir` / file.
  bool show_source = false;
  std::filesystem::path source_dir;
};

// GCC-style diagnostics: `file:line:col: severity: message [check]`, then notes and the
// witness as `note:` lines. Locations without a line print as `file: severity: …`.
std::string format_text(const std::vector<Finding>& findings, const TextOptions& options = {});

// "OnDust=true, OnRocks=true"; with `equals` " = ", "OnDust = true, OnRocks = true".
std::string format_state(const State& state, std::string_view equals = "=");

// The prefix that makes a file relative to `mission_dir` openable from the current directory:
// the directory as given when it is relative, else relative to the current directory when it
// lies inside it, else absolute; with a trailing '/', or "" for the current directory itself.
std::string path_prefix_for(const std::filesystem::path& mission_dir);

// `file` (relative to the mission directory, or absolute) as the user opens it: prefix + file,
// lexically normalised ("missions/m/../out/c.xml" → "missions/out/c.xml"); absolute when it
// climbs higher than the mission's own path does ("/tmp/pkg/domain.fret", not "../../tmp/…").
std::string user_path(const std::string& file, const std::string& prefix);

// A message with every place "file.ext:line:col" in it (a file relative to the mission, at the
// start or after a space, a parenthesis or a quote) as user_path names that file; any other
// text as it is.
std::string with_user_path(const std::string& message, const std::string& prefix);

}  // namespace uabt
