#pragma once
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "campaign/campaign.hpp"
#include "compile/compile.hpp"
#include "load/mission.hpp"

namespace uabt::cli {

// DESIGN §7 exit codes.
inline constexpr int kExitPass = 0;
inline constexpr int kExitFail = 1;
inline constexpr int kExitUsage = 2;

const char* tool_version();

// Loads a mission, or prints why it cannot and returns nullopt (exit code 2: not a mission
// directory at all).
std::optional<load::Mission> load_or_complain(const std::filesystem::path& dir,
                                              const load::LoadOptions& options);

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
