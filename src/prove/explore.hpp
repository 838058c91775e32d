#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "prove/model.hpp"
#include "prove/prove.hpp"
#include "runtime/engine_state.hpp"

namespace uabt::prove {

// One step of a path: for the first tick, the mission's initial values (an index into the
// product of the relevant mission variables' values), and the choices made within the tick
// (the environment's values as the tick read them, the actions' outcomes), in the order the
// tick made them. A symbolic engine gives the values and outcomes
// themselves instead: `values` per Model::vars (those the tick chooses), `outcomes` per
// ChoiceWorld leaf, one per time the leaf is ticked within the tick (ChoiceWorld::force).
struct Step {
  std::uint64_t env = 0;
  std::vector<std::uint32_t> inner;
  std::vector<runtime::ScriptValue> values;
  std::vector<std::vector<std::int32_t>> outcomes;
  // Per leaf, per time it is ticked, per output port: what it writes if it ends (symbolic).
  std::vector<std::vector<std::vector<runtime::ScriptValue>>> outputs;
};

// What the explicit-state search found for one guarantee.
struct Finding {
  std::size_t property = 0;
  std::uint64_t tick = 0;
  std::vector<Step> path;  // ticks 1..tick
};

struct SearchResult {
  std::vector<std::optional<Finding>> violations;  // per property (guarantees only)
  std::vector<std::uint64_t> first_trigger;  // per property: first tick its trigger holds, 0 never
  std::uint64_t states = 0, transitions = 0, depth = 0;
  bool complete = false;
  // Stopped by Options::explicit_steps or explicit_memory: what was spent, "" when neither.
  std::string budget_spent;
  std::optional<std::string> tick_error;  // the first reachable tick error: "tick N of a run: …"
  std::optional<Vacuity> vacuous;
};

// Why runs stop before they could show anything (`prove-vacuous`), as both engines report it:
// no first state (`initial`, or the assumptions alone), or a run stuck after `tick` (by the
// assumptions, or by the Environment requirement `excluded_by`).
enum class Stuck { initial, assumptions, deadlock };
Vacuity vacuity_of(const Model& model, Stuck kind, std::uint64_t tick = 0,
                   const fretish::Requirement* excluded_by = nullptr);

// Breadth-first search over the model's states (engine state, action progress, property
// monitors), each stored once by its bytes: the first violation found of each guarantee is
// one of the shortest.
SearchResult explore(Model& model, const Options& options);

// "tick N of a run: MESSAGE": a tick that stops with an error, as both engines note it.
std::string tick_error_text(std::uint64_t tick, const std::string& message);

// The error with which the last tick of `path` stops when replayed on the model's own engine
// (tick_error_text); throws ProveError when the replay does not stop there.
std::string replay_tick_error(Model& model, const std::vector<Step>& path);

// Replays `path` on the model's own engine, calling `before_tick(t)` once the values set before
// tick t are on the blackboard (the initial ones; a symbolic path's environment), and
// `after_tick(t, root, chosen)` after the tick and the monitors' reads, with the environment's
// values the tick chose on demand (indices into Model::vars; their values are still on the
// blackboard). The model's ChoiceWorld::recorder is used as it is set.
void replay_path(Model& model, const std::vector<Step>& path,
                 const std::function<void(std::uint64_t)>& before_tick,
                 const std::function<void(std::uint64_t, runtime::NodeStatus,
                                          const std::vector<std::size_t>&)>& after_tick);

}  // namespace uabt::prove
