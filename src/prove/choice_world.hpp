#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "fretish/domain.hpp"
#include "prove/world_model.hpp"
#include "runtime/script/program.hpp"
#include "runtime/world.hpp"

namespace uabt::prove {

// Thrown out of a tick by Chooser::choose when the tick reaches a choice point in a state it
// has already explored from: every continuation from there was seen. Not a std::exception, so
// that nothing in the engine takes it for a tick error.
struct ChoicePruned {};

// The nondeterminism inside one tick, resolved one choice at a time. A tick is replayed with a
// forced prefix of choices; choices past it take option 0 and are recorded, so that every
// sequence of choices of a tick can be enumerated like an odometer.
class Chooser {
 public:
  void start(const std::vector<std::uint32_t>& prefix);
  // As start(), for a tick resumed at its choice number `at` (within `prefix`): the choices
  // before it were made as in the last sequence.
  void resume(const std::vector<std::uint32_t>& prefix, std::size_t at);
  // `site` names the choice point (an action, an environment variable) for `seen`: 2 * leaf
  // for an action's outcome (asked before the action changes anything), odd for an
  // environment variable, from 2^31 on for an output port's value.
  // `allowed`: the options the search may take (bit k for option k < 64; options from 64 on
  // are always allowed); a replay takes what its prefix says.
  std::uint32_t choose(std::uint32_t options, std::uint32_t site = 0,
                       std::uint64_t allowed = ~std::uint64_t{0});
  static bool outcome_site(std::uint32_t site) { return site < (1u << 31) && site % 2 == 0; }
  // When set, told of every choice point (its site and its number in the tick) before it
  // chooses.
  std::function<void(std::uint32_t site, std::size_t at)> reached;
  // When set, asked at every choice point past the forced prefix: true when the tick has
  // reached this point before in the same state (in an earlier sequence of choices). Then
  // the sequences below it were all explored already, and choose() throws ChoicePruned;
  // advance() goes on with the next sequence that differs before it.
  std::function<bool(std::uint32_t site)> seen;
  const std::vector<std::uint32_t>& taken() const { return taken_; }
  // Whether this sequence has made the choice its prefix changes (or a later one): every point
  // it reaches from there on, no earlier sequence reached with the same choices.
  bool past_prefix() const { return pos_ >= forced_; }
  // How many choices this sequence made where more than one option was allowed.
  std::size_t branchings() const { return branchings_; }
  // The next sequence after the one just taken, false when every one was.
  bool advance(std::vector<std::uint32_t>& prefix) const;

 private:
  std::vector<std::uint32_t> taken_, arity_;
  std::vector<std::uint64_t> allowed_;
  std::size_t pos_ = 0, forced_ = 0, branchings_ = 0;
};

// The state key a robot leaf answers from or is contracted by: `Name(port=value,…)` with its
// literal ports, sorted by name; a leaf with a `{key}` port is keyed by its name alone (what
// the simulated world falls back to once the qualified key is not set).
std::string leaf_state_key(const std::string& name, std::span<const runtime::LeafPort> ports);

// What an action did, for building a counterexample. An action's duration is counted in its
// own ticks, as the simulated world counts a scenario's `ticks`: a tick of the engine may tick
// it twice (a wake-up re-tick) or not at all (a parent waiting on another child).
class ActionRecorder {
 public:
  virtual ~ActionRecorder() = default;
  // Every tick of the action; `first`: the first one of a start.
  virtual void ticked(std::uint32_t leaf, bool first) = 0;
  virtual void ended(std::uint32_t leaf, runtime::NodeStatus result) = 0;
  virtual void halted(std::uint32_t leaf) = 0;
};

// The world `uabt prove` explores: conditions read the state as the simulated world does
// (SimWorld's keys: `Name(port=value)` when that is a state variable, else `Name`); actions
// follow their world.json contract, choosing on every tick between running on and ending with
// each allowed result; an action without a contract may return RUNNING, SUCCESS or FAILURE on
// any tick and changes nothing.
class ChoiceWorld : public runtime::World {
 public:
  // `domain` (optional) is what effects must keep each variable within.
  ChoiceWorld(const WorldModel& model, std::vector<bt::NodeModel> node_models,
              std::set<std::string, std::less<>> state_names,
              const fretish::Domain* domain = nullptr);

  std::uint32_t bind_leaf(const runtime::LeafBinding& leaf) override;
  runtime::NodeStatus tick_leaf(const runtime::LeafContext& leaf) override;
  void halt_leaf(const runtime::LeafContext& leaf) override;

  Chooser chooser;
  ActionRecorder* recorder = nullptr;
  // From now on, until called again, the outcomes of the actions instead of the chooser's:
  // per leaf, one per time it is ticked (-1 runs on, k >= 0 ends with its contract's k-th
  // result), as a symbolic engine's counterexample gives them. nullptr: the chooser again.
  // `outputs` (per leaf, per time it is ticked, per output port): what an ending action writes.
  void force(const std::vector<std::vector<std::int32_t>>* outcomes,
             const std::vector<std::vector<std::vector<runtime::ScriptValue>>>* outputs = nullptr) {
    forced_ = outcomes;
    forced_outputs_ = outputs;
    forced_next_.assign(leaves_.size(), 0);
  }

  struct Leaf {
    runtime::NodeId node = runtime::kNoNode;
    std::string name, label;  // label: the condition's key, the action's contract or name
    bool condition = false;
    runtime::SlotId key = runtime::kNoSlot;
    const ActionContract* contract = nullptr;
    std::optional<runtime::script::Program> on_success, on_failure;
    std::vector<std::string> writes;
    // Its output ports `{key}`: what it writes when it ends, the contract's value or one of
    // output_values[slot] (chosen).
    struct Output {
      std::string port;
      runtime::SlotId slot = runtime::kNoSlot;
      const runtime::ScriptValue* fixed = nullptr;
    };
    std::vector<Output> outputs;
    std::vector<runtime::SlotId> inputs;  // the entries its input ports `{key}` read
  };
  // Per entry an output port writes without a value from world.json: the values it may get.
  std::map<runtime::SlotId, std::vector<runtime::ScriptValue>> output_values;
  const std::vector<Leaf>& leaves() const { return leaves_; }
  // Progress of every action (ticks it has run in its current start; for an action without
  // contract only whether it runs, as nothing else about it matters; -1 - k while it ends with
  // its k-th result, its outputs and effect running): the world's state.
  const std::vector<std::int64_t>& elapsed() const { return elapsed_; }
  void set_elapsed(const std::vector<std::int64_t>& e) { elapsed_ = e; }
  // The longest run the explicit engine can explore (a breadth-first search holds at least one
  // state per tick of depth, so its state limit bounds it). An action whose contract allows
  // more ticks than that is never made to end by its maximum within an explored run, so the
  // ticks it runs past its minimum look alike: its count stops there, and `"ticks": [1,
  // 9223372036854775807]` costs two states instead of one per tick.
  void set_horizon(std::uint64_t ticks) { horizon_ = ticks; }

 private:
  const WorldModel& model_;
  std::vector<bt::NodeModel> models_;
  std::set<std::string, std::less<>> state_names_;
  const fretish::Domain* domain_ = nullptr;
  std::vector<Leaf> leaves_;
  std::vector<std::int64_t> elapsed_;
  std::uint64_t horizon_ = UINT64_MAX;
  const std::vector<std::vector<std::int32_t>>* forced_ = nullptr;
  const std::vector<std::vector<std::vector<runtime::ScriptValue>>>* forced_outputs_ = nullptr;
  std::vector<std::size_t> forced_next_;
};

}  // namespace uabt::prove
