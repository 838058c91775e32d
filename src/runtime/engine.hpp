#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/location.hpp"
#include "bt/tree.hpp"
#include "runtime/blackboard.hpp"
#include "runtime/status.hpp"

namespace uabt::runtime {

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = UINT32_MAX;

class World;
struct EngineState;
namespace detail {
struct Core;
}

// A tree BehaviorTree.CPP would refuse to load: unknown SubTree ID, recursive SubTrees, an
// unsupported built-in node, a literal port that does not convert, a script that does not
// parse. The message starts with "file:line:col: ".
class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a runtime node is, for observers, logs and the manager. Stable for the engine's life:
// a node swapped out keeps its id and info, with `alive` false.
struct NodeInfo {
  std::string tag;          // element name as written: Sequence, MoveForward, Action (explicit)
  std::string kind;         // registered name: the ID of <Action ID="X">, otherwise the tag
  std::string name;         // the `name` attribute, "" if none
  std::string tree_id;      // the <BehaviorTree> whose definition holds this node
  NodeId parent = kNoNode;  // a tree's root has the SubTree node calling it as parent
  std::uint32_t child_index = 0;  // position among the parent's children
  std::uint32_t instance = 0;     // tree instance: 0 is the main tree, then one per SubTree call
  SourceLocation location;
  const bt::Node* element = nullptr;  // the XML element (kept alive by the engine)
  bool alive = true;

  // "mission.xml:12:7: MoveTo 'approach'": where a message about the node points.
  std::string place() const {
    return place_text(location) + ": " + kind + (name.empty() ? "" : " '" + name + "'");
  }
};

// A failure BT.CPP raises as an exception while ticking (undefined script key, type error,
// bad port, wrong child count, a skipped IfThenElse/WhileDoElse condition). As in BT.CPP the
// tick stops there: Engine::tick() throws a TickException carrying it, nothing is halted or
// reset, and a later tick resumes where this one stopped.
struct TickError {
  std::uint64_t tick = 0;
  NodeId node = kNoNode;
  std::string message;  // "file:line:col: Kind 'name': what went wrong"
  std::string path;     // the node's instance path (Engine::instance_path)
  std::string script;   // the script that failed, "" when the error is not a script's
};

class TickException : public std::runtime_error {
 public:
  explicit TickException(TickError e) : std::runtime_error(e.message), error(std::move(e)) {}
  TickError error;
};

struct Stats {
  std::uint64_t root_ticks = 0;      // Engine::tick() calls
  std::uint64_t node_ticks = 0;      // every node tick, the root's included
  std::uint64_t swaps = 0;           // tree instances rebuilt by replace_tree
  std::uint64_t errors = 0;          // TickErrors, recorded or not
  std::uint64_t wakeup_reticks = 0;  // extra root ticks the wake-up signal asked for
};

// Told about every status change, in the order BT.CPP's StatusChangeLogger would see them
// (a control goes IDLE→RUNNING when ticked, completed children are reset to IDLE by their
// parent, halted nodes go to IDLE, a completed root goes back to IDLE at the end of the tick).
// Must not modify the engine from the callbacks.
class Observer {
 public:
  virtual ~Observer() = default;
  virtual void on_status_change(NodeId node, NodeStatus previous, NodeStatus next) = 0;
  // After every tick of a node, with what it returned to its parent (SKIPPED included), also
  // when its status did not change. Wake-up re-ticks are ticks like any other.
  virtual void on_node_ticked(NodeId /*node*/, NodeStatus /*result*/) {}
};

// What replace_tree does with an instance of the tree that is RUNNING.
enum class SwapPolicy {
  refuse_if_running,  // change nothing (not even the definition) if any instance runs
  halt_then_swap,     // halt the running instance (its actions get halt), then rebuild it
  defer_until_idle,   // rebuild it after the first tick at whose end it is not RUNNING
};

struct SwapResult {
  enum class Outcome { swapped, deferred, refused };
  Outcome outcome = Outcome::swapped;
  std::size_t swapped = 0;   // instances rebuilt now
  std::size_t halted = 0;    // of those, RUNNING ones halted first
  std::size_t deferred = 0;  // RUNNING instances waiting to be rebuilt
};

struct EngineOptions {
  // Bound on the wake-up loop of one tick (BT.CPP's tickOnce re-ticks the root while a node
  // asked for it, without limit). A tree that keeps asking, e.g. Repeat num_cycles="-1" over
  // a child that completes at once, would never return from BT.CPP's tickOnce(); uabt stops
  // after this many re-ticks with a TickException naming the node that asked last. Trees that
  // settle within the bound tick exactly as in BT.CPP.
  std::uint32_t max_wakeup_reticks = 100000;
  // SubTree calls nested deeper than this are refused at load (ticking recurses).
  int max_subtree_nesting = 64;
  // TickErrors kept; later ones are only counted (Stats::errors).
  std::size_t max_recorded_errors = 1000;
  // Not BT.CPP: a RUNNING ReactiveFallback of guarded ReactiveSequences (the compiler's
  // reactive selection) does not re-run its guards while none of the variables they read
  // (condition_reads) has changed; it goes straight to the running branch. Same selections,
  // results and actions as BT.CPP, fewer condition ticks and status changes. Assumes a
  // condition answers from its reads only (smart_selection.hpp).
  bool smart_selection = false;
};

// BehaviorTree.CPP 4.x tick engine over a bt::Document (ARCHITECTURE §8). Nodes live in flat
// vectors and are addressed by NodeId; blackboard keys and scripts are resolved and compiled
// once at instantiation, so a tick does no string lookups and no allocations.
// Leaves that are not built in are delegated to a World.
class Engine {
 public:
  // Instantiates the document's main tree (main_tree_to_execute, or its only tree), or the
  // tree `main_tree` when given. `world` must outlive the engine. Throws LoadError.
  static Engine build(const bt::Document& doc, World& world, EngineOptions options = {});
  static Engine build(const bt::Document& doc, const std::string& main_tree, World& world,
                      EngineOptions options = {});

  Engine(Engine&&) noexcept;
  Engine& operator=(Engine&&) noexcept;
  ~Engine();

  // One tick (BT.CPP's Tree::tickOnce): the root is ticked, then ticked again at once while
  // it is RUNNING and a node emitted the wake-up signal (Repeat, RetryUntilSuccessful,
  // SequenceWithMemory after a child that completed within the tick). A root that completes
  // is reset to IDLE. Deferred swaps whose instance is no longer RUNNING are applied at the
  // end of the tick. Throws TickException where BT.CPP's tick throws (see TickError).
  NodeStatus tick();
  // Goes on with the tick a TickTrail (engine_state.hpp) restored to a checkpoint: the root
  // is ticked again, without counting a new tick, and goes down its running nodes to the
  // leaf the checkpoint stopped at, which is ticked again; the tick then ends as tick() ends.
  // Only where TickTrail::resumable() said so, which is where BT.CPP's nodes go on with the
  // very child they were ticking.
  NodeStatus resume_tick();
  // Halts the whole tree as BT.CPP's Tree::haltTree: the root, then every node (each one's
  // _onHalted runs; robot leaves hear halt only while RUNNING); every node is IDLE afterwards.
  // An _onHalted script that fails throws TickException, as in BT.CPP.
  void halt();

  NodeId root() const;
  NodeStatus status() const;       // the root's (IDLE again once a tick completed it)
  NodeStatus last_result() const;  // what the last tick() returned (IDLE before the first)
  NodeStatus status(NodeId node) const;
  std::size_t node_count() const;  // ids in use, swapped-out nodes included
  const NodeInfo& info(NodeId node) const;
  std::span<const NodeId> children(NodeId node) const;
  // "navigation/Fallback/Sequence[1]/SubTree[1]": the node's place in its own tree, in the
  // compiler's trace-map notation (the root without index, then Tag[child index]).
  std::string tree_path(NodeId node) const;
  // The place in the running tree: SubTree calls joined with their tree paths,
  // "MainTree/Sequence/Fallback[0]/SubTree[1]/navigation/Fallback/...".
  std::string instance_path(NodeId node) const;
  NodeId find_path(std::string_view instance_path) const;         // kNoNode if none (alive only)
  std::vector<NodeId> find_by_name(std::string_view name) const;  // `name` attribute, alive
  // SubTree nodes (alive) that call `tree_id`; the main tree has none.
  std::vector<NodeId> subtree_calls(std::string_view tree_id) const;

  // What a condition read in its last tick: a ScriptCondition's keys, a robot condition's
  // state entry (World::condition_reads), with their values now (empty: not set). Empty for
  // every other node.
  std::vector<std::pair<std::string, ScriptValue>> condition_reads(NodeId node) const;

  void add_observer(Observer* observer);
  void remove_observer(Observer* observer);

  Blackboard& blackboard();
  const Blackboard& blackboard() const;
  // The blackboard scope a node reads and writes (its tree instance's).
  ScopeId scope(NodeId node) const;

  std::uint64_t tick_count() const;  // root ticks so far
  const Stats& stats() const;
  const std::vector<TickError>& errors() const;

  // Puts the engine back as Engine::build left it, over `world`: the node statuses, counters
  // and blackboard of `built` (EngineState::save right after build; values written since go
  // back to empty), no errors, no statistics, and every robot leaf bound again to `world` in
  // the order build bound them. What follows runs exactly as on a freshly built engine, without
  // instantiating the tree again. Observers stay. Not after a hot swap.
  void reset(World& world, const EngineState& built);

  // Hot swap (ARCHITECTURE §8), between two ticks.
  // Registers or replaces the definition of `def.id` for later instantiations only.
  void define_tree(bt::TreeDef def);
  bool has_tree(std::string_view tree_id) const;
  // Replaces tree `tree_id` (main tree or SubTree) by `def` in every instance, each rebuilt
  // on its own blackboard scope (entries survive). Nodes outside the instances keep their
  // state and are not halted. `def` is validated first: on LoadError nothing changes.
  SwapResult replace_tree(const std::string& tree_id, bt::TreeDef def, SwapPolicy policy);
  std::size_t pending_swaps() const;
  void apply_pending_swaps();

 private:
  friend struct EngineState;  // saves and restores the state between ticks (engine_state.hpp)
  friend class TickTrail;     // and within a tick
  explicit Engine(std::unique_ptr<detail::Core> core);
  NodeStatus tick_root();  // the root ticked, and the end of the tick: tick(), resume_tick()
  NodeStatus wake_up_loop();
  std::unique_ptr<detail::Core> core_;
};

// An observer registered for one scope: removed however the scope ends, so that an engine kept
// for the next run never calls an observer that is gone.
class Observing {
 public:
  Observing(Engine& engine, Observer& observer) : engine_(engine), observer_(observer) {
    engine_.add_observer(&observer_);
  }
  ~Observing() { engine_.remove_observer(&observer_); }
  Observing(const Observing&) = delete;
  Observing& operator=(const Observing&) = delete;

 private:
  Engine& engine_;
  Observer& observer_;
};

}  // namespace uabt::runtime
