#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"
#include "load/mission.hpp"

namespace uabt::compile {

enum class SelectionStyle { sequence, reactive };

struct Options {
  SelectionStyle selection = SelectionStyle::sequence;
  int bt_format = 4;  // 3: refuse guards that need ScriptCondition
};

// Where a generated node came from: requirement, atom and source line (DESIGN §4).
struct TraceEntry {
  std::string tree_id;
  std::string node_path;    // e.g. navigation/Fallback[0]/Sequence[1]/Inverter[0]/OnDust[0]
  std::string requirement;  // requirement id ("" for the selector itself)
  std::string atom;         // FRETISH text of the atom or operator it implements
  SourceLocation source;
};

struct Result {
  bt::Document document;
  std::vector<TraceEntry> trace;
  std::vector<Finding> findings;  // errors that stopped compilation (e.g. v3 + ScriptCondition)
  bool ok = false;
};

// Algorithm 1 + Fig. 4: every <Adaptable ID="A"/> becomes <SubTree ID="A" _autoremap="true"/>
// and a selection tree A = Fallback[Sequence[guard_i, SubTree alt_i]...] in priority order.
Result compile_mission(const load::Mission& mission, const Options& options);

// The condition-checking subtree of a guard (Algorithm 1): atoms → condition leaves or
// ScriptCondition, ! → Inverter, | → Fallback, & → Sequence; xor, ->, <-> rewritten first.
bt::Node guard_to_tree(const fretish::Expr& guard, const fretish::Domain& domain,
                       SelectionStyle style);

// BT.CPP script text of a relational atom: "battery < 20", "terrain == 'rocks'".
std::string atom_to_script(const fretish::Expr& atom, const fretish::Domain& domain);

}  // namespace uabt::compile
