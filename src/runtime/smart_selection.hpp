// Internal to the runtime: smart re-selection (EngineOptions::smart_selection).
//
// A ReactiveFallback re-runs every guard on every tick. When the fallback is RUNNING and no
// variable its guards read has changed since the guards were last run, running them again
// gives the same answers, so the fallback may go straight to the branch that runs. "A
// variable its guards read" is what Engine::condition_reads names: the blackboard keys of a
// ScriptCondition, the state entry a world condition answers from. Applies only to a
// ReactiveFallback whose children are ReactiveSequences [guard..., body] where every guard
// node is a Sequence, Fallback, Inverter, a ScriptCondition that assigns nothing, or a world
// leaf that is a condition, none with pre-/post-condition scripts: such a guard completes
// within its tick, changes nothing and answers from its reads only.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "runtime/core.hpp"

namespace uabt::runtime::detail {

using Reads = std::vector<std::pair<std::string, ScriptValue>>;

struct SmartSelector {
  std::vector<NodeId> guard_leaves;  // of every branch, in order
  Reads snapshot;                    // their reads when the guards were last run
  bool valid = false;                // snapshot describes the branch now RUNNING
  std::uint32_t running = 0;         // that branch
};

struct SmartSelection {
  // Per node: index into selectors + 1; 0 unknown; kNot: not a monitored selector.
  std::vector<std::uint32_t> index;
  std::vector<SmartSelector> selectors;
  // Set by the fallback for the one branch whose guards it vouches for in this tick.
  NodeId skip_guards_of = kNoNode;
  // The last monitored branch that failed, failed in its body (not in a guard).
  bool failed_in_body = false;
  static constexpr std::uint32_t kNot = UINT32_MAX;
};

// What a condition leaf reads now (Engine::condition_reads).
Reads condition_reads(Core& core, NodeId node);
// The selector data of a ReactiveFallback, or nullptr when it is not monitored (or the option
// is off).
SmartSelector* smart_selector(Core& core, NodeId fallback);
// Where the fallback's tick starts: the RUNNING branch when its guards' reads are unchanged
// (that branch is then told to skip its guards), else 0.
std::uint32_t smart_start(Core& core, NodeId fallback, SmartSelector& s, bool was_running,
                          Reads& reads_now);
// After the fallback's tick: keeps the snapshot when the tick ended RUNNING in `branch`, with
// every branch before it failed in a guard and no guard read changed during the tick.
void smart_done(Core& core, SmartSelector& s, NodeStatus result, std::uint32_t branch, bool clean,
                Reads&& reads_before);
// For a ReactiveSequence: the child its tick starts at (its last one when the fallback vouched
// for its guards in this tick).
std::uint32_t smart_sequence_start(Core& core, NodeId sequence);

}  // namespace uabt::runtime::detail
