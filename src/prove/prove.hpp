#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "base/location.hpp"
#include "base/value.hpp"
#include "bt/tree.hpp"
#include "load/mission.hpp"
#include "prove/world_model.hpp"

namespace uabt::prove {

// Per guarantee (ARCHITECTURE §10): proved for every depth, violated with a counterexample, bounded
// (no violation up to the depth explored, nothing proved), vacuous (the world model leaves no
// run, or runs that cannot go on: Result::vacuity says why), or not checked (why in `reason`).
enum class Verdict { proved, violated, bounded, vacuous, unsupported };
const char* verdict_name(Verdict v);

// One tick of a counterexample as its replay saw it: the root's status and the values the
// property reads, plus what the actions did.
struct TickRow {
  std::uint64_t tick = 0;
  std::string root;
  std::vector<std::pair<std::string, Value>> values;
  // "Drill started", "Drill running" (every tick it runs without starting or ending),
  // "Drill failure"
  std::vector<std::string> actions;
};

struct Counterexample {
  std::uint64_t tick = 0;  // the tick at which the property is violated
  std::string scenario;    // ARCHITECTURE §8 scenario JSON that replays it (`uabt run --scenario`)
  std::vector<TickRow> rows;  // ticks 1..tick
  // What the reader needs to know about the runs: "action 'Drive' has no world.json entry,
  // so it may run any number of ticks".
  std::vector<std::string> notes;
};

struct Answer {
  std::string requirement;
  std::string text;  // the requirement as written
  SourceLocation location;
  Verdict verdict = Verdict::unsupported;
  std::string reason;
  std::uint64_t depth = 0;  // ticks explored (bounded), the violation's tick, or for a proof
                            // the explicit depth / the symbolic engine's k
  std::optional<Counterexample> counterexample;
  // The first tick at which the guarantee's trigger (its mode and its condition) holds on
  // some run; 0 when it never does (a proof that says nothing). Not decided when the symbolic
  // engine neither reached the trigger nor proved that no run does within its bounds.
  std::uint64_t first_trigger = 0;
  bool trigger_decided = true;
  bool has_trigger = false;  // the guarantee has a mode or a condition
  // The symbolic engine: proved by IC3/PDR (Z3's Spacer) rather than by k-induction (depth is
  // then 0: no k was needed).
  bool by_pdr = false;
};

// Why a proof would be vacuous (`prove-vacuous`).
struct Vacuity {
  std::string message;
  SourceLocation location;
};

struct Options {
  std::uint64_t depth = 0;             // 0: until every reachable state is explored
  std::size_t max_states = 2'000'000;  // beyond it the answer is bounded
  std::string engine = "auto";         // auto | explicit | symbolic
  // What the symbolic engine may spend, in Z3's resource count (its own tally of solver steps:
  // the same for the same question on any machine, unlike a clock). Depths and frames bound
  // the search's length, not its work: one check or one IC3/PDR frame can take hours. Each
  // check and query gets what is left; when it is spent the search stops, and what it left
  // open is bounded at the depth BMC had checked. The heaviest shipped or tested mission
  // spends about 30 million; Z3 counts 0.5 to 1 million a second on one core.
  std::uint64_t symbolic_resources = 100'000'000;
  // What the explicit-state engine may spend: steps (node ticks, the bytes of every state it
  // compares, and 256 for each transition's fixed cost), and memory (the bytes of the states
  // it keeps). States bound what the search keeps, not its work: a Sequence of 2,000 actions
  // without a world.json contract has 4,000 states, but each tick may end in any of them, and
  // each state of a large tree is large. When either is spent the search stops, and what is
  // not violated is bounded at the depth it reached. Both are deterministic, like the
  // symbolic budget. One core at 2.5 GHz does about 140 million steps a second (so the
  // default is about a minute); the shipped missions spend under a million.
  std::uint64_t explicit_steps = 10'000'000'000;
  std::uint64_t explicit_memory = std::uint64_t{1} << 30;
  // The explicit engine follows once the branches of the monitors' reads that meet again, and
  // skips one whose assumption monitors allow no more than those of a branch it met
  // (AssumptionOrder). Off, every branch is followed: for cross-checking that it loses nothing.
  bool merge_monitor_reads = true;
};

struct Result {
  std::vector<Answer> answers;                // one per guarantee, file order
  std::string engine;                         // explicit | symbolic
  std::uint64_t states = 0, transitions = 0;  // explicit
  std::uint64_t induction_k = 0;              // symbolic: deepest k-induction tried
  std::uint64_t depth = 0;                    // deepest tick explored (symbolic: the BMC depth)
  bool complete = false;                      // every reachable state was explored
  std::optional<Vacuity> vacuity;             // the world leaves no run, or a run stuck
  std::string engine_reason;                  // why `auto` took the symbolic engine
  std::vector<std::string> notes;
  bool passed() const;  // every guarantee proved
};

// A mission prove cannot model (a real variable, an unbounded integer, a port read from the
// blackboard, a world.json effect that writes an undeclared name), or an internal
// disagreement between a counterexample and its replay.
class ProveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Model-checks every guarantee of `mission` on `compiled` (the gate's compiled tree) in the
// world `world` allows. Every counterexample is replayed on the runtime's simulated world
// before it is returned.
// `auto` takes the explicit-state engine whenever it can cut every environment variable into
// finitely many cells (ARCHITECTURE §10.1), else the symbolic one, and says why.
Result prove(const load::Mission& mission, const bt::Document& compiled, const WorldModel& world,
             const Options& options);

// True when the mission states at least one guarantee (a requirement that is neither a
// selection requirement nor about the Environment).
bool has_guarantees(const load::Mission& mission);

}  // namespace uabt::prove
