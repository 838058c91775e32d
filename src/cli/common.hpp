#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "campaign/campaign.hpp"
#include "compile/compile.hpp"
#include "load/mission.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace uabt::cli {

// ARCHITECTURE §7 exit codes.
inline constexpr int kExitPass = 0;
inline constexpr int kExitFail = 1;
inline constexpr int kExitUsage = 2;

const char* tool_version();

// A command line uabt refuses, in its own words; main prints "uabt: " and the message, exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The range of every numeric option (README, "Commands").
inline constexpr std::int64_t kMaxTimeoutMs = 3'600'000;  // --timeout-ms: up to an hour per query
inline constexpr std::int64_t kMaxProveDepth = 10'000;    // prove --depth, in ticks
inline constexpr std::int64_t kMaxTicks = 1'000'000;      // --max-ticks; run --uplink TICK

// A whole number `text` given to `option`, within [min, max]; UsageError otherwise ("--depth
// must be a whole number from 1 to 10000, not -1").
std::int64_t whole_number(const std::string& option, const std::string& text, std::int64_t min,
                          std::int64_t max);
// Adds an option that takes a whole number in [min, max] (checked by whole_number) and passes it
// to `set`; the help names the range.
CLI::Option* add_number_option(CLI::App& cmd, const std::string& name, std::int64_t min,
                               std::int64_t max, const std::string& help,
                               std::function<void(std::int64_t)> set);

// MISSION, the argument every command that reads a mission takes: an existing directory.
void add_mission_argument(CLI::App& cmd, std::string& mission);
// --nodes FILE: the TreeNodesModel of the robot's nodes, read into LoadOptions::nodes_file.
void add_nodes_option(CLI::App& cmd, std::string& nodes);

// Loads a mission, or prints why it cannot, sets `exit_code` to 2 (not a mission directory at
// all) and returns nullopt.
std::optional<load::Mission> load_or_complain(const std::filesystem::path& dir,
                                              const load::LoadOptions& options, int& exit_code);

// Points the findings located in `from` (a displayed name) at `to` instead.
void relocate_findings(std::vector<Finding>& findings, const std::string& from,
                       const std::string& to);

// The compiler's selector style named by --selection (sequence, reactive, optimized).
compile::SelectionStyle selection_style(const std::string& name);
// --selection NAME: the style of every adaptable node; "" (not given): each node's own
// `<Adaptable selection=…>`, else sequence.
void apply_selection(const std::string& name, compile::Options& options);
// The help of every command's --selection.
inline constexpr const char* kSelectionHelp =
    "selector style of every adaptable node (default: its own selection attribute, else "
    "sequence); optimized keeps a node's declared reactive (a decision re-checked every tick)";

// --criterion NAME of `uabt tests`: decision, mcdc, boundary, guarantee, or all of them ("all").
std::set<campaign::Criterion> campaign_criteria(const std::string& name);
// The mission (with `uplinks` merged) for `uabt prove`, `uabt tests` and `uabt coverage`, or
// nullopt after printing why and setting `exit_code`: 2 when it is no mission, 1 when it has
// load errors (a requirement that does not parse, a duration with no meaning in ticks, …),
// which would leave what they answer about something other than what is written.
std::optional<load::Mission> load_without_errors(const std::string& dir,
                                                 const std::vector<std::string>& uplinks,
                                                 int& exit_code);

// Writes `content` to `path` atomically, or to stdout when `path` is empty or "-".
void emit(const std::string& path, const std::string& content);

}  // namespace uabt::cli
