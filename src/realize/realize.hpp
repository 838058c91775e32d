#pragma once
// Realizability (ARCHITECTURE §15): can any behavior tree meet the mission's guarantees, in every
// world its assumptions allow? Each tick the environment chooses its inputs first, then the tree
// its outputs; the guarantees and assumptions are FRET's past-time monitors (the ones `uabt
// prove` steps). The mission's guarantees are realizable when the tree has a way to answer
// every input so that no guarantee is ever violated while the assumptions hold: a safety game
// over the monitors' states, solved exactly by a greatest fixpoint over the states reachable,
// per component of requirements that share outputs (FRET's compositional check).
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/diagnostics.hpp"
#include "base/location.hpp"
#include "base/value.hpp"
#include "load/mission.hpp"
#include "prove/world_model.hpp"

namespace uabt::realize {

// Who decides a name the requirements read (README "Realizability").
enum class Role { input, output };

struct Signal {
  std::string name;
  Role role = Role::input;
  std::vector<Value> values;  // one per cell
  std::string why;            // why it has that role: "a domain variable no tree writes"
  // For `<label>.result`: the action ID world.json and scenarios key the node by ("" when the
  // label names leaves of several IDs).
  std::string action;
};

// One input chosen by the environment at one tick of a defeating run.
struct Choice {
  std::uint64_t tick = 0;
  State inputs;  // name, value
};

struct Component {
  std::vector<std::string> requirements;  // ids: its guarantees then its assumptions, file order
  // true, false, or nullopt when it was not decided (`reason` says why).
  std::optional<bool> realizable;
  std::string reason;
  std::uint64_t states = 0;  // monitor states explored
  // Minimal sets of its guarantees that no tree meets together (with its assumptions), each in
  // file order, all of them unless `conflicts_complete` is false.
  std::vector<std::vector<std::string>> conflicts;
  bool conflicts_complete = true;
  // Inputs (how the robot's nodes end among them) that defeat every tree whatever it answers,
  // tick by tick, when a fixed sequence does (the environment may also need to watch the
  // tree's outputs: then none).
  std::vector<Choice> defeating_inputs;
};

struct Result {
  // true: realizable; false: unrealizable; nullopt: not decided (fail closed).
  std::optional<bool> realizable;
  std::vector<Signal> signals;  // inputs then outputs, each by name
  std::vector<Component> components;
  std::vector<std::string> notes;  // what was left out and why
};

struct Options {
  // Limits of one game, past which its component is not decided.
  std::uint64_t max_states = 200'000;
  std::uint64_t max_moves = 1u << 16;         // input valuations times output valuations per state
  std::uint64_t max_transitions = 5'000'000;  // the moves kept, over all states
  // How many guarantees a component may have for every minimal conflict to be listed (subsets
  // are tried by size; 20 at the most); beyond, one minimal conflict is given.
  std::size_t max_conflict_search = 12;
  std::uint64_t max_defeat_depth = 12;  // ticks of a fixed defeating input sequence searched
};

// A requirement that cannot be read as a monitor leaves its component not decided, with why.
// `world` (the mission's world.json) bounds how each action may end.
Result check_realizability(const load::Mission& mission, const prove::WorldModel& world,
                           const Options& options = {});

// The defeating inputs of an unrealizable component as a `uabt run` scenario (ARCHITECTURE §8):
// tick 1's inputs as its initial state, each later change as an event at its tick, and an
// action the inputs always end the same way as a one-tick action with that result. Replayed on
// the mission's tree, a run that keeps going through the last tick violates one of the
// component's first conflict. Nothing when no fixed input sequence defeats every tree.
std::optional<std::string> defeat_scenario(const Result& result, const Component& component);

// The findings of a result: one `requirements-unrealizable` error per minimal conflict (at its
// first requirement, those in `first` listed first: an uplink's), one `realizability-undecided`
// error per component not decided.
std::vector<Finding> findings_of(const load::Mission& mission, const Result& result,
                                 const std::set<std::string>& first = {});

}  // namespace uabt::realize
