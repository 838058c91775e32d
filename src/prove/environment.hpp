#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "monitor/expression.hpp"
#include "prove/model.hpp"
#include "runtime/blackboard.hpp"

namespace uabt::prove {

struct Model;

// The environment of one tick, chosen on demand (ARCHITECTURE §10.1): every relevant environment
// variable is pending when the tick starts, and gets its value when the tick, an effect or a
// monitor first reads it; the value then stays for the rest of the tick. Each value offered
// keeps the tick's state assumptions (the domain's `assume`s, and on the first tick
// world.json's `initial`) satisfiable by the variables not chosen yet, so every run the search
// takes can go on with a full state that satisfies them. Values nobody reads are never chosen
// and are not part of the successor state.
class Environment : public runtime::PendingResolver, private monitor::Reader {
 public:
  explicit Environment(Model& model);

  // Takes the mission's values as they are now (the tick's start) and marks the environment
  // pending. `first`: the initial condition applies too.
  void start_tick(bool first);
  // Whether some choice of the environment satisfies the assumptions in this state (when not,
  // the run cannot go on: no tick follows). Cached by the values the assumptions read.
  bool satisfiable();
  // The monitors' reads after the tick, on `frame` (the state after the tick, for the reads that
  // follow): a variable still pending is chosen when an atom reaches it, as a read of the tick
  // would choose it, and its value is written into `frame`. Values no atom's value depends on
  // are never chosen.
  monitor::Reader& monitor_reader(std::vector<monitor::Val>& frame) {
    monitor_frame_ = &frame;
    return *this;
  }
  // After the monitors' reads: the choices cut in the state at hand meet the state after the
  // tick, which the monitors read.
  void monitors_read();
  // Every variable the properties read that is still pending, in a fixed order (a
  // counterexample's table shows them all), then monitors_read().
  void resolve_monitor_reads();
  // Leaves the tick: nothing pending, every environment variable back at its placeholder value.
  void end_tick();

  // The variables (indices into Model::vars) chosen in this tick, in order.
  const std::vector<std::size_t>& chosen() const { return chosen_; }
  // Back to the tick as it was when chosen() had `count` variables (a checkpoint within the
  // tick, taken outside resolve()): the variables chosen since are pending again. The
  // blackboard's values are the caller's to restore.
  void undo(std::size_t count);

  void resolve(runtime::SlotId slot) override;
  // A variable cut in the state at hand (Model::state_cuts) is read again after its choice.
  void watched(runtime::SlotId slot) override;

  // Whether a variable cut in the state at hand was read, after its choice in a tick, with the
  // mission's state changed so that its cell was no longer one truth value for every atom (an
  // effect wrote a variable of the atom in between). The cells of that state are refined, and
  // the search must start over: what it found with the coarser cells may miss runs.
  bool refined() const { return refined_; }
  void clear_refined() { refined_ = false; }

  // Whether the variable's value may still be read once the tick has chosen it: false for a
  // variable only one place of the tree reads (StateVar::read_once) and that neither a monitor
  // nor an assumption reads. Such a value is not part of a mid-tick state.
  bool live(std::size_t var) const { return live_[var]; }
  // Whether the variable's value may still matter once the monitors read from property `from`
  // on (an index into Model::properties): one of them reads it, or an assumption of the domain
  // constrains it.
  bool read_from(std::size_t var, std::size_t from) const { return read_until_[var] > from; }
  // The one variable property `property` reads that is still pending, when nobody reads it
  // after that property, no assumption of the domain constrains it and its values are not cut
  // in the state at hand: its choices (as the monitors read them), else null.
  const std::vector<monitor::Val>* sole_reader_choices(std::size_t property, std::size_t& var);
  // The next choice of `var`'s value offers only the choices whose bit is set in `allowed`, if
  // it is made before the tick ends or is resumed at a checkpoint (undo).
  void offer_only(std::size_t var, std::uint64_t allowed) {
    offer_var_ = var;
    offer_allowed_ = allowed;
  }

 private:
  struct Constraint {
    std::shared_ptr<monitor::CompiledExpression> expr;
    std::vector<std::size_t> vars;  // Model::vars it reads
    bool first_only = false;        // world.json's initial
  };
  bool active(const Constraint& c) const { return first_ || !c.first_only; }
  void reach(int slot) override;
  bool boolean(int slot) const override;
  std::size_t var_of_frame(int slot) const {
    return static_cast<std::size_t>(slot) < var_of_frame_.size()
               ? var_of_frame_[static_cast<std::size_t>(slot)]
               : SIZE_MAX;
  }

  // Whether the constraints connected to `seeds` through unassigned variables can all hold.
  bool component_satisfiable(std::vector<std::size_t> seeds);
  bool holds(Constraint& c);

  // The cells of a variable cut in the state at hand: the breakpoints and one value per cell.
  struct Cells {
    std::set<verify::detail::Fraction> breaks;
    std::vector<runtime::ScriptValue> values;
    std::vector<monitor::Val> vals;
  };
  // The cells of variable `var` in the state at hand, cached per the values its atoms read:
  // `completion` (an unchosen value the assumptions' check enumerates): only the atoms read with
  // the tick's starting state.
  Cells& cells(std::size_t var, bool completion, std::string& key);
  void fill(std::size_t var, Cells& cells);
  // The atom's breakpoint with the mission's values now (or at the tick's start).
  std::optional<verify::detail::Fraction> breakpoint(const StateCut::Atom& atom, bool start) const;
  // Refines the cells the choice `k` of this tick was made from when an atom now cuts its cell.
  void check(std::size_t k);

  Model& m_;
  std::unordered_map<std::string, Cells> cells_;
  struct Watch {
    std::size_t var;
    std::string key;
    runtime::ScriptValue value;
  };
  std::vector<Watch> watches_;                                   // this tick's cut choices
  std::unordered_map<std::size_t, runtime::ScriptValue> start_;  // mission values at the start
  std::vector<std::size_t> start_reads_;  // the mission variables the cuts read
  bool refined_ = false;
  std::vector<Constraint> constraints_;
  std::vector<std::vector<std::size_t>> constraints_of_;  // per variable
  std::vector<std::vector<monitor::Val>> choices_;        // per variable: its values as read
  std::vector<std::size_t> env_;                          // relevant environment variables
  std::vector<std::size_t> mission_vars_;                 // every other variable in the frame
  std::vector<std::uint32_t> options_;                    // resolve()'s scratch
  std::vector<std::size_t> seeds_;
  std::vector<std::size_t> var_of_slot_;
  std::vector<std::size_t> var_of_frame_;  // Model::vars by monitor::Variables slot
  std::vector<monitor::Val>* monitor_frame_ = nullptr;
  std::vector<std::size_t> monitor_reads_;
  std::vector<char> assigned_;
  std::vector<char> live_;
  std::vector<std::size_t> read_until_;  // per variable: 1 + the last property reading it
  std::vector<std::vector<std::size_t>> reads_of_;  // per property: the variables it reads
  std::size_t offer_var_ = SIZE_MAX;
  std::uint64_t offer_allowed_ = ~std::uint64_t{0};
  std::vector<monitor::Val> frame_;
  std::vector<std::size_t> chosen_;
  bool first_ = false;
  std::unordered_map<std::string, bool> cache_;
};

}  // namespace uabt::prove
