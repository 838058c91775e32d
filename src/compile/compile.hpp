#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"
#include "compile/decision.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "load/mission.hpp"

namespace uabt::compile {

// sequence: Fig. 4; reactive: Fig. 4 with reactive controls; optimized: a decision structure
// that selects the same alternative while ticking fewer conditions (optimized_selection.cpp).
enum class SelectionStyle { sequence, reactive, optimized };

struct Options {
  // The style of adaptable nodes that declare none (`<Adaptable selection=…>`); with
  // `selection_forced` (an explicit --selection), of every node.
  SelectionStyle selection = SelectionStyle::sequence;
  bool selection_forced = false;
  int bt_format = 4;  // 3: refuse guards that need ScriptCondition
};

// Where a generated node came from: requirement, atom and source line (ARCHITECTURE §4).
struct TraceEntry {
  std::string tree_id;
  std::string node_path;    // e.g. navigation/Fallback[0]/Sequence[1]/Inverter[0]/OnDust[0]
  std::string requirement;  // requirement id ("" for the selector itself)
  std::string atom;         // FRETISH text of the atom or operator it implements
  SourceLocation source;
};

// What one adaptable node's selection costs, in condition nodes ticked per selection.
struct SelectionStats {
  std::string adaptable;
  std::size_t requirements = 0;
  std::size_t cells = 0;        // states, grouped where every atom keeps its value
  SelectionCost algorithm1;     // Fig. 4
  SelectionCost optimized;      // the decision structure (equal to algorithm1 when not built)
  bool optimized_used = false;  // the selection tree is the decision structure
  std::string reason;           // why Fig. 4 was kept
};

struct Result {
  bt::Document document;
  std::vector<TraceEntry> trace;
  std::vector<SelectionStats> selection_stats;  // --selection optimized: one per adaptable node
  std::vector<Finding> findings;  // errors that stopped compilation (e.g. v3 + ScriptCondition)
  bool ok = false;
};

// A compiled tree as the robot loads it: the bytes written for `options`, read back by the one
// XML reader, so that what conform checks, prove proves and the test campaign runs is what is
// uplinked. `tree` is empty, with `findings` saying why, when the bytes do not read back.
struct ReadBack {
  std::string xml;
  std::optional<bt::Document> tree;
  std::vector<Finding> findings;
};
ReadBack read_back(const Result& compiled, const Options& options);

// The style `adaptable`'s selection is compiled in under `options`.
SelectionStyle selection_style_of(const load::Mission& mission, const std::string& adaptable,
                                  const Options& options);

// Whether `adaptable`'s selection is re-checked every tick: `reactive`, or `optimized` on a node
// that declares selection="reactive" (optimized chooses the layout, not the reactivity).
bool reactive_selection(const load::Mission& mission, const std::string& adaptable,
                        const Options& options);

// Algorithm 1 + Fig. 4: every <Adaptable ID="A"/> becomes <SubTree ID="A" _autoremap="true"/>
// and a selection tree A = Fallback[Sequence[guard_i, SubTree alt_i]...] in priority order.
Result compile_mission(const load::Mission& mission, const Options& options);

// The condition-checking subtree of a guard (Algorithm 1): atoms → condition leaves or
// ScriptCondition, ! → Inverter, | → Fallback, & → Sequence; xor, ->, <-> rewritten first.
bt::Node guard_to_tree(const fretish::Expr& guard, const fretish::Domain& domain,
                       SelectionStyle style);

// --selection optimized: the decision structure of one adaptable node's selection, when it ticks
// fewer conditions than Fig. 4 (on average, then in the worst case); nullopt otherwise (the
// reason is in `stats`). Appends its trace entries (every leaf names its requirement).
// `reactive`: the decision is re-checked every tick (WhileDoElse, ReactiveSequence), so a
// changed state pre-empts a running alternative as a ReactiveFallback does.
std::optional<bt::Node> optimized_selector(const load::Mission& mission,
                                           const std::string& adaptable, int bt_format,
                                           bool reactive, std::vector<TraceEntry>& trace,
                                           SelectionStats& stats);

// BT.CPP script text of a relational atom: "battery < 20", "terrain == 'rocks'".
std::string atom_to_script(const fretish::Expr& atom, const fretish::Domain& domain);

}  // namespace uabt::compile
