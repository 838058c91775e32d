#pragma once
// Guarantee targets of a campaign (ARCHITECTURE §13): FLIP-style obligations of every guarantee
// with a trigger, solved by the prove engines over world.json and checked by the runtime monitor.
#include <map>
#include <optional>
#include <set>
#include <string>

#include "campaign/campaign.hpp"
#include "prove/reach.hpp"

namespace uabt::campaign {

// world.json's model, kept in `storage`, when the mission directory holds one; else nullptr
// (the campaign then plans no guarantee targets and its scenarios carry no action contracts).
const prove::WorldModel* load_world(const load::Mission& mission,
                                    std::optional<prove::WorldModel>& storage);

// The goals of the guarantee targets, in target order (a goal's id is its target's id): per
// guarantee with a trigger, the trigger firing, then each atom of its condition and of its
// response true and false, deciding it.
std::vector<prove::Goal> guarantee_goals(const load::Mission& mission);

// The guarantee targets as the campaign plans them (when options.criteria has
// Criterion::guarantee): their verdicts over options.world, the scenarios that reach them (each
// replayed with the runtime's monitor, chosen by greedy set cover; purposes index `targets`),
// notes when none are planned, and the traps the monitor watches, one per target in order.
struct GuaranteePlan {
  std::vector<Target> targets;
  std::vector<bool> covered;
  std::vector<Scenario> scenarios;
  std::vector<std::string> notes;
  load::Mission traps;
};
GuaranteePlan plan_guarantee_targets(const load::Mission& mission, const Replayer& replayer,
                                     const Options& options);

// The targets (indices into plan.targets) a scenario reaches, replayed with the runtime's
// monitor watching every trap, as the campaign checks its own scenarios.
std::set<std::size_t> guarantees_reached(const GuaranteePlan& plan, const Replayer& replayer,
                                         const std::string& json, const std::string& file);
// The targets a monitor trace reaches, by `uabt monitor`'s check of the traps over it; a trap
// the trace cannot be read for ("the trace lacks OnMud") is put in `not_judged` with the reason.
std::set<std::size_t> guarantees_reached(const GuaranteePlan& plan, const std::string& content,
                                         const std::string& file,
                                         std::map<std::size_t, std::string>& not_judged);

// Adds the guarantee targets (when options.criteria has Criterion::guarantee) to `c`: their
// verdicts, and the scenarios that reach them, each replayed with the runtime's monitor and
// chosen by greedy set cover; placed before the behaviour changes' scenarios.
void add_guarantee_targets(const load::Mission& mission, const Replayer& replayer,
                           const Options& options, Campaign& c);

}  // namespace uabt::campaign
