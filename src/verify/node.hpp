#pragma once
#include <optional>
#include <string>
#include <vector>

#include <z3++.h>

#include "fretish/selection.hpp"
#include "verify/prefilter.hpp"
#include "verify/session.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::detail {

// One selection requirement of the node under analysis.
struct Guard {
  explicit Guard(z3::context& c) : formula(c.bool_val(true)), literal(c.bool_val(true)) {}

  const fretish::SelectionRequirement* requirement = nullptr;
  bool is_default = false;               // no condition: always enabled
  z3::expr formula;                      // the lowered guard (true for the default)
  z3::expr literal;                      // stands for `formula` where `define`d
  Signature signature;                   // cheap over-approximation for pre-filters
  Answer satisfiable = Answer::unknown;  // D ∧ g
  Answer selectable = Answer::unknown;   // D ∧ g ∧ ¬(earlier guards): some state selects it
};

// One adaptable node: its guards in priority order (default last).
struct Node {
  std::string adaptable;
  std::vector<Guard> guards;
  // meeting[i]: the guards whose signatures do not rule out meeting guard i, ascending. Only
  // these can overlap it or hide part of it.
  std::vector<std::vector<std::size_t>> meeting;
  Result* result = nullptr;
  const Options* options = nullptr;
  bool first_hit = false;  // policy="first": an overlap is a note, priority decides
  // Conditions the checks build from parts of guards (the independent parts vacuity asks
  // about): the encoder's typing refers to them, so they live as long as the node.
  std::vector<fretish::ExprPtr> made;
};

// "Req1 (on_dust)"
std::string label(const Guard& g);
// Asserts each guard's literal equivalent to its formula in the session's current scope.
void define(Session& session, const std::vector<const Guard*>& guards);

// A finding of the verify stage about `node`, located at `location`.
Finding node_finding(const Node& node, const std::string& check, std::string message,
                     const SourceLocation& location);
// Reports that a question could not be decided.
void report_inconclusive(Node& node, Session& session, const std::string& question,
                         const SourceLocation& location, const std::vector<const Guard*>& guards);

// A region of the state space as a few readable cubes over the node's atoms.
struct RegionCubes {
  std::vector<std::string> cubes;
  std::string more;  // "… and more" when the list is cut short, else ""
};
// Describes the region that `inside` (assumption literals, satisfied by `model`) selects, as
// cubes over the atoms of `guards` (those the region depends on: the two guards of an overlap,
// not the whole node, so that describing one overlap costs what the two guards cost);
// `outside` is a literal that holds exactly outside it. Uses the session's current scope.
RegionCubes describe_region(const std::vector<const Guard*>& guards, Session& session,
                            z3::model model, const std::vector<z3::expr>& inside,
                            const z3::expr& outside);

// The checks, in the order verify_mission runs them.
void check_satisfiable_and_shadowed(Node& node, Session& session);
void check_overlaps(Node& node, Session& session);
void check_gap(Node& node, Session& session, std::vector<std::string>& region);
void check_vacuous_atoms(Node& node, Session& session, const std::vector<std::string>& assumed);

}  // namespace uabt::verify::detail
