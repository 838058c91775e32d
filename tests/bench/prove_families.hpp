#pragma once
// The model-checking benchmark families of the peers (BehaVerify, MoVe4BT), generated as real
// mission directories (mission.xml, domain.fret, requirements.fret, world.json) for
// `uabt prove`.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace uabt::bench {

struct FamilyMission {
  std::filesystem::path dir;
  int tree_nodes = 0;  // BT nodes of the compiled tree (its selection trees and alternatives too)
  // The verdict each guarantee must get, and the tick of a violated one's counterexample.
  std::map<std::string, std::string> verdicts;
  std::map<std::string, std::uint64_t> violation_ticks;
};

// BehaVerify's binary tree: a complete binary tree of `fallback_nodes` Fallback nodes and
// leaves (odd, >= 3) under a KeepRunningUntilFailure root. In left-to-right order the leaves
// alternate between a check `vv_j >= K` (a ScriptCondition) and an action that increments or
// decrements one of `counters` counters vv_j (`vv = vv < 8 ? vv + 1 : vv`), each ending in one tick
// with success or failure, nondeterministically. The counters start at 0 and range over [0, 8].
// Guarantees: `Bounded` (always vv_0 <= 8: proved) and `BelowMax` (always vv_0 < 8: violated at
// tick 8, when the first action has incremented vv_0 eight times).
FamilyMission generate_binary_tree(const std::filesystem::path& dir, int fallback_nodes,
                                   int counters = 3);

// A checklist: a Sequence of N Fallback[IsOk_i, Repair_i] and then Work, under ForceSuccess and
// KeepRunningUntilFailure (3 N + 4 nodes). Repair_i takes 2 or 3 ticks, succeeds (IsOk_i =
// true) or fails (the checklist starts over); Work takes 2 ticks. Every IsOk_i starts false.
// Guarantees: `Ready` (always Work.running -> every IsOk_i: proved) and `NeverWorks` (always
// !Work.running: violated at tick N + 1, when the last repair ends and Work starts).
FamilyMission generate_checklist(const std::filesystem::path& dir, int checks);

// A pre-flight checklist over N sensor flags Ok_1 .. Ok_N: booleans of domain.fret, conditions
// of nodes.xml, written by no action, so the environment may set each of them anew before every
// tick. A Sequence of N Fallback[Ok_i, Repair_i] and then Launch, under ForceSuccess and
// KeepRunningUntilFailure (3 N + 4 nodes). Repair_i takes 1 or 2 ticks and succeeds without
// touching Ok_i; Launch takes 2 ticks and succeeds. Every initial state is allowed. Guarantees:
// - `RepairOnlyWhenNeeded`: always Repair_N.running -> !Ok_N. Proved. Repair_N returns RUNNING
//   only in the first tick of a 2-tick repair (in its second tick, or in the only tick of a
//   1-tick one, it returns SUCCESS). A Fallback resumes a running child without its earlier
//   children, so a repair in its first tick was reached through Ok_N in that same tick, and
//   Ok_N failed. Values are set before a tick and stay for it, and no action writes Ok_N, so
//   Ok_N is still false after the tick, when the property reads it. (With 3-tick repairs the
//   Fallback would resume Repair_N in a second RUNNING tick without reading Ok_N, which the
//   environment may have set meanwhile: violated at tick 2.)
// - `LaunchOnlyWhenOk`: always Launch.running -> Ok_1. Violated at tick 1: Ok_1 is false, a
//   1-tick Repair_1 succeeds without setting it, every other flag is true (or its repair also
//   takes one tick), so Launch starts in tick 1 and returns RUNNING with Ok_1 false. No run can
//   violate it earlier than the first tick.
FamilyMission generate_preflight(const std::filesystem::path& dir, int flags);

// A checklist that checks each flag again after its fix: N sensor flags Check1 .. CheckN
// (booleans of domain.fret, conditions of nodes.xml, written by no action, so the environment may
// set each of them anew before every tick) and a Sequence of N Fallback[CheckK, Sequence[FixK,
// CheckK]] and then Launch, under KeepRunningUntilFailure (5 N + 3 nodes, N >= 2). FixK takes 1 or
// 2 ticks and succeeds or fails without touching CheckK; Launch takes 3 ticks and succeeds.
// Guarantee `Ready`: always (Launch.running | Launch.success) -> (Check1 & … & CheckN).
// - Without `kept`: violated at tick 2 (N >= 2). In tick 1 Check1 holds, Check2 fails and a
//   2-tick Fix2 runs; in tick 2 the Sequence resumes at Fix2 without reading Check1 again: Fix2
//   succeeds, Check2 .. CheckN are read true and Launch starts, while the environment has
//   cleared Check1. Not at tick 1: every flag is read true in the tick Launch starts in.
// - With `kept`, the assumptions `KeepK: upon CheckK Environment shall always satisfy CheckK`
//   (a flag once set stays set): proved. Every flag was read true in the tick Launch started
//   or earlier, so each is still set while Launch runs or succeeds.
FamilyMission generate_recheck(const std::filesystem::path& dir, int flags, bool kept = false);

// A lunar sampling sortie (one size): two real environment variables `slope in [0, 30]`
// (degrees) and `battery in [0, 100]` (percent), an enum `illumination in {sun, shadow, night}`,
// and the mission's own booleans AtSite and HasSample (conditions, written by actions only), a
// nodes.xml that registers every leaf. The tree:
//   KeepRunningUntilFailure > ForceSuccess > Sequence sortie [
//     Fallback reach_site [AtSite, Adaptable traverse (selection="reactive")],
//     Fallback collect [HasSample, Adaptable sample (sequence selection)],
//     StowSample ]
// traverse, in priority order (a partition of the domain, no default):
//   Direct   battery >= 40 & slope < 10 & illumination = sun             -> drive_direct
//   Cautious battery >= 40 & slope < 25 & (slope >= 10 | illumination != sun) -> drive_cautious
//   Hold     battery < 40 | slope >= 25                                    -> hold_position
// sample (a partition too):
//   Core     battery >= 60 & illumination != night                          -> drill_core
//   Scoop    battery < 60 | illumination = night                            -> scoop_regolith
// drive_direct = DriveDirect (1-2 ticks, AtSite = true); drive_cautious = Sequence[ScanHazards
// (1 tick), DriveSlow (2-3 ticks, AtSite = true)]; hold_position = HoldPosition (1-2 ticks,
// fails: the sortie starts over); drill_core = Sequence[DeployArm (1 tick), DrillCore (2-3
// ticks, success with HasSample = true or failure)]; scoop_regolith = Sequence[DeployArm,
// ScoopRegolith (1-2 ticks, HasSample = true)]; StowSample (1 tick) ends the sortie with
// AtSite = HasSample = false (on to the next site). Initially !AtSite & !HasSample; the
// environment sets slope, battery and illumination freely before every tick.
// Guarantees (a property reads a value after the tick, which is the value the tree read in it:
// values are set before a tick and no action writes these three):
// - `DirectOnFlat`: always traverse.selected = drive_direct -> slope < 10 & illumination = sun.
//   Proved: the selection is reactive, so in every tick that ticks traverse the ReactiveFallback
//   starts again at the Direct branch and re-checks its guard; drive_direct is the last
//   alternative ticked only when that guard held in this tick (DriveDirect never fails, so
//   nothing falls through after it). In the sequence style a drive started in tick 1 runs on
//   unchecked in tick 2: violated at tick 2.
// - `HoldWhenSteep`: always traverse & slope >= 25 -> traverse.selected = hold_position.
//   Proved: in a tick that ticks traverse with slope >= 25 the Direct and Cautious guards fail
//   (they need slope < 10, slope < 25) and the Hold guard holds, so the last alternative ticked
//   is hold_position, whatever it returns. (Violated at tick 2 in the sequence style, as above.)
// - `SampleAtSite`: always DrillCore.running | ScoopRegolith.running -> AtSite. Proved: collect
//   is ticked only after reach_site succeeded in the same tick (AtSite read true, or a drive
//   succeeded and set it; hold_position only fails), or when the sortie resumes a running
//   collect; only StowSample clears AtSite, and it ends the sortie, which then starts again at
//   reach_site.
// - `DrillOnCharge`: always DrillCore.running -> battery >= 60. Violated at tick 2: in tick 1
//   (battery >= 60, sun, slope < 10) a 1-tick DriveDirect reaches the site and the sample
//   selection starts a 3-tick DrillCore; the selection is not reactive, so in tick 2 the
//   sortie resumes the running drill without re-checking the guard while the environment has
//   dropped the battery below 60. Not at tick 1: then the Core guard read battery >= 60 in that
//   very tick.
FamilyMission generate_lunar(const std::filesystem::path& dir);

// The lunar sortie with a reserve (lunar_reserve): the mission's own `integer reserve in [20,
// 60]`, 20 at first, which each sample raises by 10 (DrillCore's and ScoopRegolith's
// on_success); every battery threshold stands above it (40 becomes reserve + 20, 60 reserve +
// 40), so the guards and DrillOnCharge compare the environment's battery with the mission's
// state (`battery >= reserve + 40`). Same verdicts as the lunar sortie, DrillOnCharge violated
// at tick 2 for the same reason.
FamilyMission generate_lunar_reserve(const std::filesystem::path& dir);

// A selection over a wide vocabulary, for the whole gate: `KeepRunningUntilFailure >
// Adaptable site (selection="reactive")`, where `dig` (a Dig action, 1 or 2 ticks, success) is
// selected by one guard and `hold` (Hold, 1 tick, success) is the default. Guarantees:
// - `DigOnlyWhereSelected`: always Dig.running -> <what the guard says, shortly>. Proved: the
//   reactive selection
//   checks the guard in every tick Dig runs in, and the environment's values stay for the
//   tick.
// The gate passes.
//
// The guard `depth = 0 | depth = 1 | … | depth = N-1` over `integer depth in [0, 100000]`
// (the scale checklist's 60,000-disjunct row); the guarantee reads `depth < N`.
FamilyMission generate_disjunct_site(const std::filesystem::path& dir, int disjuncts);
// The guard `terrain = sand` over `enum terrain in {sand, rocks, unknown, v0, …}` of N values
// (the scale checklist's 4,096-value row: values no atom names are one cell).
FamilyMission generate_enum_site(const std::filesystem::path& dir, int values);

}  // namespace uabt::bench
