#pragma once
// Reaching a condition with the prove engines (ARCHITECTURE §13): a state the test campaign wants a
// run to reach is posed as a trap, "the robot shall always satisfy !(condition)" in the scope of
// the guarantee it is about, and proved like any guarantee. A violated trap is reached: its
// counterexample (replayed on the runtime before it is returned) is a scenario that gets
// there, with world.json's action runs. A proved trap is unreachable in world.json's world; a
// bounded one is not decided within the depth explored.
#include <optional>
#include <string>
#include <vector>

#include "fretish/requirement.hpp"
#include "prove/prove.hpp"

namespace uabt::prove {

struct Goal {
  std::string id;                                  // the trap's requirement id
  const fretish::Requirement* scope_of = nullptr;  // its scope is the goal's (nullptr: none)
  fretish::ExprPtr condition;                      // a condition of one tick
  // When set, the goal is `condition` at a tick where scope_of's timing judges its response
  // (next, eventually, within, for, after, until, before: monitor::Shape::judged), not at any
  // tick of the scope.
  bool at_judged_tick = false;
};

struct Reach {
  Verdict verdict = Verdict::unsupported;  // violated: reached; proved: unreachable
  std::string reason;                      // unsupported or vacuous: why
  std::uint64_t depth = 0;                 // the tick reached, or the depth explored
  std::optional<Counterexample> witness;   // reached: the scenario and its tick
  std::string engine;                      // explicit | symbolic
  std::uint64_t states = 0;                // explicit: states explored
};

// The trap of a goal: its scope, component "uabt", "always satisfy !(condition)"; for a goal
// at_judged_tick, the guarantee's own condition, timing and response with `judged` set to the
// condition (no FRETISH sentence says that: its text names the guarantee).
fretish::Requirement trap_requirement(const Goal& goal);

// One answer per goal, in order, from one proof of every trap together (the mission's
// guarantees are left out; its Environment assumptions are kept). Throws ProveError as prove().
std::vector<Reach> reach(const load::Mission& mission, const bt::Document& compiled,
                         const WorldModel& world, const std::vector<Goal>& goals,
                         const Options& options);

}  // namespace uabt::prove
